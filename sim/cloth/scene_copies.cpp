#include "sim/cloth/scene_copies.hpp"

#include "sim/cloth/build_cloth.hpp"
#include "sim/scene/parameter_keys.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace clothlab {
namespace {

Vec3d plus(const Vec3d& a, const Vec3d& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}

}  // namespace

std::string copies_unsupported_reason(const Scene& scene) {
  if (scene.mannequin) return "the mannequin is one body: a scene with a mannequin is not copied";
  for (const ClothSpec& c : scene.cloths)
    if (!c.pins_follow.empty())
      return c.key + "." + std::string(key_of<&ClothSpec::pins_follow>()) +
             ": a cloth whose pins follow a collider";
  return {};
}

double copy_spacing(const Scene& scene) {
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  bool any = false;
  for (const ClothSpec& spec : scene.cloths) {
    for (const Vec3d& p : build_cloth(spec).positions) {
      for (int k = 0; k < 2; ++k) {  // x and z, rounded to float as the solver keeps them
        const double x = static_cast<float>(p[std::size_t(2 * k)]);
        lo[k] = std::min(lo[k], x);
        hi[k] = std::max(hi[k], x);
      }
      any = true;
    }
  }
  const double extent = any ? std::max(hi[0] - lo[0], hi[1] - lo[1]) : 1.0;
  return extent + std::max(0.25, 0.25 * extent);
}

Vec3d copy_offset(int k, int copies, double spacing) {
  const int cols = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(copies))));
  return {(k % cols) * spacing, 0.0, -(k / cols) * spacing};
}

Scene with_copies(const Scene& scene, int copies, double spacing) {
  if (copies <= 1) return scene;
  if (const std::string why = copies_unsupported_reason(scene); !why.empty())
    throw std::invalid_argument(why);
  Scene out = scene;
  const std::size_t cloths = scene.cloths.size();
  for (int k = 1; k < copies; ++k) {
    const Vec3d d = copy_offset(k, copies, spacing);
    for (std::size_t c = 0; c < cloths; ++c) {
      ClothSpec cloth = scene.cloths[c];
      cloth.origin = plus(cloth.origin, d);
      cloth.key = "copy " + std::to_string(k) + " of " + cloth.key;
      out.cloths.push_back(std::move(cloth));
    }
    for (const ColliderSpec& spec : scene.colliders) {
      if (spec.kind == ColliderKind::plane) continue;  // shared
      ColliderSpec c = spec;
      c.center = plus(c.center, d);
      c.a = plus(c.a, d);
      c.b = plus(c.b, d);
      c.key = "copy " + std::to_string(k) + " of " + spec.key;
      out.colliders.push_back(std::move(c));
    }
  }
  return out;
}

}  // namespace clothlab
