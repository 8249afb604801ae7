// The weave geometry follows the yarn model of Irawan & Marschner ("Specular reflection from
// woven cloth", ACM TOG 31(1), 2012): each yarn is a round thread whose centre line rises over
// the crossing yarns it floats on and dives under the others, so the visible surface is a set
// of half-cylinders bent along their length. Here, as in make_fabric_texture, a thread's
// elevation e (-1 under .. +1 over) blends the over/under states of the two nearest crossings
// with a smoothstep, and its cross-section is a half-ellipse of width kThreadWidth of a cell.
// The thread on top at a texel is chosen by the albedo's rule (the higher elevation wins, the
// warp on ties; a thread alone covers the texel where the other leaves a gap), so every map
// agrees with the albedo texel by texel.
#include "vis/textures/weave_maps.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "vis/textures/fabric_texture.hpp"
#include "vis/textures/twill.hpp"

namespace clothlab {
namespace {

// The twill's geometry is the albedo's (vis/textures/twill.hpp).
using twill::kThreadWidth;
using twill::thread_profile;
using twill::warp_on_top;

// Relief of a thread: the gap floor is 0; a thread's surface is kBase + kLift * (e + 1) / 2 +
// kCrown * profile, so 1 on the crown of a floating thread.
constexpr float kBase = 0.1f, kLift = 0.4f, kCrown = 0.5f;

template <class OnTop>
float thread_elevation(float along, OnTop on_top) {
  return twill::thread_height(along, on_top);
}

enum class Top : std::uint8_t { gap, warp, weft };

struct Texel {
  Top top;
  int weft;      // weft thread (row band) index of the texel, 0 .. n - 1
  float height;  // 0 .. 1
};

// The weave sampled at texel centres exactly as make_fabric_texture samples it.
class Weave {
 public:
  explicit Weave(int size)
      : n_(fabric_thread_count(size)), cells_per_pixel_(float(n_) / float(size)) {}

  int threads() const { return n_; }

  Texel at(int x, int y) const {
    const float v = (float(y) + 0.5f) * cells_per_pixel_;  // weft coordinate, in cells
    const int j = static_cast<int>(v);
    const float fv = v - float(j);
    const float u = (float(x) + 0.5f) * cells_per_pixel_;  // warp coordinate, in cells
    const int i = static_cast<int>(u);
    const float fu = u - float(i);

    const float warp_profile = thread_profile(fu);
    const float weft_profile = thread_profile(fv);
    const float warp_e = thread_elevation(v, [i](int jj) { return warp_on_top(i, jj); });
    const float weft_e = thread_elevation(u, [j](int ii) { return !warp_on_top(ii, j); });

    const bool warp_visible = warp_profile > 0.0f && (weft_profile == 0.0f || warp_e >= weft_e);
    if (warp_visible) return {Top::warp, j, surface(warp_e, warp_profile)};
    if (weft_profile > 0.0f) return {Top::weft, j, surface(weft_e, weft_profile)};
    return {Top::gap, j, 0.0f};
  }

 private:
  static float surface(float elevation, float profile) {
    return kBase + kLift * 0.5f * (elevation + 1.0f) + kCrown * profile;
  }

  int n_;
  float cells_per_pixel_;
};

void check_size(const char* what, int size) {
  if (size < 1) throw std::invalid_argument(std::string(what) + ": size " + std::to_string(size));
}

void set_bytes(Image& image, int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  std::uint8_t* p = image.at(x, y);
  p[0] = r;
  p[1] = g;
  p[2] = b;
  p[3] = 255;
}

// Whether weft thread j (0 .. n - 1) is one of the m metallic ones: m neighbouring threads
// from `phase` on, a band. In a 2/2 twill each weft's floats start one cell after the previous
// weft's, so a band's floats climb the twill's diagonal and read as metal woven into the rib;
// threads spread evenly every 4th (the twill's period) put their floats in the same columns, a
// grid of dashes.
bool metallic_weft(int j, int m, int n, int phase) {
  return ((j - phase) % n + n) % n < m;
}

}  // namespace

std::vector<float> make_weave_height(int size) {
  check_size("make_weave_height", size);
  const Weave weave(size);
  std::vector<float> height(std::size_t(size) * std::size_t(size));
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      height[std::size_t(x) + std::size_t(y) * std::size_t(size)] = weave.at(x, y).height;
  return height;
}

glm::vec3 decode_normal(const std::uint8_t* rgb) {
  const auto channel = [](std::uint8_t b) {
    return std::clamp(float(b) * (1.0f / 127.0f) - 128.0f / 127.0f, -1.0f, 1.0f);
  };
  return {channel(rgb[0]), channel(rgb[1]), channel(rgb[2])};
}

void encode_normal(const glm::vec3& n, std::uint8_t* rgb) {
  for (int c = 0; c < 3; ++c) {
    const long b = 128 + std::lround(127.0f * std::clamp(n[c], -1.0f, 1.0f));
    rgb[c] = static_cast<std::uint8_t>(std::clamp(b, 1L, 255L));
  }
}

Image make_flat_normal_map(int size) {
  check_size("make_flat_normal_map", size);
  Image image(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) set_bytes(image, x, y, 128, 128, 255);
  return image;
}

Image make_weave_normal_map(int size, float strength) {
  check_size("make_weave_normal_map", size);
  if (!std::isfinite(strength) || strength < 0.0f)
    throw std::invalid_argument("make_weave_normal_map: strength " + std::to_string(strength));
  const std::vector<float> h = make_weave_height(size);
  const auto at = [&](int x, int y) {
    return h[std::size_t((x + size) % size) + std::size_t((y + size) % size) * std::size_t(size)];
  };
  // Central differences over two texels, converted to height per thread spacing.
  const float scale = 0.5f * strength * float(size) / float(fabric_thread_count(size));
  Image image(size, size);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const float dhdu = (at(x + 1, y) - at(x - 1, y)) * scale;
      const float dhdv = (at(x, y + 1) - at(x, y - 1)) * scale;  // +v = +y = down the image
      const glm::vec3 n = glm::normalize(glm::vec3(-dhdu, -dhdv, 1.0f));
      std::uint8_t* p = image.at(x, y);
      encode_normal(n, p);
      p[3] = 255;
    }
  }
  return image;
}

float max_metal_fraction(int size) {
  check_size("max_metal_fraction", size);
  const Weave weave(size);
  long count = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) count += weave.at(x, y).top == Top::weft;
  return float(double(count) / (double(size) * double(size)));
}

Image make_thread_mask(int size, float metal_fraction, std::uint32_t seed) {
  check_size("make_thread_mask", size);
  if (!(metal_fraction >= 0.0f && metal_fraction <= 1.0f))
    throw std::invalid_argument("make_thread_mask: metal_fraction " +
                                std::to_string(metal_fraction));
  const Weave weave(size);
  const int n = weave.threads();
  // Texels where each weft thread is on top; then the thread count m whose metallic texels come
  // nearest the request (threads' shares differ when a cell is not a whole texel count).
  std::vector<long> weft_texels(std::size_t(n), 0);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const Texel t = weave.at(x, y);
      if (t.top == Top::weft) ++weft_texels[std::size_t(t.weft)];
    }
  }
  const int phase = int(hash32(seed ^ 0x6d657461U) % std::uint32_t(n));
  const double target = double(metal_fraction) * double(size) * double(size);
  int m = 0;
  double best = target;  // m = 0 covers no texel
  for (int k = 1; k <= n; ++k) {
    long texels = 0;
    for (int j = 0; j < n; ++j)
      if (metallic_weft(j, k, n, phase)) texels += weft_texels[std::size_t(j)];
    if (std::abs(double(texels) - target) < best) best = std::abs(double(texels) - target), m = k;
  }

  Image image(size, size);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const Texel t = weave.at(x, y);
      const bool metal = t.top == Top::weft && metallic_weft(t.weft, m, n, phase);
      const std::uint8_t b = metal ? 255 : 0;
      set_bytes(image, x, y, b, b, b);
    }
  }
  return image;
}

Image make_thread_direction(int size) {
  check_size("make_thread_direction", size);
  const Weave weave(size);
  Image image(size, size);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const Top top = weave.at(x, y).top;
      set_bytes(image, x, y, top == Top::weft ? 255 : 0, top == Top::gap ? 0 : 255, 0);
    }
  }
  return image;
}

}  // namespace clothlab
