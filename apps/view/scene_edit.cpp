#include "apps/view/scene_edit.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include "sim/scene/parameter_keys.hpp"

namespace clothlab::vis {
namespace {

// The [ / ] keys' range per axis: the table's panel range for cloth.resolution.
Range resolution_range() {
  return find_parameter(Section::cloth, key_of<&ClothSpec::resolution>())->ui;
}

// Index i on an axis of `from` vertices moved to the same relative place on `to` vertices.
int remap_index(int i, int from, int to) {
  if (from <= 1 || to <= 1) return std::min(i, to - 1);
  const double t = double(i) / double(from - 1);
  return std::clamp(static_cast<int>(std::lround(t * (to - 1))), 0, to - 1);
}

}  // namespace

void copy_dynamics(const Scene& from, Scene& to) {
  // The whole solver block except threads (M owns those) and precision (a rebuild of the model).
  const int threads = to.solver.threads;
  const Precision precision = to.solver.precision;
  to.solver = from.solver;
  to.solver.threads = threads;
  to.solver.precision = precision;
  to.springs = from.springs;
  for (std::size_t c = 0; c < to.cloths.size() && c < from.cloths.size(); ++c)
    to.cloths[c].springs = from.cloths[c].springs;
  to.forces.drag = from.forces.drag;
  to.forces.wind = from.forces.wind;
}

bool scale_resolution(Scene& scene, double factor) {
  const Range range = resolution_range();
  const int lo = static_cast<int>(range.lo), hi = static_cast<int>(range.hi);
  bool changed = false;
  for (ClothSpec& cloth : scene.cloths) {
    for (int& n : cloth.resolution) {
      if (n <= 1) continue;
      const int scaled = std::clamp(static_cast<int>(std::lround(n * factor)), lo, hi);
      changed |= scaled != n;
      n = scaled;
    }
  }
  return changed;
}

void remap_grid_indices(Scene& scene, const Scene& base) {
  for (std::size_t c = 0; c < scene.cloths.size() && c < base.cloths.size(); ++c) {
    const auto [nu0, nv0] = base.cloths[c].resolution;
    ClothSpec& cloth = scene.cloths[c];
    const auto [nu, nv] = cloth.resolution;
    if (nu < 1 || nv < 1) continue;  // invalid; validate_scene reports it
    // Two pins may land on one vertex at a coarse resolution: keep each vertex once.
    std::set<std::array<int, 2>> seen;
    cloth.pins.clear();
    for (const auto& [i, j] : base.cloths[c].pins) {
      const std::array<int, 2> pin{remap_index(i, nu0, nu), remap_index(j, nv0, nv)};
      if (seen.insert(pin).second) cloth.pins.push_back(pin);
    }
  }
  if (!scene.trace || !base.trace) return;
  std::set<std::tuple<int, int, int>> seen;
  scene.trace->vertices.clear();
  for (const TraceVertex& v : base.trace->vertices) {
    if (v.cloth < 0 || static_cast<std::size_t>(v.cloth) >= scene.cloths.size()) continue;
    const auto [nu0, nv0] = base.cloths[static_cast<std::size_t>(v.cloth)].resolution;
    const auto [nu, nv] = scene.cloths[static_cast<std::size_t>(v.cloth)].resolution;
    if (nu < 1 || nv < 1) continue;
    const TraceVertex moved{v.cloth, remap_index(v.i, nu0, nu), remap_index(v.j, nv0, nv)};
    if (seen.emplace(moved.cloth, moved.i, moved.j).second) scene.trace->vertices.push_back(moved);
  }
}

double wind_speed(const Scene& scene) {
  const Vec3d& w = scene.forces.wind.velocity;
  return std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
}

void set_wind_speed(Scene& scene, double speed) {
  Vec3d& w = scene.forces.wind.velocity;
  const double current = wind_speed(scene);
  if (current > 0.0) {
    for (double& x : w) x *= speed / current;
  } else {
    w = {speed, 0.0, 0.0};
  }
}

double total_mass(const Scene& scene) {
  double m = 0.0;
  for (const ClothSpec& cloth : scene.cloths) m += cloth.mass;
  return m;
}

}  // namespace clothlab::vis
