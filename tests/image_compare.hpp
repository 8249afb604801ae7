// How far a rendered image is from another (a golden image, or the same frame drawn another
// way): the share of pixels with a colour channel off by more than 8/255 and the mean absolute
// difference over the colour channels, optionally with a difference image (|a - b| x 8).
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>

#include "vis/textures/image.hpp"

namespace clothlab::testing {

struct Comparison {
  double fraction_over = 0.0;  // pixels with a channel off by more than 8/255
  double mean_abs = 0.0;       // mean |difference| over all channels, in 1/255
};

inline Comparison compare(const Image& actual, const Image& golden, Image* diff = nullptr) {
  Comparison c;
  long over = 0;
  double sum = 0.0;
  if (diff) *diff = Image(actual.width, actual.height);
  for (int y = 0; y < actual.height; ++y) {
    for (int x = 0; x < actual.width; ++x) {
      int worst = 0;
      for (int ch = 0; ch < 3; ++ch) {
        const int d = std::abs(int(actual.at(x, y)[ch]) - int(golden.at(x, y)[ch]));
        worst = std::max(worst, d);
        sum += d;
        if (diff) diff->at(x, y)[ch] = static_cast<std::uint8_t>(std::min(255, 8 * d));
      }
      over += worst > 8;
    }
  }
  const double pixels = double(actual.width) * actual.height;
  c.fraction_over = over / pixels;
  c.mean_abs = sum / (3.0 * pixels);
  return c;
}

}  // namespace clothlab::testing
