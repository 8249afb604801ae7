// Range and consistency checks on a Scene. Types were checked by the parser; this file holds the
// rules on values, so that a Scene built in code (tests, benchmarks) is checked the same way.
#include "sim/scene/validate.hpp"

#include "sim/mesh/triangle_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <tuple>
#include <utility>

// GCC 12 at -O3 reports a false -Wrestrict inside std::string for `"text" + std::string(...)`
// (GCC bug 105329); the message texts below are built that way throughout.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ == 12
#pragma GCC diagnostic ignored "-Wrestrict"
#endif

namespace clothlab {

namespace {

constexpr std::int64_t kMaxVertices = 16'000'000;
constexpr int kMaxThreads = 1024;
constexpr double kMaxDt = 1.0;
constexpr int kMaxSubsteps = 100000;
constexpr int kMaxIterations = 100000;
constexpr double kOrthogonalityTolerance = 1e-6;

class Validator {
 public:
  explicit Validator(const Scene& scene) : scene_(scene) {}

  void run() {
    check_cloth_count();
    check_springs(scene_.springs, "springs");
    for (const ClothSpec& cloth : scene_.cloths) check_cloth(cloth);
    check_forces();
    check_solver();
    if (scene_.trace) check_trace(*scene_.trace);
    check_render(scene_.render);
    for (const ColliderSpec& c : scene_.colliders) check_collider(c);
    for (const ClothSpec& cloth : scene_.cloths) check_pins_follow(cloth);
  }

 private:
  // The location of key, or of its nearest parent that has one ("forces.wind.gust" falls back
  // to "forces.wind" when gust took its default).
  SourceLoc where(std::string key) const {
    while (!key.empty()) {
      if (auto it = scene_.locations.find(key); it != scene_.locations.end()) return it->second;
      const auto cut = key.find_last_of(".[");
      if (cut == std::string::npos) break;
      key.resize(cut);
    }
    return SourceLoc{scene_.file, 0, 0};
  }

  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    throw SceneError(where(key), key, message);
  }

  void finite(const std::string& key, double value) const {
    if (!std::isfinite(value)) fail(key, "must be finite (got " + format_number(value) + ")");
  }
  void positive(const std::string& key, double value) const {
    finite(key, value);
    if (!(value > 0.0)) fail(key, "must be > 0 (got " + format_number(value) + ")");
  }
  void non_negative(const std::string& key, double value) const {
    finite(key, value);
    if (!(value >= 0.0)) fail(key, "must be >= 0 (got " + format_number(value) + ")");
  }
  void finite3(const std::string& key, const Vec3d& v) const {
    for (double x : v) finite(key, x);
  }

  void check_cloth_count() const {
    if (scene_.cloths.empty())
      fail("cloth", "the scene has no cloth; add a [cloth] table or [[cloth]] tables");
    if (!scene_.multi_cloth && scene_.cloths.size() != 1)
      fail("cloth", "the one-cloth form ([cloth]) holds exactly one cloth");
  }

  void check_springs(const SpringSpec& springs, const std::string& key) const {
    if (springs.rule != "seed")
      fail(key + ".rule", "unknown spring rule \"" + springs.rule + "\" (valid: seed)");
    non_negative(key + ".stiffness", springs.stiffness);
    non_negative(key + ".damping", springs.damping);
  }

  void check_cloth(const ClothSpec& cloth) const {
    const std::string& k = cloth.key;
    if (cloth.shape != "grid" && cloth.shape != "tube" && cloth.shape != "mesh")
      fail(k + ".shape", "shape \"" + cloth.shape + "\" is unknown (valid: grid, tube, mesh)");
    if (cloth.shape == "mesh") {
      check_mesh_cloth(cloth);
    } else if (cloth.shape == "tube") {
      check_tube(cloth);
    } else {
      for (const char* tube_key : {".radius", ".length"})
        if (scene_.locations.count(k + tube_key))
          fail(k + tube_key, "belongs to shape = \"tube\" (this cloth is a grid)");
      for (double s : cloth.size) positive(k + ".size", s);
    }
    check_resolution(cloth);
    check_axes(cloth);
    positive(k + ".mass", cloth.mass);
    check_pins(cloth);
    if (cloth.springs) check_springs(*cloth.springs, k + ".springs");
    if (cloth.release_at) non_negative(k + ".release_at", *cloth.release_at);
  }

  // A tube takes radius and length instead of size; at least 6 vertices round a ring (so the
  // seed rule's offsets of up to 2 around do not meet themselves across the seam) and 2 rings.
  void check_tube(const ClothSpec& cloth) const {
    const std::string& k = cloth.key;
    if (scene_.locations.count(k + ".size"))
      fail(k + ".size", "a tube takes radius and length, not size");
    positive(k + ".radius[0]", cloth.radius[0]);
    positive(k + ".radius[1]", cloth.radius[1]);
    positive(k + ".length", cloth.length);
    const auto [nu, nv] = cloth.resolution;
    if (nu < 6 || nv < 2)
      fail(k + ".resolution", "a tube needs at least 6 vertices around and 2 rings (got [" +
                                  std::to_string(nu) + ", " + std::to_string(nv) + "])");
  }

  void check_resolution(const ClothSpec& cloth) const {
    const auto [nu, nv] = cloth.resolution;
    const std::string key = cloth.key + ".resolution";
    if (nu < 1 || nv < 1)
      fail(key, "each count must be >= 1 (got [" + std::to_string(nu) + ", " + std::to_string(nv) +
                    "])");
    const std::int64_t vertices = std::int64_t{nu} * nv;
    if (vertices > kMaxVertices)
      fail(key, std::to_string(nu) + " x " + std::to_string(nv) + " = " + std::to_string(vertices) +
                    " vertices; at most " + std::to_string(kMaxVertices) + " are allowed");
  }

  void check_axes(const ClothSpec& cloth) const {
    finite3(cloth.key + ".origin", cloth.origin);
    finite3(cloth.key + ".u_axis", cloth.u_axis);
    finite3(cloth.key + ".v_axis", cloth.v_axis);
    const double lu = length(cloth.u_axis);
    const double lv = length(cloth.v_axis);
    if (lu == 0.0) fail(cloth.key + ".u_axis", "must not be the zero vector");
    if (lv == 0.0) fail(cloth.key + ".v_axis", "must not be the zero vector");
    const Vec3d& u = cloth.u_axis;
    const Vec3d& v = cloth.v_axis;
    const double cosine = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) / (lu * lv);
    if (!(std::abs(cosine) < kOrthogonalityTolerance))
      fail(cloth.key + ".v_axis",
           "must be orthogonal to u_axis (cos angle = " + format_number(cosine) + ")");
  }

  static double length(const Vec3d& v) {
    return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  }

  // A mesh cloth takes its geometry from the OBJ: no grid or tube keys; every vertex belongs to
  // a face (a loose vertex would fall alone) and no edge has zero length (a spring of rest
  // length 0 has no direction when its ends meet).
  void check_mesh_cloth(const ClothSpec& cloth) const {
    const std::string& k = cloth.key;
    for (const char* grid_key :
         {".size", ".resolution", ".u_axis", ".v_axis", ".radius", ".length"})
      if (scene_.locations.count(k + grid_key))
        fail(k + grid_key,
             "belongs to a grid or tube cloth (a mesh cloth takes its shape from file)");
    finite3(k + ".rotation", cloth.rotation);
    positive(k + ".scale", cloth.scale);
    if (!cloth.mesh || cloth.mesh->triangles.empty())
      fail(k + ".file", "no OBJ mesh was read for this mesh cloth");
    const TriangleMesh& mesh = *cloth.mesh;
    std::vector<bool> used(mesh.positions.size(), false);
    for (const auto& t : mesh.triangles)
      for (int c = 0; c < 3; ++c) {
        used[std::size_t(t[c])] = true;
        const int a = t[c], b = t[(c + 1) % 3];
        if ((mesh.positions[std::size_t(a)] - mesh.positions[std::size_t(b)]).norm() == 0.0)
          fail(k + ".file", "the edge between OBJ vertices " + std::to_string(a + 1) + " and " +
                                std::to_string(b + 1) + " has zero length");
      }
    for (std::size_t v = 0; v < used.size(); ++v)
      if (!used[v])
        fail(k + ".file", "OBJ vertex " + std::to_string(v + 1) + " belongs to no face");
  }

  // Pins name vertices inside the grid, once each, and leave at least one vertex free (a fully
  // pinned cloth has nothing to simulate and is almost certainly a typo).
  void check_pins(const ClothSpec& cloth) const {
    const auto [nu, nv] = cloth.resolution;
    std::set<std::pair<int, int>> seen;
    for (std::size_t n = 0; n < cloth.pins.size(); ++n) {
      const auto [i, j] = cloth.pins[n];
      const std::string key = cloth.key + ".pins[" + std::to_string(n) + "]";
      const std::string pin = cloth.shape == "mesh"
                                  ? std::to_string(i + 1)
                                  : "[" + std::to_string(i) + ", " + std::to_string(j) + "]";
      if (cloth.shape == "mesh" && (i < 0 || i >= nu))
        fail(key, "pin " + std::to_string(i + 1) + " is not an OBJ vertex number (1.." +
                      std::to_string(nu) + ")");
      if (i < 0 || i >= nu || j < 0 || j >= nv)
        fail(key, "pin " + pin + " is outside the " + std::to_string(nu) + " x " +
                      std::to_string(nv) + " grid (0 <= i < " + std::to_string(nu) + ", 0 <= j < " +
                      std::to_string(nv) + ")");
      if (!seen.emplace(i, j).second) fail(key, "pin " + pin + " is listed twice");
    }
    if (static_cast<std::int64_t>(seen.size()) >= std::int64_t{nu} * nv)
      fail(cloth.key + ".pins", "every vertex is pinned; leave at least one free");
  }

  void check_forces() const {
    const ForceSpec& f = scene_.forces;
    finite3("forces.gravity", f.gravity);
    non_negative("forces.drag", f.drag);
    if (!f.wind.enabled) return;
    finite3("forces.wind.velocity", f.wind.velocity);
    non_negative("forces.wind.gust", f.wind.gust);
    positive("forces.wind.gust_period", f.wind.gust_period);
    non_negative("forces.wind.coefficient", f.wind.coefficient);
  }

  void check_solver() const {
    positive("solver.self_thickness", scene_.solver.self_thickness);
    const SolverSpec& s = scene_.solver;
    if (!to_string_known(s.integrator)) fail("solver.integrator", "unknown integrator");
    if (!s.dt_auto) positive("solver.dt", s.dt);
    if (s.dt > kMaxDt)
      fail("solver.dt",
           "must be <= " + format_number(kMaxDt) + " s (got " + format_number(s.dt) + ")");
    if (s.threads < 0 || s.threads > kMaxThreads)
      fail("solver.threads", "must be between 0 (all cores) and " + std::to_string(kMaxThreads) +
                                 " (got " + std::to_string(s.threads) + ")");
    if (s.substeps < 1 || s.substeps > kMaxSubsteps)
      fail("solver.substeps", "must be between 1 and " + std::to_string(kMaxSubsteps) + " (got " +
                                  std::to_string(s.substeps) + ")");
    if (s.iterations < 0 || s.iterations > kMaxIterations)
      fail("solver.iterations", "must be between 0 (the method's default) and " +
                                    std::to_string(kMaxIterations) + " (got " +
                                    std::to_string(s.iterations) + ")");
    if (!(s.cg_tolerance > 0.0 && s.cg_tolerance < 1.0))
      fail("solver.cg_tolerance",
           "must be between 0 and 1, exclusive (got " + format_number(s.cg_tolerance) + ")");
    if (s.cg_max_iterations < 1 || s.cg_max_iterations > kMaxIterations)
      fail("solver.cg_max_iterations", "must be between 1 and " + std::to_string(kMaxIterations) +
                                           " (got " + std::to_string(s.cg_max_iterations) + ")");
    if (s.precision != Precision::f32 && s.precision != Precision::f64)
      fail("solver.precision", "must be \"float\" or \"double\"");
  }

  // A value in [lo, hi].
  void within(const std::string& key, double value, double lo, double hi) const {
    finite(key, value);
    if (!(value >= lo && value <= hi))
      fail(key, "must be between " + format_number(lo) + " and " + format_number(hi) + " (got " +
                    format_number(value) + ")");
  }
  void colour(const std::string& key, const Vec3d& c, double hi) const {
    for (std::size_t k = 0; k < 3; ++k) within(key + "[" + std::to_string(k) + "]", c[k], 0.0, hi);
  }
  void check_pins_follow(const ClothSpec& cloth) const {
    if (!cloth.pins_follow) return;
    const int c = *cloth.pins_follow;
    const std::string key = cloth.key + ".pins_follow";
    if (c < 0 || c >= static_cast<int>(scene_.colliders.size()))
      fail(key, "names collider " + std::to_string(c) + ", but the scene has " +
                    std::to_string(scene_.colliders.size()) + " ([[colliders]] count from 0)");
    if (cloth.pins.empty()) fail(key, "the cloth has no pins to move");
  }

  // Sizes positive, friction and thickness non-negative, directions non-zero, keyframe times
  // increasing; the rounding of a box fits inside it.
  void check_collider(const ColliderSpec& c) const {
    const std::string& k = c.key;
    switch (c.kind) {
      case ColliderKind::plane:
        finite3(k + ".point", c.point);
        finite3(k + ".normal", c.normal);
        if (length(c.normal) < 1e-9) fail(k + ".normal", "must not be the zero vector");
        break;
      case ColliderKind::sphere:
        finite3(k + ".center", c.center);
        positive(k + ".radius", c.radius);
        break;
      case ColliderKind::box: {
        finite3(k + ".center", c.center);
        finite3(k + ".rotation", c.rotation);
        double smallest = INFINITY;
        for (std::size_t a = 0; a < 3; ++a) {
          positive(k + ".half_extents[" + std::to_string(a) + "]", c.half_extents[a]);
          smallest = std::min(smallest, c.half_extents[a]);
        }
        non_negative(k + ".rounding", c.rounding);
        if (!(c.rounding < smallest))
          fail(k + ".rounding", "must be smaller than the smallest half extent (" +
                                    format_number(smallest) + " m), got " +
                                    format_number(c.rounding));
        break;
      }
      case ColliderKind::mesh:
        finite3(k + ".center", c.center);
        finite3(k + ".rotation", c.rotation);
        positive(k + ".scale", c.scale);
        if (c.sdf_resolution < 8 || c.sdf_resolution > 256)
          fail(k + ".resolution",
               "must be between 8 and 256 cells (got " + std::to_string(c.sdf_resolution) + ")");
        if (!c.mesh) fail(k + ".file", "no mesh was read (a mesh collider needs file = \"x.obj\")");
        break;
      case ColliderKind::capsule:
        finite3(k + ".a", c.a);
        finite3(k + ".b", c.b);
        positive(k + ".radius", c.radius);
        if (length({c.b[0] - c.a[0], c.b[1] - c.a[1], c.b[2] - c.a[2]}) < 1e-9)
          fail(k + ".b", "must differ from a (a capsule needs an axis)");
        break;
    }
    non_negative(k + ".friction.static", c.static_friction);
    non_negative(k + ".friction.kinetic", c.kinetic_friction);
    non_negative(k + ".thickness", c.thickness);
    finite3(k + ".motion.velocity", c.motion.velocity);
    finite3(k + ".motion.angular_velocity", c.motion.angular_velocity);
    for (std::size_t i = 0; i < c.motion.keys.size(); ++i) {
      const ColliderKey& key = c.motion.keys[i];
      const std::string kk = k + ".motion.keys[" + std::to_string(i) + "]";
      finite(kk + ".time", key.time);
      finite3(kk + ".offset", key.offset);
      finite3(kk + ".rotation", key.rotation);
      if (i > 0 && !(key.time > c.motion.keys[i - 1].time))
        fail(kk + ".time", "keyframe times must increase (got " + format_number(key.time) +
                               " after " + format_number(c.motion.keys[i - 1].time) + ")");
    }
    if (!c.motion.keys.empty() && (c.motion.velocity != Vec3d{0.0, 0.0, 0.0} ||
                                   c.motion.angular_velocity != Vec3d{0.0, 0.0, 0.0}))
      fail(k + ".motion", "give either keys or velocities, not both");
  }

  void check_render(const RenderSpec& r) const {
    if (r.mode < 1 || r.mode > 7)
      fail("render.mode",
           "must be a display mode from 1 to 7 (got " + std::to_string(r.mode) + ")");
    if (r.shadow_map_size < 256 || r.shadow_map_size > 8192)
      fail("render.shadow_map_size",
           "must be between 256 and 8192 texels (got " + std::to_string(r.shadow_map_size) + ")");
    const LightSpec& l = r.light;
    if (l.position) finite3("render.light.position", *l.position);
    if (l.target) finite3("render.light.target", *l.target);
    if (l.position && l.target &&
        length({(*l.target)[0] - (*l.position)[0], (*l.target)[1] - (*l.position)[1],
                (*l.target)[2] - (*l.position)[2]}) < 1e-6)
      fail("render.light.target", "must differ from render.light.position");
    finite3("render.light.direction", l.direction);
    if (length(l.direction) < 1e-9) fail("render.light.direction", "must not be zero");
    colour("render.light.color", l.color, 1e3);
    non_negative("render.light.intensity", l.intensity);
    non_negative("render.light.size", l.size);
    within("render.sky.turbidity", r.sky.turbidity, 1.7, 10.0);  // Preetham's fitted range
    within("render.pole.radius", r.pole.radius, 1e-4, 1.0);
    if (r.camera.target) finite3("render.camera.target", *r.camera.target);
    if (r.camera.yaw) finite("render.camera.yaw", *r.camera.yaw);
    if (r.camera.pitch) within("render.camera.pitch", *r.camera.pitch, -89.0, 89.0);
    if (r.camera.distance) within("render.camera.distance", *r.camera.distance, 0.01, 1e4);
    for (const MeshSpec& m : r.meshes) {
      finite3(m.key + ".center", m.center);
      positive(m.key + ".radius", m.radius);
      for (std::size_t k = 0; k < 3; ++k)
        positive(m.key + ".half_extents[" + std::to_string(k) + "]", m.half_extents[k]);
      finite3(m.key + ".rotation", m.rotation);
      colour(m.key + ".color", m.color, 1.0);
    }
    const ClothLookSpec& c = r.cloth;
    within("render.cloth.roughness", c.roughness, 0.0, 1.0);
    within("render.cloth.sheen", c.sheen, 0.0, 1.0);
    within("render.cloth.sheen_roughness", c.sheen_roughness, 0.07, 1.0);
    within("render.cloth.thread_fraction", c.thread_fraction, 0.0, 1.0);
    within("render.cloth.opacity", c.opacity, 0.0, 1.0);
    within("render.cloth.transmission", c.transmission, 0.0, 1.0);
    within("render.cloth.bump", c.bump, 0.0, 2.0);
    within("render.cloth.subsurface", c.subsurface, 0.0, 1.0);
    if (c.color) colour("render.cloth.color", *c.color, 1.0);
  }

  static bool to_string_known(IntegratorKind kind) {
    return integrator_from_string(to_string(kind)).has_value();
  }

  void check_trace(const TraceSpec& trace) const {
    std::set<std::tuple<int, int, int>> seen;
    for (std::size_t n = 0; n < trace.vertices.size(); ++n)
      check_trace_vertex(trace.vertices[n], "trace.vertices[" + std::to_string(n) + "]", seen);
    if (!(trace.position || trace.velocity || trace.force || trace.energy))
      fail("trace.fields", "name at least one of position, velocity, force, energy");
    if (trace.every < 1)
      fail("trace.every", "must be >= 1 (got " + std::to_string(trace.every) + ")");
  }

  void check_trace_vertex(const TraceVertex& v, const std::string& key,
                          std::set<std::tuple<int, int, int>>& seen) const {
    const int cloths = static_cast<int>(scene_.cloths.size());
    if (v.cloth < 0 || v.cloth >= cloths)
      fail(key, "cloth index " + std::to_string(v.cloth) + " is out of range (the scene has " +
                    std::to_string(cloths) + " cloth" + (cloths == 1 ? "" : "s") + ")");
    const auto [nu, nv] = scene_.cloths[static_cast<std::size_t>(v.cloth)].resolution;
    if (v.i < 0 || v.i >= nu || v.j < 0 || v.j >= nv)
      fail(key, "vertex [" + std::to_string(v.i) + ", " + std::to_string(v.j) +
                    "] is outside the " + std::to_string(nu) + " x " + std::to_string(nv) +
                    " grid of " + scene_.cloths[static_cast<std::size_t>(v.cloth)].key);
    if (!seen.emplace(v.cloth, v.i, v.j).second) fail(key, "vertex is listed twice");
  }

  const Scene& scene_;
};

}  // namespace

void validate_scene(const Scene& scene) {
  Validator(scene).run();
}

}  // namespace clothlab
