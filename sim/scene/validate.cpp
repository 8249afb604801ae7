// Range and consistency checks on a Scene. Types were checked by the parser; this file holds the
// rules on values, so that a Scene built in code (tests, benchmarks) is checked the same way.
#include "sim/scene/validate.hpp"

#include "sim/core/vec3_math.hpp"
#include "sim/mesh/mesh_edges.hpp"
#include "sim/mesh/triangle_mesh.hpp"
#include "sim/scene/name_list.hpp"
#include "sim/scene/parameter_binding.hpp"

#include <Eigen/Geometry>
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

using binding::key_of;

// prefix.name: cloth[1] and mass give cloth[1].mass.
std::string key_path(const std::string& prefix, std::string_view name) {
  return prefix + "." + std::string(name);
}

}  // namespace

// The nearest recorded key: "forces.wind.gust" falls back to "forces.wind" when gust took its
// default.
SourceLoc location_of(const Scene& scene, std::string key) {
  while (!key.empty()) {
    if (auto it = scene.locations.find(key); it != scene.locations.end()) return it->second;
    const auto cut = key.find_last_of(".[");
    if (cut == std::string::npos) break;
    key.resize(cut);
  }
  return SourceLoc{scene.file, 0, 0};
}

namespace {

// The violated side of a range in words: "> 0", "<= 1", or the whole range where both bounds
// are finite and alike ("between 1 and 100000").
std::string violated(const Parameter& p, double x) {
  const Range& r = p.range;
  if (!p.range_text.empty()) return std::string(p.range_text);
  const bool both = r.lo != -Range::kInf && r.hi != Range::kInf && r.lo_open == r.hi_open;
  if (both) return range_words(p);
  const bool low = r.lo_open ? !(x > r.lo) : !(x >= r.lo);
  if (low) return std::string(r.lo_open ? "> " : ">= ") + format_number(r.lo);
  return std::string(r.hi_open ? "< " : "<= ") + format_number(r.hi);
}

constexpr std::int64_t kMaxVertices = 16'000'000;
constexpr double kOrthogonalityTolerance = 1e-6;
constexpr int kMaxMeshValence = 128;
// Neighbouring vertices of a grid or tube at least this far apart (m). Closer, the springs' rest
// lengths drown in float round-off: their stiffness k l_edge / l overflows, or the seed rule
// finds no spring at all, and the message would blame the springs rather than the geometry.
constexpr double kMinVertexSpacing = 1e-6;

class Validator {
 public:
  Validator(const Scene& scene, bool loaded) : scene_(scene), loaded_(loaded) {}

  void run();

  // The table's ranges for one struct (`object`, the section's struct, at key path `prefix`):
  // each number finite, each bounded one inside its range.
  void ranges(Section section, const void* object, const std::string& prefix) const;

 private:
  SourceLoc where(const std::string& key) const { return location_of(scene_, key); }

  // A string that must be one of the record's choices ("grid, tube, mesh").
  void one_of(const Parameter& p, const void* object, const std::string& prefix) const;

  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    throw SceneError(where(key), key, message);
  }

  // Finite, and inside the range of the solver's float (a finite double such as 1e39 would
  // be inf once the solver reads it as a float; see kMaxSceneMagnitude).
  void finite(const std::string& key, double value) const;

  void check_cloth_count() const;

  // A key given in the file for a cloth of another shape.
  bool given(const ClothSpec& cloth, std::string_view name) const {
    return scene_.locations.count(key_path(cloth.key, name)) > 0;
  }

  void check_cloth(const ClothSpec& cloth) const;

  // What the transform-feedback step (gpu/tf_cloth.hpp) runs: the one-evaluation integrators in
  // float, on cloths drawn straight from the captured buffer, which holds one entry per solver
  // vertex, so a cloth whose UVs copy vertices along a seam (tube, mesh) cannot be drawn from it.
  // Refused here, naming the key, rather than run differently from what the scene asks.
  void check_transform_feedback() const;

  // A tube takes radius and length instead of size; at least 6 vertices round a ring (so the
  // seed rule's offsets of up to 2 around do not meet themselves across the seam) and 2 rings.
  void check_tube(const ClothSpec& cloth) const;

  // Neighbouring vertices at least kMinVertexSpacing apart: along u and v on a grid; round each
  // ring (the chord 2 r sin(pi / nu)) and from ring to ring on a tube.
  void check_spacing(const ClothSpec& cloth) const;

  void check_resolution(const ClothSpec& cloth) const;

  // The limit holds for the whole scene too: several cloths each under it could not be built
  // together (two 16 M-vertex cloths need about 40 GB).
  void check_total_vertices() const;

  void check_axes(const ClothSpec& cloth) const;

  static double length(const Vec3d& v) { return scaled_length(v); }

  // A mesh cloth takes its geometry from the OBJ: no grid or tube keys; every vertex belongs to
  // a face (a loose vertex would fall alone) and no edge has zero length (a spring of rest
  // length 0 has no direction when its ends meet). Messages about the OBJ's content start with
  // its path as the scene gives it (and the OBJ line where known), after the scene's line and
  // key.
  void check_mesh_cloth(const ClothSpec& cloth) const;

  // The neighbour-list kernel pads every vertex's spring list to the longest one (slot-major,
  // so its gather loop vectorises and the GPU reads fixed strides); a vertex with hundreds of
  // edges (a fan's hub, a UV sphere's pole) would cost that width on every vertex (issue 21: a
  // 500 000-vertex sphere with valence-1000 poles needed 18 GB). kMaxMeshValence edges at a
  // vertex (at most twice as many springs with its bending ones) is the cap.
  void check_valence(const TriangleMesh& mesh, const std::string& file,
                     const std::string& obj) const;

  // A zero-area (collinear) triangle has no normal and no wind area; its springs all lie on one
  // line. "Zero" is relative: twice the area below 1e-10 of the longest edge squared.
  template <class InObj>
  void check_triangle_areas(const TriangleMesh& mesh, const std::string& file,
                            const InObj& in_obj) const;

  // Pins name vertices inside the grid, once each, and leave at least one vertex free (a fully
  // pinned cloth has nothing to simulate and is almost certainly a typo).
  void check_pins(const ClothSpec& cloth) const;

  void check_forces() const;

  void check_pins_follow(const ClothSpec& cloth) const;

  // The mannequin's friction goes to every part (load/scene_load.cpp): held to the colliders'
  // friction ranges here, under the key the scene wrote, rather than at the first part.
  void check_mannequin(const MannequinSpec& m) const;

  // The table's ranges, then: plane normals and capsule axes non-zero, a box's rounding inside
  // it, a mesh read, keyframe times increasing and not mixed with velocities.
  void check_collider(const ColliderSpec& c) const;

  void check_keyframes(const ColliderMotion& m, const std::string& motion) const;

  void check_render(const RenderSpec& r) const;

  void check_trace(const TraceSpec& trace) const;

  void check_trace_vertex(const TraceVertex& v, const std::string& key,
                          std::set<std::tuple<int, int, int>>& seen) const;

  // Whether what the load step reads is there: a mesh cloth's vertices (and so its resolution),
  // the meshes, the mannequin's colliders.
  bool unloaded_mesh(const ClothSpec& cloth) const { return !loaded_ && cloth.shape == "mesh"; }

  const Scene& scene_;
  const bool loaded_;
};

inline void Validator::run() {
  check_cloth_count();
  ranges(Section::springs, &scene_.springs, section_path(Section::springs));
  for (const ClothSpec& cloth : scene_.cloths) check_cloth(cloth);
  check_total_vertices();
  check_forces();
  ranges(Section::solver, &scene_.solver, section_path(Section::solver));
  if (scene_.solver.backend == Backend::transform_feedback) check_transform_feedback();
  if (scene_.trace) check_trace(*scene_.trace);
  check_render(scene_.render);
  for (const ColliderSpec& c : scene_.colliders) check_collider(c);
  if (scene_.music) ranges(Section::music, &*scene_.music, section_path(Section::music));
  if (scene_.mannequin) check_mannequin(*scene_.mannequin);
  if (!loaded_) return;
  for (const ClothSpec& cloth : scene_.cloths) check_pins_follow(cloth);
}

inline void Validator::ranges(Section section, const void* object,
                              const std::string& prefix) const {
  for (const Parameter& p : parameters()) {
    if (p.section != section) continue;
    if (p.kind == ValueKind::text && !p.choices.empty()) one_of(p, object, prefix);
    if (!p.values) continue;
    double values[3];
    const int n = p.values(object, values);
    for (int e = 0; e < n; ++e) {
      const bool indexed = n > 1 && p.range.bounded() && !p.whole_key;
      const std::string key =
          join_key(prefix, p.name) + (indexed ? "[" + std::to_string(e) + "]" : "");
      const double x = values[e];
      finite(key, x);
      if (!p.range.contains(x))
        fail(key, "must be " + violated(p, x) + " (got " + format_number(x) + ")");
    }
  }
}

inline void Validator::one_of(const Parameter& p, const void* object,
                              const std::string& prefix) const {
  const std::string& value = *p.text(object);
  if (listed(p.choices, value)) return;
  fail(join_key(prefix, p.name), std::string(p.name) + " \"" + value +
                                     "\" is unknown (valid: " + std::string(p.choices) + ")");
}

inline void Validator::finite(const std::string& key, double value) const {
  if (!std::isfinite(value)) fail(key, "must be finite (got " + format_number(value) + ")");
  if (std::abs(value) > kMaxSceneMagnitude)
    fail(key,
         "must be at most 3.4e+38 in magnitude, the largest float the solver can hold "
         "(got " +
             format_number(value) + ")");
}

inline void Validator::check_cloth_count() const {
  const std::string key(key_of<&Scene::cloths>());
  if (scene_.cloths.empty())
    fail(key, "the scene has no cloth; add a [cloth] table or [[cloth]] tables");
  if (!scene_.multi_cloth && scene_.cloths.size() != 1)
    fail(key, "the one-cloth form ([cloth]) holds exactly one cloth");
}

inline void Validator::check_cloth(const ClothSpec& cloth) const {
  const std::string& k = cloth.key;
  ranges(Section::cloth, &cloth, k);
  if (cloth.shape == "mesh") {
    check_mesh_cloth(cloth);
  } else if (cloth.shape == "tube") {
    check_tube(cloth);
  } else {
    for (std::string_view tube_key : {key_of<&ClothSpec::radius>(), key_of<&ClothSpec::length>()})
      if (given(cloth, tube_key))
        fail(key_path(k, tube_key), "belongs to shape = \"tube\" (this cloth is a grid)");
  }
  check_resolution(cloth);
  if (cloth.shape != "mesh") check_spacing(cloth);
  check_axes(cloth);
  if (!unloaded_mesh(cloth)) check_pins(cloth);
  if (cloth.springs)
    ranges(Section::springs, &*cloth.springs, key_path(k, key_of<&ClothSpec::springs>()));
}

inline void Validator::check_transform_feedback() const {
  const std::string solver = section_path(Section::solver);
  const std::string backend = join_key(solver, key_of<&SolverSpec::backend>()) + " = \"" +
                              to_string(Backend::transform_feedback) + "\" ";
  const IntegratorKind k = scene_.solver.integrator;
  if (k != IntegratorKind::symplectic_euler && k != IntegratorKind::explicit_euler &&
      k != IntegratorKind::seed_hack)
    fail(join_key(solver, key_of<&SolverSpec::integrator>()),
         backend + "steps symplectic_euler, explicit_euler and seed_hack, not " + to_string(k) +
             " (backend = \"gpu\" runs verlet, \"cpu\" every integrator)");
  if (scene_.solver.precision == Precision::f64)
    fail(join_key(solver, key_of<&SolverSpec::precision>()),
         backend + "computes in float, not double");
  for (const ClothSpec& cloth : scene_.cloths)
    if (cloth.shape != "grid")
      fail(key_path(cloth.key, key_of<&ClothSpec::shape>()),
           backend + "draws grid cloths only, not a " + cloth.shape +
               " (whose UVs may copy vertices along a seam, which the captured buffer does "
               "not hold; backend = \"gpu\" runs it)");
}

inline void Validator::check_tube(const ClothSpec& cloth) const {
  const std::string_view size = key_of<&ClothSpec::size>();
  if (given(cloth, size))
    fail(key_path(cloth.key, size), "a tube takes radius and length, not size");
  const auto [nu, nv] = cloth.resolution;
  if (nu < 6 || nv < 2)
    fail(key_path(cloth.key, key_of<&ClothSpec::resolution>()),
         "a tube needs at least 6 vertices around and 2 rings (got [" + std::to_string(nu) + ", " +
             std::to_string(nv) + "])");
}

inline void Validator::check_spacing(const ClothSpec& cloth) const {
  const auto [nu, nv] = cloth.resolution;
  auto require = [&](std::string_view name, double spacing, const std::string& what) {
    if (!(spacing >= kMinVertexSpacing))
      fail(key_path(cloth.key, name), "puts neighbouring vertices " + format_number(spacing) +
                                          " m apart " + what + "; at least " +
                                          format_number(kMinVertexSpacing) + " m is needed");
  };
  if (cloth.shape == "tube") {
    const double chord = 2.0 * std::sin(3.14159265358979323846 / std::max(nu, 1));
    for (int ring = 0; ring < 2; ++ring)
      require(key_of<&ClothSpec::radius>(), chord * cloth.radius[ring],
              ring == 0 ? "round the first ring" : "round the last ring");
    if (nv > 1) require(key_of<&ClothSpec::length>(), cloth.length / (nv - 1), "from ring to ring");
    return;
  }
  const char* const along[2] = {"along u", "along v"};
  for (int d = 0; d < 2; ++d)
    if (cloth.resolution[d] > 1)
      require(key_of<&ClothSpec::size>(), cloth.size[d] / (cloth.resolution[d] - 1),
              std::string(along[d]) + " (size / (resolution - 1))");
}

inline void Validator::check_resolution(const ClothSpec& cloth) const {
  const auto [nu, nv] = cloth.resolution;
  const std::int64_t vertices = std::int64_t{nu} * nv;
  if (vertices > kMaxVertices)
    fail(key_path(cloth.key, key_of<&ClothSpec::resolution>()),
         std::to_string(nu) + " x " + std::to_string(nv) + " = " + std::to_string(vertices) +
             " vertices; at most " + std::to_string(kMaxVertices) + " are allowed");
}

inline void Validator::check_total_vertices() const {
  std::int64_t total = 0;
  for (const ClothSpec& cloth : scene_.cloths) {
    if (unloaded_mesh(cloth)) continue;
    total += std::int64_t{cloth.resolution[0]} * cloth.resolution[1];
    if (total > kMaxVertices)
      fail(key_path(cloth.key, key_of<&ClothSpec::resolution>()),
           "the scene's cloths have " + std::to_string(total) + " vertices up to this one; at " +
               "most " + std::to_string(kMaxVertices) + " are allowed in all");
  }
}

inline void Validator::check_axes(const ClothSpec& cloth) const {
  const std::string u_key = key_path(cloth.key, key_of<&ClothSpec::u_axis>());
  const std::string v_key = key_path(cloth.key, key_of<&ClothSpec::v_axis>());
  const double lu = length(cloth.u_axis);
  const double lv = length(cloth.v_axis);
  if (lu == 0.0) fail(u_key, "must not be the zero vector");
  if (lv == 0.0) fail(v_key, "must not be the zero vector");
  // The cosine of the normalised axes, as the cloth is built from them.
  const Vec3d u = normalised(cloth.u_axis);
  const Vec3d v = normalised(cloth.v_axis);
  const double cosine = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  if (!(std::abs(cosine) < kOrthogonalityTolerance))
    fail(v_key, "must be orthogonal to " + std::string(key_of<&ClothSpec::u_axis>()) +
                    " (cos angle = " + format_number(cosine) + ")");
}

inline void Validator::check_mesh_cloth(const ClothSpec& cloth) const {
  const std::string& k = cloth.key;
  for (std::string_view grid_key :
       {key_of<&ClothSpec::size>(), key_of<&ClothSpec::resolution>(), key_of<&ClothSpec::u_axis>(),
        key_of<&ClothSpec::v_axis>(), key_of<&ClothSpec::radius>(), key_of<&ClothSpec::length>()})
    if (given(cloth, grid_key))
      fail(key_path(k, grid_key),
           "belongs to a grid or tube cloth (a mesh cloth takes its shape from file)");
  if (!loaded_) return;
  const std::string file = key_path(k, key_of<&ClothSpec::file>());
  if (!cloth.mesh || cloth.mesh->triangles.empty())
    fail(file, "no OBJ mesh was read for this mesh cloth");
  const TriangleMesh& mesh = *cloth.mesh;
  const auto in_obj = [&](std::size_t t) {  // "round.obj: line 57: " where the face's is known
    return cloth.file + (t < mesh.triangle_lines.size()
                             ? ": line " + std::to_string(mesh.triangle_lines[t]) + ": "
                             : std::string(": "));
  };
  std::vector<bool> used(mesh.positions.size(), false);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int c = 0; c < 3; ++c) {
      const auto& tri = mesh.triangles[t];
      used[std::size_t(tri[c])] = true;
      const int a = tri[c], b = tri[(c + 1) % 3];
      if ((mesh.positions[std::size_t(a)] - mesh.positions[std::size_t(b)]).norm() == 0.0)
        fail(file, in_obj(t) + "the edge between OBJ vertices " + std::to_string(a + 1) + " and " +
                       std::to_string(b + 1) + " has zero length");
    }
  for (std::size_t v = 0; v < used.size(); ++v)
    if (!used[v])
      fail(file, cloth.file + ": OBJ vertex " + std::to_string(v + 1) + " belongs to no face");
  check_triangle_areas(mesh, file, in_obj);
  check_valence(mesh, file, cloth.file);
}

inline void Validator::check_valence(const TriangleMesh& mesh, const std::string& file,
                                     const std::string& obj) const {
  std::vector<int> valence(mesh.positions.size(), 0);
  for (const auto& [a, b] : mesh_edges(mesh.triangles))
    ++valence[std::size_t(a)], ++valence[std::size_t(b)];
  const auto most = std::max_element(valence.begin(), valence.end());
  if (*most > kMaxMeshValence)
    fail(file, obj + ": OBJ vertex " + std::to_string(most - valence.begin() + 1) + " has " +
                   std::to_string(*most) + " edges; a mesh cloth may have at most " +
                   std::to_string(kMaxMeshValence) +
                   " at a vertex (every vertex's spring table is as wide as the widest)");
}

template <class InObj>
inline void Validator::check_triangle_areas(const TriangleMesh& mesh, const std::string& file,
                                            const InObj& in_obj) const {
  constexpr double kFlat = 1e-10;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d& a = mesh.positions[std::size_t(tri[0])];
    const Eigen::Vector3d& b = mesh.positions[std::size_t(tri[1])];
    const Eigen::Vector3d& c = mesh.positions[std::size_t(tri[2])];
    const double longest =
        std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    if ((b - a).cross(c - a).norm() > kFlat * longest) continue;
    const std::string what =
        mesh.triangle_lines.empty() ? "triangle " + std::to_string(t + 1) : "the face";
    fail(file, in_obj(t) + what + " (vertices " + std::to_string(tri[0] + 1) + ", " +
                   std::to_string(tri[1] + 1) + ", " + std::to_string(tri[2] + 1) +
                   ") has zero area: its corners are collinear");
  }
}

inline void Validator::check_pins(const ClothSpec& cloth) const {
  const auto [nu, nv] = cloth.resolution;
  const std::string pins_key = key_path(cloth.key, key_of<&ClothSpec::pins>());
  std::set<std::pair<int, int>> seen;
  for (std::size_t n = 0; n < cloth.pins.size(); ++n) {
    const auto [i, j] = cloth.pins[n];
    const std::string key = pins_key + "[" + std::to_string(n) + "]";
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
    fail(pins_key, "every vertex is pinned; leave at least one free");
}

inline void Validator::check_forces() const {
  ranges(Section::forces, &scene_.forces, section_path(Section::forces));
  if (scene_.forces.wind.enabled)
    ranges(Section::wind, &scene_.forces.wind, section_path(Section::wind));
}

inline void Validator::check_pins_follow(const ClothSpec& cloth) const {
  if (cloth.pins_follow.empty()) return;
  const std::string key = key_path(cloth.key, key_of<&ClothSpec::pins_follow>());
  for (std::size_t n = 0; n < cloth.pins_follow.size(); ++n) {
    const int c = cloth.pins_follow[n];
    if (c < 0 || c >= static_cast<int>(scene_.colliders.size()))
      fail(cloth.pins_follow.size() > 1 ? key + "[" + std::to_string(n) + "]" : key,
           "names collider " + std::to_string(c) + ", but the scene has " +
               std::to_string(scene_.colliders.size()) + " ([[colliders]] count from 0)");
  }
  if (cloth.pins.empty()) fail(key, "the cloth has no pins to move");
}

inline void Validator::check_mannequin(const MannequinSpec& m) const {
  const std::string key = section_path(Section::mannequin);
  ranges(Section::mannequin, &m, key);
  ColliderSpec every_part;
  every_part.static_friction = m.static_friction;
  every_part.kinetic_friction = m.kinetic_friction;
  ranges(Section::friction, &every_part, key_path(key, key_of<&MannequinSpec::static_friction>()));
}

inline void Validator::check_collider(const ColliderSpec& c) const {
  const std::string& k = c.key;
  ranges(Section::collider, &c, k);
  ranges(Section::friction, &c, key_path(k, key_of<&ColliderSpec::static_friction>()));
  const std::string motion = key_path(k, key_of<&ColliderSpec::motion>());
  ranges(Section::motion, &c.motion, motion);
  switch (c.kind) {
    case ColliderKind::plane:
      if (length(c.normal) < 1e-9)
        fail(key_path(k, key_of<&ColliderSpec::normal>()), "must not be the zero vector");
      break;
    case ColliderKind::box: {
      const double smallest = std::min({c.half_extents[0], c.half_extents[1], c.half_extents[2]});
      if (!(c.rounding < smallest))
        fail(key_path(k, key_of<&ColliderSpec::rounding>()),
             "must be smaller than the smallest half extent (" + format_number(smallest) +
                 " m), got " + format_number(c.rounding));
      break;
    }
    case ColliderKind::mesh:
      if (loaded_ && !c.mesh)
        fail(key_path(k, key_of<&ColliderSpec::file>()),
             "no mesh was read (a mesh collider needs file = \"x.obj\")");
      break;
    case ColliderKind::capsule:
      if (length({c.b[0] - c.a[0], c.b[1] - c.a[1], c.b[2] - c.a[2]}) < 1e-9)
        fail(key_path(k, key_of<&ColliderSpec::b>()),
             "must differ from a (a capsule needs an axis)");
      break;
    case ColliderKind::sphere:
      break;
  }
  check_keyframes(c.motion, motion);
}

inline void Validator::check_keyframes(const ColliderMotion& m, const std::string& motion) const {
  const std::string keys = key_path(motion, key_of<&ColliderMotion::keys>());
  for (std::size_t i = 0; i < m.keys.size(); ++i) {
    const ColliderKey& key = m.keys[i];
    const std::string kk = keys + "[" + std::to_string(i) + "]";
    ranges(Section::keyframe, &key, kk);
    if (i > 0 && !(key.time > m.keys[i - 1].time))
      fail(key_path(kk, key_of<&ColliderKey::time>()), "keyframe times must increase (got " +
                                                           format_number(key.time) + " after " +
                                                           format_number(m.keys[i - 1].time) + ")");
  }
  if (!m.keys.empty() &&
      (m.velocity != Vec3d{0.0, 0.0, 0.0} || m.angular_velocity != Vec3d{0.0, 0.0, 0.0}))
    fail(motion, "give either keys or velocities, not both");
}

inline void Validator::check_render(const RenderSpec& r) const {
  ranges(Section::render, &r, section_path(Section::render));
  const LightSpec& l = r.light;
  ranges(Section::light, &l, section_path(Section::light));
  if (l.position && l.target &&
      length({(*l.target)[0] - (*l.position)[0], (*l.target)[1] - (*l.position)[1],
              (*l.target)[2] - (*l.position)[2]}) < 1e-6)
    fail(key_path(section_path(Section::light), key_of<&LightSpec::target>()),
         "must differ from " +
             key_path(section_path(Section::light), key_of<&LightSpec::position>()));
  if (length(l.direction) < 1e-9)
    fail(key_path(section_path(Section::light), key_of<&LightSpec::direction>()),
         "must not be zero");
  ranges(Section::sky, &r.sky, section_path(Section::sky));
  ranges(Section::pole, &r.pole, section_path(Section::pole));
  ranges(Section::camera, &r.camera, section_path(Section::camera));
  for (const MeshSpec& m : r.meshes) ranges(Section::mesh, &m, m.key);
  ranges(Section::look, &r.cloth, section_path(Section::look));
}

inline void Validator::check_trace(const TraceSpec& trace) const {
  const std::string prefix = section_path(Section::trace);
  const std::string vertices = key_path(prefix, key_of<&TraceSpec::vertices>());
  std::set<std::tuple<int, int, int>> seen;
  for (std::size_t n = 0; n < trace.vertices.size(); ++n)
    check_trace_vertex(trace.vertices[n], vertices + "[" + std::to_string(n) + "]", seen);
  if (!(trace.position || trace.velocity || trace.force || trace.energy)) {
    const Parameter& fields = *find_parameter(Section::trace, key_of<&TraceSpec::position>());
    fail(key_path(prefix, fields.name), "name at least one of " + std::string(fields.choices));
  }
  ranges(Section::trace, &trace, prefix);
}

inline void Validator::check_trace_vertex(const TraceVertex& v, const std::string& key,
                                          std::set<std::tuple<int, int, int>>& seen) const {
  const int cloths = static_cast<int>(scene_.cloths.size());
  if (v.cloth < 0 || v.cloth >= cloths)
    fail(key, "cloth index " + std::to_string(v.cloth) + " is out of range (the scene has " +
                  std::to_string(cloths) + " cloth" + (cloths == 1 ? "" : "s") + ")");
  if (unloaded_mesh(scene_.cloths[static_cast<std::size_t>(v.cloth)])) return;
  const auto [nu, nv] = scene_.cloths[static_cast<std::size_t>(v.cloth)].resolution;
  if (v.i < 0 || v.i >= nu || v.j < 0 || v.j >= nv)
    fail(key, "vertex [" + std::to_string(v.i) + ", " + std::to_string(v.j) + "] is outside the " +
                  std::to_string(nu) + " x " + std::to_string(nv) + " grid of " +
                  scene_.cloths[static_cast<std::size_t>(v.cloth)].key);
  if (!seen.emplace(v.cloth, v.i, v.j).second) fail(key, "vertex is listed twice");
}

}  // namespace

void validate_scene(const Scene& scene) {
  Validator(scene, true).run();
}

void validate_scene_data(const Scene& scene) {
  Validator(scene, false).run();
}

}  // namespace clothlab
