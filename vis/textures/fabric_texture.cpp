// The weave is modelled as two families of round threads: warp threads run down the image
// (one per column band), weft threads run across it (one per row band). In each cell (i, j)
// one of them lies on top; in a 2/2 twill the warp is on top where (i + j) mod 4 < 2, which
// steps the floats by one thread per row and gives the diagonal rib of denim or gabardine.
// Each thread's height rises and falls smoothly between cells as it passes over and under,
// so where it dives under a crossing thread it darkens: that soft shading is what makes the
// pattern read as cloth rather than a checkerboard.
#include "vis/textures/fabric_texture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "vis/textures/twill.hpp"

namespace clothlab {
namespace {

using Rgb = std::array<float, 3>;

constexpr Rgb kWarpColour{0.56f, 0.11f, 0.12f};  // dark red
constexpr Rgb kWeftColour{0.46f, 0.08f, 0.13f};  // slightly deeper, bluer red
constexpr std::uint32_t kWarpTag = 1, kWeftTag = 2;
using twill::kThreadWidth;
using twill::smoothstep;
using twill::thread_height;
using twill::thread_profile;
using twill::warp_on_top;

// Per-thread dye variation: +-8 % brightness and a small shift between red and blue.
Rgb thread_colour(Rgb base, std::uint32_t seed, std::uint32_t tag, int index) {
  const float brightness = 0.92f + 0.16f * hash_unit(seed, tag, std::uint32_t(index));
  const float tint = 0.04f * (hash_unit(seed, tag + 16, std::uint32_t(index)) - 0.5f);
  return {base[0] * brightness + tint, base[1] * brightness, base[2] * brightness - tint};
}

// Fibre twist: faint slanted stripes along a thread (period 1/3 cell along it) so single
// threads look spun from fibres rather than flat. Periodic in whole cells, so seams match.
float twist(float along, float across) {
  return 0.93f + 0.07f * std::sin(2.0f * std::numbers::pi_v<float> * (3.0f * along + across));
}

struct Sample {
  float profile;  // 0 when this thread does not cover the pixel
  float height;   // -1 .. 1, for picking the upper thread and shading the dives
};

Rgb shade(Rgb colour, const Sample& s, float fibre) {
  // Lit like a cylinder seen from above, dimmed where the thread dives under its neighbour.
  const float light = (0.45f + 0.55f * s.profile) * (0.72f + 0.28f * s.height) * fibre;
  return {colour[0] * light, colour[1] * light, colour[2] * light};
}

}  // namespace

int fabric_thread_count(int size) {
  const int threads = std::min(16, size / 4) / 4 * 4;
  return std::max(4, threads);
}

Image make_fabric_texture(int size, std::uint32_t seed) {
  if (size < 1) throw std::invalid_argument("make_fabric_texture: size " + std::to_string(size));
  Image image(size, size);
  const int n = fabric_thread_count(size);
  const float cells_per_pixel = float(n) / float(size);
  const Rgb gap{kWeftColour[0] * 0.25f, kWeftColour[1] * 0.25f, kWeftColour[2] * 0.25f};

  for (int y = 0; y < size; ++y) {
    const float v = (float(y) + 0.5f) * cells_per_pixel;  // weft coordinate, in cells
    const int j = static_cast<int>(v);
    const float fv = v - float(j);
    for (int x = 0; x < size; ++x) {
      const float u = (float(x) + 0.5f) * cells_per_pixel;  // warp coordinate, in cells
      const int i = static_cast<int>(u);
      const float fu = u - float(i);

      const Sample warp{thread_profile(fu),
                        thread_height(v, [i](int jj) { return warp_on_top(i, jj); })};
      const Sample weft{thread_profile(fv),
                        thread_height(u, [j](int ii) { return !warp_on_top(ii, j); })};

      Rgb c = gap;
      const bool warp_visible =
          warp.profile > 0.0f && (weft.profile == 0.0f || warp.height >= weft.height);
      if (warp_visible) {
        c = shade(thread_colour(kWarpColour, seed, kWarpTag, i), warp, twist(v, fu));
      } else if (weft.profile > 0.0f) {
        c = shade(thread_colour(kWeftColour, seed, kWeftTag, j), weft, twist(u, fv));
      }
      image.set_rgb(x, y, c[0], c[1], c[2]);
    }
  }
  return image;
}

}  // namespace clothlab
