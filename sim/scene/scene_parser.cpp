// Scene parser: TOML text -> (apply --set overrides, overrides.cpp) -> typed read into Scene ->
// validate_scene.
// The TOML layer (toml++) checks syntax; this file checks keys and types and records where each
// value came from; validate.cpp checks ranges. Errors are SceneError, never a crash.
#include "sim/scene/scene_parser.hpp"

#include "sim/audio/music_track.hpp"
#include "sim/body/body_motion.hpp"
#include "sim/mesh/triangle_mesh.hpp"
#include "sim/scene/overrides.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <utility>

// GCC 12 at -O3 reports a false -Wrestrict inside std::string for `"text" + std::string(...)`
// (GCC bug 105329); the message texts below are built that way throughout.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ == 12
#pragma GCC diagnostic ignored "-Wrestrict"
#endif

namespace clothlab {

namespace {

// ---------------------------------------------------------------------------------------------
// Reading the TOML tree into a Scene

std::string describe(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string:
      return "string \"" + *node.value<std::string>() + "\"";
    case toml::node_type::integer:
      return "integer " + std::to_string(*node.value<std::int64_t>());
    case toml::node_type::floating_point: {
      // "16.0", not "16": the point is what makes it a float.
      std::string text = format_number(*node.value<double>());
      if (text.find_first_not_of("-0123456789") == std::string::npos) text += ".0";
      return "float " + text;
    }
    case toml::node_type::boolean:
      return *node.value<bool>() ? "boolean true" : "boolean false";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::table:
      return "a table";
    default:
      return "a date/time";
  }
}

// A fixed list of key or value names.
using Names = std::span<const std::string_view>;

std::string list_names(Names names) {
  std::string text;
  for (std::string_view name : names) text += (text.empty() ? "" : ", ") + std::string(name);
  return text;
}

constexpr std::string_view kTopKeys[] = {"cloth",  "springs",   "forces", "solver",   "trace",
                                         "render", "colliders", "music",  "mannequin"};
constexpr std::string_view kMusicKeys[] = {"file", "tempo", "seconds"};
constexpr std::string_view kMannequinKeys[] = {"position",  "facing",   "settle",   "blend_beats",
                                               "amplitude", "friction", "thickness"};
constexpr std::string_view kClothKeys[] = {
    "shape",   "size",       "resolution", "origin", "u_axis",      "v_axis", "mass",  "pins",
    "springs", "release_at", "radius",     "length", "pins_follow", "file",   "scale", "rotation"};
constexpr std::string_view kSpringKeys[] = {"rule", "stiffness", "damping"};
constexpr std::string_view kForceKeys[] = {"gravity", "drag", "wind"};
constexpr std::string_view kWindKeys[] = {"velocity", "gust", "seed", "gust_period", "coefficient"};
constexpr std::string_view kSolverKeys[] = {
    "integrator", "dt",        "substeps", "iterations",     "cg_tolerance",  "cg_max_iterations",
    "threads",    "precision", "backend",  "self_collision", "self_thickness"};
constexpr std::string_view kTraceKeys[] = {"vertices", "fields", "every"};
constexpr std::string_view kTraceFields[] = {"position", "velocity", "force", "energy"};
constexpr std::string_view kRenderKeys[] = {"mode", "shadows", "shadow_map_size", "light", "sky",
                                            "pole", "meshes",  "cloth",           "camera"};
constexpr std::string_view kCameraKeys[] = {"target", "yaw", "pitch", "distance"};
constexpr std::string_view kLightKeys[] = {"type",  "position",  "target", "direction",
                                           "color", "intensity", "size"};
constexpr std::string_view kSkyKeys[] = {"enabled", "turbidity"};
constexpr std::string_view kPoleKeys[] = {"enabled", "radius"};
constexpr std::string_view kMeshKeys[] = {"type",  "center", "radius", "half_extents", "rotation",
                                          "color", "file",   "scale",  "smooth"};
constexpr std::string_view kColliderKeys[] = {
    "type",     "point",    "normal",    "center", "radius", "half_extents", "rotation",  "a", "b",
    "rounding", "friction", "thickness", "motion", "file",   "scale",        "resolution"};
constexpr std::string_view kFrictionKeys[] = {"static", "kinetic"};
constexpr std::string_view kMotionKeys[] = {"velocity", "angular_velocity", "keys"};
constexpr std::string_view kKeyframeKeys[] = {"time", "offset", "rotation"};
constexpr std::string_view kLookKeys[] = {"roughness", "sheen",        "sheen_roughness", "threads",
                                          "opacity",   "transmission", "thread_fraction", "color",
                                          "bump",      "subsurface",   "glints"};

class Reader {
 public:
  Reader(const OverrideOrigins& origins, Scene& scene) : origins_(origins), scene_(scene) {}

  void read(const toml::table& root) {
    check_top_keys(root);
    if (const toml::node* node = root.get("springs"))
      scene_.springs = read_springs(table(*node, "springs"), "springs", SpringSpec{});
    read_cloths(root);
    if (const toml::node* node = root.get("forces")) read_forces(table(*node, "forces"));
    if (const toml::node* node = root.get("solver")) read_solver(table(*node, "solver"));
    if (const toml::node* node = root.get("trace")) scene_.trace = read_trace(*node);
    if (const toml::node* node = root.get("render")) read_render(*node);
    if (const toml::node* node = root.get("colliders")) read_colliders(*node);
    if (const toml::node* node = root.get("music")) read_music(*node);
    if (const toml::node* node = root.get("mannequin")) read_mannequin(*node);
    resolve_follow_names();
  }

 private:
  // --- locations and errors ---

  SourceLoc loc(const std::string& key, const toml::node& node) const {
    for (std::string k = key; !k.empty();) {
      if (auto it = origins_.find(k); it != origins_.end()) return SourceLoc{it->second, 0, 0};
      const auto cut = k.find_last_of(".[");
      if (cut == std::string::npos) break;
      k.resize(cut);
    }
    const toml::source_position begin = node.source().begin;
    return SourceLoc{scene_.file, static_cast<int>(begin.line), static_cast<int>(begin.column)};
  }

  void note(const std::string& key, const toml::node& node) {
    scene_.locations[key] = loc(key, node);
  }

  [[noreturn]] void fail(const std::string& key, const toml::node& node,
                         const std::string& message) const {
    throw SceneError(loc(key, node), key, message);
  }

  // Calls read(node, key) for t[name] when present, after recording its location.
  template <class F>
  void field(const toml::table& t, const std::string& prefix, std::string_view name, F&& read) {
    if (const toml::node* node = t.get(name)) {
      const std::string key = join_key(prefix, name);
      note(key, *node);
      read(*node, key);
    }
  }

  // For a key that should not be there, point at the key itself rather than at its value.
  [[noreturn]] void fail_key(const std::string& path, const toml::key& name, const toml::node& node,
                             const std::string& message) const {
    SourceLoc where = loc(path, node);
    const toml::source_position begin = name.source().begin;
    if (where.line > 0 && begin.line > 0) {  // line 0: the key came from a --set
      where.line = static_cast<int>(begin.line);
      where.column = static_cast<int>(begin.column);
    }
    throw SceneError(where, path, message);
  }

  static bool contains(Names names, std::string_view name) {
    return std::find(names.begin(), names.end(), name) != names.end();
  }

  void check_keys(const toml::table& t, const std::string& prefix, Names allowed) const {
    for (const auto& [name, node] : t)
      if (!contains(allowed, name.str()))
        fail_key(join_key(prefix, name.str()), name, node,
                 "unknown key (valid keys in " + prefix + ": " + list_names(allowed) + ")");
  }

  void check_top_keys(const toml::table& root) const {
    for (const auto& [name, node] : root) {
      const std::string key(name.str());
      if (!contains(kTopKeys, key))
        fail_key(key, name, node, "unknown top-level key (valid: " + list_names(kTopKeys) + ")");
    }
  }

  // --- typed values ---

  double number(const toml::node& node, const std::string& key) const {
    double value = 0.0;
    if (const auto* i = node.as_integer())
      value = static_cast<double>(i->get());
    else if (const auto* f = node.as_floating_point())
      value = f->get();
    else
      fail(key, node, "expected a number, got " + describe(node));
    if (!std::isfinite(value)) fail(key, node, "must be finite (got " + format_number(value) + ")");
    return value;
  }

  // Floats are refused where an integer is meant (a resolution of 32.5 is a mistake).
  std::int64_t integer(const toml::node& node, const std::string& key) const {
    const auto* i = node.as_integer();
    if (!i) fail(key, node, "expected an integer, got " + describe(node));
    return i->get();
  }

  int small_integer(const toml::node& node, const std::string& key) const {
    const std::int64_t value = integer(node, key);
    if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max())
      fail(key, node, "out of range (got " + std::to_string(value) + ")");
    return static_cast<int>(value);
  }

  std::string text(const toml::node& node, const std::string& key) const {
    const auto* s = node.as_string();
    if (!s) fail(key, node, "expected a string, got " + describe(node));
    return s->get();
  }

  const toml::table& table(const toml::node& node, const std::string& key) const {
    const auto* t = node.as_table();
    if (!t) fail(key, node, "expected a table, got " + describe(node));
    return *t;
  }

  const toml::array& array(const toml::node& node, const std::string& key,
                           std::optional<std::size_t> size = std::nullopt,
                           std::string_view what = "") const {
    const auto* a = node.as_array();
    if (!a) fail(key, node, "expected an array" + std::string(what) + ", got " + describe(node));
    if (size && a->size() != *size)
      fail(key, node,
           "expected " + std::to_string(*size) + " elements" + std::string(what) + ", got " +
               std::to_string(a->size()));
    return *a;
  }

  template <std::size_t N>
  std::array<double, N> numbers(const toml::node& node, const std::string& key) const {
    const toml::array& a = array(node, key, N, " (numbers)");
    std::array<double, N> out{};
    for (std::size_t n = 0; n < N; ++n)
      out[n] = number(*a.get(n), key + "[" + std::to_string(n) + "]");
    return out;
  }

  // [i, j] pairs, and [c, i, j] triples for trace vertices.
  std::vector<int> index_tuple(const toml::node& node, const std::string& key, std::size_t min,
                               std::size_t max, std::string_view form) const {
    const auto* a = node.as_array();
    if (!a || a->size() < min || a->size() > max)
      fail(key, node,
           "expected " + std::string(form) + ", got " + describe(node) +
               (a ? " of " + std::to_string(a->size()) : std::string()));
    std::vector<int> out;
    for (std::size_t n = 0; n < a->size(); ++n)
      out.push_back(small_integer(*a->get(n), key + "[" + std::to_string(n) + "]"));
    return out;
  }

  // --- sections ---

  void read_cloths(const toml::table& root) {
    const toml::node* node = root.get("cloth");
    if (!node) return;  // validate_scene reports the missing cloth
    note("cloth", *node);
    if (const toml::table* one = node->as_table()) {
      scene_.multi_cloth = false;
      scene_.cloths.push_back(read_cloth(*one, "cloth"));
      return;
    }
    const toml::array& many = array(*node, "cloth", std::nullopt, " of tables ([[cloth]])");
    if (many.empty()) fail("cloth", *node, "the scene has no cloth; [[cloth]] list is empty");
    scene_.multi_cloth = true;
    for (std::size_t c = 0; c < many.size(); ++c) {
      const std::string key = "cloth[" + std::to_string(c) + "]";
      note(key, *many.get(c));
      scene_.cloths.push_back(read_cloth(table(*many.get(c), key), key));
    }
  }

  ClothSpec read_cloth(const toml::table& t, const std::string& key) {
    check_keys(t, key, kClothKeys);
    ClothSpec cloth;
    cloth.key = key;
    field(t, key, "shape", [&](auto& n, auto& k) { cloth.shape = text(n, k); });
    field(t, key, "size", [&](auto& n, auto& k) { cloth.size = numbers<2>(n, k); });
    field(t, key, "resolution", [&](auto& n, auto& k) {
      const toml::array& a = array(n, k, 2, " (integers)");
      for (std::size_t d = 0; d < 2; ++d)
        cloth.resolution[d] = small_integer(*a.get(d), k + "[" + std::to_string(d) + "]");
    });
    field(t, key, "origin", [&](auto& n, auto& k) { cloth.origin = numbers<3>(n, k); });
    field(t, key, "u_axis", [&](auto& n, auto& k) { cloth.u_axis = numbers<3>(n, k); });
    field(t, key, "v_axis", [&](auto& n, auto& k) { cloth.v_axis = numbers<3>(n, k); });
    field(t, key, "mass", [&](auto& n, auto& k) { cloth.mass = number(n, k); });
    field(t, key, "pins",
          [&](auto& n, auto& k) { cloth.pins = read_pins(n, k, cloth.shape == "mesh"); });
    field(t, key, "release_at", [&](auto& n, auto& k) { cloth.release_at = number(n, k); });
    field(t, key, "radius", [&](auto& n, auto& k) {
      // One radius (a cylinder) or [first ring, last ring] (a frustum).
      if (n.is_array()) {
        cloth.radius = numbers<2>(n, k);
      } else {
        const double r = number(n, k);
        cloth.radius = {r, r};
      }
    });
    field(t, key, "length", [&](auto& n, auto& k) { cloth.length = number(n, k); });
    field(t, key, "pins_follow", [&](auto& n, auto& k) {
      // A collider's index, or a mannequin part's name (resolved once the mannequin is read).
      if (n.is_string()) {
        cloth.pins_follow_name = text(n, k);
        follow_nodes_[k] = &n;
      } else {
        cloth.pins_follow = small_integer(n, k);
      }
    });
    // A cloth's own springs start from the top-level [springs], so they need name only what
    // differs.
    field(t, key, "springs",
          [&](auto& n, auto& k) { cloth.springs = read_springs(table(n, k), k, scene_.springs); });
    field(t, key, "file", [&](auto& n, auto& k) { cloth.file = text(n, k); });
    field(t, key, "scale", [&](auto& n, auto& k) { cloth.scale = number(n, k); });
    field(t, key, "rotation", [&](auto& n, auto& k) { cloth.rotation = numbers<3>(n, k); });
    if (cloth.shape == "mesh") read_cloth_mesh(t, key, cloth);
    return cloth;
  }

  // A mesh cloth's OBJ, read now (errors name the key); its vertex count becomes the resolution
  // [n, 1], the layout a mesh cloth has in the solver (sim/model/model.hpp, ClothRange).
  void read_cloth_mesh(const toml::table& t, const std::string& key, ClothSpec& cloth) {
    if (cloth.file.empty())
      fail(key + ".file", t, "missing (a mesh cloth needs file = \"cloth.obj\")");
    if (!t.contains("origin")) cloth.origin = {0.0, 0.0, 0.0};
    cloth.mesh = std::make_shared<const TriangleMesh>(read_obj(t, key, cloth.file, cloth.scale));
    cloth.resolution = {static_cast<int>(cloth.mesh->positions.size()), 1};
  }

  // [i, j] pairs on a grid or tube; on a mesh cloth OBJ vertex numbers (1 = the file's first v
  // line, as its f lines count), kept as (number - 1, 0).
  std::vector<std::array<int, 2>> read_pins(const toml::node& node, const std::string& key,
                                            bool mesh) {
    const toml::array& a =
        array(node, key, std::nullopt, mesh ? " of OBJ vertex numbers" : " of [i, j] pairs");
    std::vector<std::array<int, 2>> pins;
    for (std::size_t n = 0; n < a.size(); ++n) {
      const std::string k = key + "[" + std::to_string(n) + "]";
      note(k, *a.get(n));
      if (mesh) {
        pins.push_back({small_integer(*a.get(n), k) - 1, 0});
      } else {
        const std::vector<int> ij = index_tuple(*a.get(n), k, 2, 2, "an [i, j] pair of integers");
        pins.push_back({ij[0], ij[1]});
      }
    }
    return pins;
  }

  SpringSpec read_springs(const toml::table& t, const std::string& key, SpringSpec springs) {
    check_keys(t, key, kSpringKeys);
    field(t, key, "rule", [&](auto& n, auto& k) { springs.rule = text(n, k); });
    field(t, key, "stiffness", [&](auto& n, auto& k) { springs.stiffness = number(n, k); });
    field(t, key, "damping", [&](auto& n, auto& k) { springs.damping = number(n, k); });
    return springs;
  }

  void read_forces(const toml::table& t) {
    const std::string key = "forces";
    check_keys(t, key, kForceKeys);
    ForceSpec& f = scene_.forces;
    field(t, key, "gravity", [&](auto& n, auto& k) { f.gravity = numbers<3>(n, k); });
    field(t, key, "drag", [&](auto& n, auto& k) { f.drag = number(n, k); });
    field(t, key, "wind", [&](auto& n, auto& k) { f.wind = read_wind(table(n, k), k); });
  }

  WindSpec read_wind(const toml::table& t, const std::string& key) {
    check_keys(t, key, kWindKeys);
    WindSpec wind;
    wind.enabled = true;
    if (!t.contains("velocity"))
      fail(key + ".velocity", t, "missing (wind needs velocity = [x, y, z] in m/s)");
    field(t, key, "velocity", [&](auto& n, auto& k) { wind.velocity = numbers<3>(n, k); });
    field(t, key, "gust", [&](auto& n, auto& k) { wind.gust = number(n, k); });
    field(t, key, "seed", [&](auto& n, auto& k) {
      const std::int64_t seed = integer(n, k);
      if (seed < 0) fail(k, n, "must be >= 0 (got " + std::to_string(seed) + ")");
      wind.seed = static_cast<std::uint64_t>(seed);
    });
    field(t, key, "gust_period", [&](auto& n, auto& k) { wind.gust_period = number(n, k); });
    field(t, key, "coefficient", [&](auto& n, auto& k) { wind.coefficient = number(n, k); });
    return wind;
  }

  void read_solver(const toml::table& t) {
    const std::string key = "solver";
    check_keys(t, key, kSolverKeys);
    SolverSpec& s = scene_.solver;
    field(t, key, "integrator", [&](auto& n, auto& k) { s.integrator = read_integrator(n, k); });
    field(t, key, "dt", [&](auto& n, auto& k) {
      if (n.is_string()) {
        if (text(n, k) != "auto")
          fail(k, n, "expected a number of seconds or \"auto\", got " + describe(n));
        s.dt_auto = true;
      } else {
        s.dt = number(n, k);
        s.dt_auto = false;
      }
    });
    field(t, key, "substeps", [&](auto& n, auto& k) { s.substeps = small_integer(n, k); });
    field(t, key, "iterations", [&](auto& n, auto& k) { s.iterations = small_integer(n, k); });
    field(t, key, "cg_tolerance", [&](auto& n, auto& k) { s.cg_tolerance = number(n, k); });
    field(t, key, "cg_max_iterations",
          [&](auto& n, auto& k) { s.cg_max_iterations = small_integer(n, k); });
    field(t, key, "threads", [&](auto& n, auto& k) { s.threads = small_integer(n, k); });
    field(t, key, "precision", [&](auto& n, auto& k) {
      const std::string p = text(n, k);
      if (p != "float" && p != "double")
        fail(k, n, "unknown precision \"" + p + "\" (valid: float, double)");
      s.precision = p == "float" ? Precision::f32 : Precision::f64;
    });
    field(t, key, "self_collision", [&](auto& n, auto& k) { s.self_collision = boolean(n, k); });
    field(t, key, "self_thickness", [&](auto& n, auto& k) { s.self_thickness = number(n, k); });
    field(t, key, "backend", [&](auto& n, auto& k) {
      const std::string b = text(n, k);
      if (b != "cpu" && b != "gpu") fail(k, n, "unknown backend \"" + b + "\" (valid: cpu, gpu)");
      s.backend = b == "gpu" ? Backend::gpu : Backend::cpu;
    });
  }

  IntegratorKind read_integrator(const toml::node& node, const std::string& key) const {
    const std::string name = text(node, key);
    if (auto kind = integrator_from_string(name)) return *kind;
    std::string valid;
    for (IntegratorKind k : kAllIntegrators)
      valid += (valid.empty() ? "" : ", ") + std::string(to_string(k));
    fail(key, node, "unknown integrator \"" + name + "\" (valid: " + valid + ")");
  }

  TraceSpec read_trace(const toml::node& node) {
    const std::string key = "trace";
    const toml::table& t = section(node, key, kTraceKeys);
    TraceSpec trace;
    field(t, key, "vertices",
          [&](auto& n, auto& k) { trace.vertices = read_trace_vertices(n, k); });
    field(t, key, "fields", [&](auto& n, auto& k) { read_trace_fields(n, k, trace); });
    field(t, key, "every", [&](auto& n, auto& k) { trace.every = small_integer(n, k); });
    return trace;
  }

  // [i, j] names a vertex of cloth 0; [c, i, j] one of cloth c (the multi-cloth form).
  std::vector<TraceVertex> read_trace_vertices(const toml::node& node, const std::string& key) {
    const bool multi = scene_.multi_cloth;
    const std::string_view form = multi ? "[c, i, j] or [i, j]" : "[i, j]";
    const toml::array& a = array(node, key, std::nullopt, " of " + std::string(form) + " vertices");
    std::vector<TraceVertex> vertices;
    for (std::size_t n = 0; n < a.size(); ++n) {
      const std::string k = key + "[" + std::to_string(n) + "]";
      note(k, *a.get(n));
      const std::vector<int> v =
          index_tuple(*a.get(n), k, 2, multi ? 3 : 2, std::string(form) + " of integers");
      vertices.push_back(v.size() == 2 ? TraceVertex{0, v[0], v[1]}
                                       : TraceVertex{v[0], v[1], v[2]});
    }
    return vertices;
  }

  void read_trace_fields(const toml::node& node, const std::string& key, TraceSpec& trace) {
    const toml::array& a = array(node, key, std::nullopt, " of field names");
    if (a.empty()) fail(key, node, "name at least one of " + list_names(kTraceFields));
    trace.position = trace.velocity = trace.force = trace.energy = false;
    for (std::size_t n = 0; n < a.size(); ++n) {
      const std::string k = key + "[" + std::to_string(n) + "]";
      const std::string name = text(*a.get(n), k);
      bool* flag = name == "position"   ? &trace.position
                   : name == "velocity" ? &trace.velocity
                   : name == "force"    ? &trace.force
                   : name == "energy"   ? &trace.energy
                                        : nullptr;
      if (!flag)
        fail(k, *a.get(n),
             "unknown field \"" + name + "\" (valid: " + list_names(kTraceFields) + ")");
      if (*flag) fail(k, *a.get(n), "field \"" + name + "\" is listed twice");
      *flag = true;
    }
  }

  // A name from a fixed table (enum value and its scene-file spelling).
  template <class E, std::size_t N>
  E choice(const toml::node& node, const std::string& key,
           const std::array<std::pair<E, const char*>, N>& names, std::string_view what) const {
    const std::string name = text(node, key);
    std::string valid;
    for (const auto& [value, spelling] : names) {
      if (name == spelling) return value;
      valid += (valid.empty() ? "" : ", ") + std::string(spelling);
    }
    fail(key, node, "unknown " + std::string(what) + " \"" + name + "\" (valid: " + valid + ")");
  }

  bool boolean(const toml::node& node, const std::string& key) const {
    const auto* b = node.as_boolean();
    if (!b) fail(key, node, "expected true or false, got " + describe(node));
    return b->get();
  }

  void read_render(const toml::node& node) {
    const std::string key = "render";
    note(key, node);
    const toml::table& t = table(node, key);
    check_keys(t, key, kRenderKeys);
    RenderSpec& r = scene_.render;
    field(t, key, "mode", [&](auto& n, auto& k) { r.mode = small_integer(n, k); });
    field(t, key, "shadows",
          [&](auto& n, auto& k) { r.shadows = choice(n, k, kShadowFilterNames, "shadow filter"); });
    field(t, key, "shadow_map_size",
          [&](auto& n, auto& k) { r.shadow_map_size = small_integer(n, k); });
    field(t, key, "light", [&](auto& n, auto& k) { read_light(table(n, k), k, r.light); });
    field(t, key, "sky", [&](auto& n, auto& k) {
      const toml::table& s = table(n, k);
      check_keys(s, k, kSkyKeys);
      field(s, k, "enabled", [&](auto& m, auto& q) { r.sky.enabled = boolean(m, q); });
      field(s, k, "turbidity", [&](auto& m, auto& q) { r.sky.turbidity = number(m, q); });
    });
    field(t, key, "pole", [&](auto& n, auto& k) {
      const toml::table& p = table(n, k);
      check_keys(p, k, kPoleKeys);
      field(p, k, "enabled", [&](auto& m, auto& q) { r.pole.enabled = boolean(m, q); });
      field(p, k, "radius", [&](auto& m, auto& q) { r.pole.radius = number(m, q); });
    });
    field(t, key, "meshes", [&](auto& n, auto& k) {
      const toml::array& a = array(n, k, std::nullopt, " of tables ([[render.meshes]])");
      for (std::size_t m = 0; m < a.size(); ++m) {
        const std::string mk = k + "[" + std::to_string(m) + "]";
        note(mk, *a.get(m));
        r.meshes.push_back(read_mesh(table(*a.get(m), mk), mk));
      }
    });
    field(t, key, "cloth", [&](auto& n, auto& k) { read_look(table(n, k), k, r.cloth); });
    field(t, key, "camera", [&](auto& n, auto& k) {
      const toml::table& c = table(n, k);
      check_keys(c, k, kCameraKeys);
      field(c, k, "target", [&](auto& m, auto& q) { r.camera.target = numbers<3>(m, q); });
      field(c, k, "yaw", [&](auto& m, auto& q) { r.camera.yaw = number(m, q); });
      field(c, k, "pitch", [&](auto& m, auto& q) { r.camera.pitch = number(m, q); });
      field(c, k, "distance", [&](auto& m, auto& q) { r.camera.distance = number(m, q); });
    });
  }

  void read_light(const toml::table& t, const std::string& key, LightSpec& light) {
    check_keys(t, key, kLightKeys);
    field(t, key, "type",
          [&](auto& n, auto& k) { light.type = choice(n, k, kLightTypeNames, "light type"); });
    field(t, key, "position", [&](auto& n, auto& k) { light.position = numbers<3>(n, k); });
    field(t, key, "target", [&](auto& n, auto& k) { light.target = numbers<3>(n, k); });
    field(t, key, "direction", [&](auto& n, auto& k) { light.direction = numbers<3>(n, k); });
    field(t, key, "color", [&](auto& n, auto& k) { light.color = numbers<3>(n, k); });
    field(t, key, "intensity", [&](auto& n, auto& k) { light.intensity = number(n, k); });
    field(t, key, "size", [&](auto& n, auto& k) { light.size = number(n, k); });
  }

  MeshSpec read_mesh(const toml::table& t, const std::string& key) {
    check_keys(t, key, kMeshKeys);
    MeshSpec mesh;
    mesh.key = key;
    if (!t.contains("type"))
      fail(key + ".type", t,
           "missing (a mesh needs type = \"sphere\", \"box\", \"torus_knot\" or \"obj\")");
    field(t, key, "type",
          [&](auto& n, auto& k) { mesh.kind = choice(n, k, kMeshKindNames, "mesh type"); });
    field(t, key, "center", [&](auto& n, auto& k) { mesh.center = numbers<3>(n, k); });
    field(t, key, "radius", [&](auto& n, auto& k) { mesh.radius = number(n, k); });
    field(t, key, "half_extents", [&](auto& n, auto& k) { mesh.half_extents = numbers<3>(n, k); });
    field(t, key, "rotation", [&](auto& n, auto& k) { mesh.rotation = numbers<3>(n, k); });
    field(t, key, "color", [&](auto& n, auto& k) { mesh.color = numbers<3>(n, k); });
    field(t, key, "file", [&](auto& n, auto& k) { mesh.file = text(n, k); });
    field(t, key, "scale", [&](auto& n, auto& k) { mesh.scale = number(n, k); });
    field(t, key, "smooth", [&](auto& n, auto& k) { mesh.smooth = boolean(n, k); });
    if (mesh.kind == MeshKind::obj) {
      if (mesh.file.empty())
        fail(key + ".file", t, "missing (an obj mesh needs file = \"thing.obj\")");
      mesh.obj = std::make_shared<const TriangleMesh>(read_obj(t, key, mesh.file, mesh.scale));
    }
    return mesh;
  }

  // An OBJ named by `key`.file, read now so that a missing, malformed or empty file is a scene
  // error naming the key (the path is relative to the scene file's folder).
  TriangleMesh read_obj(const toml::table& t, const std::string& key, const std::string& file,
                        double scale) {
    if (!(scale > 0.0))
      fail(key + ".scale", *t.get("scale"), "must be > 0 (got " + format_number(scale) + ")");
    try {
      return load_obj(scene_relative(file), scale);
    } catch (const ObjError& e) {
      fail(key + ".file", *t.get("file"), e.what());
    }
  }

  void read_colliders(const toml::node& node) {
    const std::string key = "colliders";
    note(key, node);
    const toml::array& a = array(node, key, std::nullopt, " of tables ([[colliders]])");
    for (std::size_t c = 0; c < a.size(); ++c) {
      const std::string ck = key + "[" + std::to_string(c) + "]";
      note(ck, *a.get(c));
      scene_.colliders.push_back(read_collider(table(*a.get(c), ck), ck));
    }
  }

  ColliderSpec read_collider(const toml::table& t, const std::string& key) {
    check_keys(t, key, kColliderKeys);
    ColliderSpec c;
    c.key = key;
    if (!t.contains("type"))
      fail(key + ".type", t,
           "missing (a collider needs type = \"plane\", \"sphere\", \"box\" or \"capsule\")");
    field(t, key, "type",
          [&](auto& n, auto& k) { c.kind = choice(n, k, kColliderKindNames, "collider type"); });
    field(t, key, "point", [&](auto& n, auto& k) { c.point = numbers<3>(n, k); });
    field(t, key, "normal", [&](auto& n, auto& k) { c.normal = numbers<3>(n, k); });
    field(t, key, "center", [&](auto& n, auto& k) { c.center = numbers<3>(n, k); });
    field(t, key, "radius", [&](auto& n, auto& k) { c.radius = number(n, k); });
    field(t, key, "half_extents", [&](auto& n, auto& k) { c.half_extents = numbers<3>(n, k); });
    field(t, key, "rotation", [&](auto& n, auto& k) { c.rotation = numbers<3>(n, k); });
    field(t, key, "rounding", [&](auto& n, auto& k) { c.rounding = number(n, k); });
    field(t, key, "a", [&](auto& n, auto& k) { c.a = numbers<3>(n, k); });
    field(t, key, "b", [&](auto& n, auto& k) { c.b = numbers<3>(n, k); });
    field(t, key, "thickness", [&](auto& n, auto& k) { c.thickness = number(n, k); });
    field(t, key, "friction",
          [&](auto& n, auto& k) { read_friction(n, k, c.static_friction, c.kinetic_friction); });
    field(t, key, "motion", [&](auto& n, auto& k) { c.motion = read_motion(table(n, k), k); });
    field(t, key, "scale", [&](auto& n, auto& k) { c.scale = number(n, k); });
    field(t, key, "resolution", [&](auto& n, auto& k) { c.sdf_resolution = small_integer(n, k); });
    field(t, key, "file", [&](auto& n, auto& k) { c.file = text(n, k); });
    if (c.kind == ColliderKind::mesh) read_collider_mesh(t, key, c);
    return c;
  }

  // A top-level table: its place noted for messages and its keys checked.
  const toml::table& section(const toml::node& node, const std::string& key, Names keys) {
    note(key, node);
    const toml::table& t = table(node, key);
    check_keys(t, key, keys);
    return t;
  }

  // A number that must lie in [lo, hi]; `unit` follows the bounds in the message (" s", " BPM").
  double number_within(const toml::node& n, const std::string& k, double lo, double hi,
                       const std::string& unit = "") const {
    const double value = number(n, k);
    if (value < lo || value > hi)
      fail(k, n,
           "must be between " + format_number(lo) + " and " + format_number(hi) + unit + " (got " +
               format_number(value) + ")");
    return value;
  }

  // A file named in the scene: relative paths are relative to the scene file's folder.
  std::string scene_relative(const std::string& file) const {
    std::filesystem::path path(file);
    if (path.is_relative() && scene_.file != "<string>")
      path = std::filesystem::path(scene_.file).parent_path() / path;
    return path.string();
  }

  // A number is both coefficients; a table names them.
  void read_friction(const toml::node& n, const std::string& k, double& static_friction,
                     double& kinetic_friction) {
    if (n.is_table()) {
      const toml::table& f = table(n, k);
      check_keys(f, k, kFrictionKeys);
      field(f, k, "static", [&](auto& m, auto& q) { static_friction = number(m, q); });
      field(f, k, "kinetic", [&](auto& m, auto& q) { kinetic_friction = number(m, q); });
    } else {
      static_friction = kinetic_friction = number(n, k);
    }
  }

  // [music]: the file is read and analysed now (or the drum track generated), so a missing or
  // unreadable file is a scene error naming the key.
  void read_music(const toml::node& node) {
    const std::string key = "music";
    const toml::table& t = section(node, key, kMusicKeys);
    MusicSpec m;
    field(t, key, "file", [&](auto& n, auto& k) { m.file = text(n, k); });
    field(t, key, "tempo",
          [&](auto& n, auto& k) { m.tempo = number_within(n, k, 40.0, 240.0, " BPM"); });
    field(t, key, "seconds",
          [&](auto& n, auto& k) { m.seconds = number_within(n, k, 1.0, 3600.0, " s"); });
    if (m.file.empty()) {
      m.track = std::make_shared<const MusicTrack>(generated_music(m.tempo, m.seconds));
    } else {
      const std::string path = scene_relative(m.file);
      try {
        m.track = std::make_shared<const MusicTrack>(load_music(path));
      } catch (const AudioError& e) {
        fail(key + ".file", *t.get("file"), e.what());
      }
      if (m.track->analysis.beats.size() < 2)
        fail(key + ".file", *t.get("file"), path + ": no beat found in the music");
    }
    scene_.music = std::move(m);
  }

  // [mannequin]: the dance is built now (on the music's beats, or a steady 120 BPM) and each of
  // the figure's primitives appended to the colliders as "mannequin.<part>".
  void read_mannequin(const toml::node& node) {
    const std::string key = "mannequin";
    const toml::table& t = section(node, key, kMannequinKeys);
    MannequinSpec m;
    field(t, key, "position", [&](auto& n, auto& k) { m.position = numbers<3>(n, k); });
    field(t, key, "facing", [&](auto& n, auto& k) { m.facing = number(n, k); });
    field(t, key, "settle",
          [&](auto& n, auto& k) { m.settle = number_within(n, k, 0.0, 60.0, " s"); });
    field(t, key, "blend_beats", [&](auto& n, auto& k) {
      m.blend_beats = small_integer(n, k);
      if (m.blend_beats < 1 || m.blend_beats > 64)
        fail(k, n, "must be between 1 and 64 (got " + std::to_string(m.blend_beats) + ")");
    });
    field(t, key, "amplitude",
          [&](auto& n, auto& k) { m.amplitude = number_within(n, k, 0.0, 1.5); });
    field(t, key, "friction",
          [&](auto& n, auto& k) { read_friction(n, k, m.static_friction, m.kinetic_friction); });
    field(t, key, "thickness", [&](auto& n, auto& k) { m.thickness = number(n, k); });

    DanceSpec dance;
    dance.settle_seconds = m.settle;
    dance.blend_beats = m.blend_beats;
    dance.amplitude = m.amplitude;
    std::vector<double> beats = constant_tempo_beats(120.0, 3600.0), amplitude;
    if (scene_.music) {
      beats = scene_.music->track->analysis.beats;
      amplitude = beat_amplitudes(scene_.music->track->analysis);
    }
    try {
      m.motion = std::make_shared<const BodyMotion>(
          Dance(make_mannequin(), dance, std::move(beats), std::move(amplitude)),
          Eigen::Vector3d(m.position[0], m.position[1], m.position[2]), m.facing);
    } catch (const std::invalid_argument& e) {
      fail(key, node, e.what());
    }
    const auto& parts = m.motion->dance().primitives();
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const BodyPrimitive& p = parts[i];
      ColliderSpec c;
      c.kind = p.shape == BodyShape::sphere ? ColliderKind::sphere
               : p.shape == BodyShape::box  ? ColliderKind::box
                                            : ColliderKind::capsule;
      c.radius = p.shape == BodyShape::box ? 0.1 : p.radius;
      for (int a = 0; a < 3; ++a)
        c.half_extents[a] = p.shape == BodyShape::box ? p.half_extents[a] : 0.1;
      c.a = {0.0, -p.half_length, 0.0};
      c.b = {0.0, p.half_length, 0.0};
      c.static_friction = m.static_friction;
      c.kinetic_friction = m.kinetic_friction;
      c.thickness = m.thickness;
      c.body = m.motion;
      c.body_part = static_cast<int>(i);
      c.key = key + "." + p.name;
      scene_.colliders.push_back(std::move(c));
    }
    scene_.mannequin = std::move(m);
  }

  // pins_follow = "pelvis": the mannequin part's collider, once the mannequin has been read.
  void resolve_follow_names() {
    for (ClothSpec& cloth : scene_.cloths) {
      if (cloth.pins_follow_name.empty()) continue;
      const std::string k = cloth.key + ".pins_follow";
      const toml::node& n = *follow_nodes_.at(k);
      if (!scene_.mannequin)
        fail(k, n,
             "names a mannequin part (\"" + cloth.pins_follow_name +
                 "\"), but the scene has no [mannequin]");
      std::string parts;
      for (std::size_t c = 0; c < scene_.colliders.size(); ++c) {
        const ColliderSpec& spec = scene_.colliders[c];
        if (!spec.body) continue;
        const std::string part = spec.key.substr(std::string("mannequin.").size());
        if (part == cloth.pins_follow_name) cloth.pins_follow = static_cast<int>(c);
        parts += (parts.empty() ? "" : ", ") + part;
      }
      if (!cloth.pins_follow)
        fail(k, n, "no mannequin part \"" + cloth.pins_follow_name + "\" (parts: " + parts + ")");
    }
  }

  void read_collider_mesh(const toml::table& t, const std::string& key, ColliderSpec& c) {
    if (c.file.empty())
      fail(key + ".file", t, "missing (a mesh collider needs file = \"thing.obj\")");
    c.mesh = std::make_shared<const TriangleMesh>(read_obj(t, key, c.file, c.scale));
  }

  ColliderMotion read_motion(const toml::table& t, const std::string& key) {
    check_keys(t, key, kMotionKeys);
    ColliderMotion m;
    field(t, key, "velocity", [&](auto& n, auto& k) { m.velocity = numbers<3>(n, k); });
    field(t, key, "angular_velocity",
          [&](auto& n, auto& k) { m.angular_velocity = numbers<3>(n, k); });
    field(t, key, "keys", [&](auto& n, auto& k) {
      const toml::array& a = array(n, k, std::nullopt, " of tables ({ time, offset, rotation })");
      for (std::size_t i = 0; i < a.size(); ++i) {
        const std::string kk = k + "[" + std::to_string(i) + "]";
        note(kk, *a.get(i));
        const toml::table& kt = table(*a.get(i), kk);
        check_keys(kt, kk, kKeyframeKeys);
        ColliderKey frame;
        if (!kt.contains("time"))
          fail(kk + ".time", kt, "missing (a keyframe needs its time in s)");
        field(kt, kk, "time", [&](auto& q, auto& qk) { frame.time = number(q, qk); });
        field(kt, kk, "offset", [&](auto& q, auto& qk) { frame.offset = numbers<3>(q, qk); });
        field(kt, kk, "rotation", [&](auto& q, auto& qk) { frame.rotation = numbers<3>(q, qk); });
        m.keys.push_back(frame);
      }
    });
    return m;
  }

  void read_look(const toml::table& t, const std::string& key, ClothLookSpec& look) {
    check_keys(t, key, kLookKeys);
    field(t, key, "roughness", [&](auto& n, auto& k) { look.roughness = number(n, k); });
    field(t, key, "sheen", [&](auto& n, auto& k) { look.sheen = number(n, k); });
    field(t, key, "sheen_roughness",
          [&](auto& n, auto& k) { look.sheen_roughness = number(n, k); });
    field(t, key, "threads", [&](auto& n, auto& k) {
      look.threads = choice(n, k, kThreadMetalNames, "thread metal");
    });
    field(t, key, "thread_fraction",
          [&](auto& n, auto& k) { look.thread_fraction = number(n, k); });
    field(t, key, "opacity", [&](auto& n, auto& k) { look.opacity = number(n, k); });
    field(t, key, "transmission", [&](auto& n, auto& k) { look.transmission = number(n, k); });
    field(t, key, "bump", [&](auto& n, auto& k) { look.bump = number(n, k); });
    field(t, key, "subsurface", [&](auto& n, auto& k) { look.subsurface = number(n, k); });
    field(t, key, "glints", [&](auto& n, auto& k) { look.glints = boolean(n, k); });
    field(t, key, "color", [&](auto& n, auto& k) { look.color = numbers<3>(n, k); });
  }

  const OverrideOrigins& origins_;
  Scene& scene_;
  std::map<std::string, const toml::node*> follow_nodes_;  // pins_follow names, for messages
};

}  // namespace

Scene parse_scene_string(std::string_view toml_text, const std::string& name,
                         const std::vector<std::string>& overrides) {
  toml::table root;
  try {
    root = toml::parse(toml_text, name);
  } catch (const toml::parse_error& error) {
    const toml::source_position at = error.source().begin;
    throw SceneError(SourceLoc{name, static_cast<int>(at.line), static_cast<int>(at.column)}, "",
                     "TOML syntax error: " + std::string(error.description()));
  }
  OverrideOrigins origins;
  apply_overrides(root, overrides, origins);

  Scene scene;
  scene.file = name;
  Reader(origins, scene).read(root);
  validate_scene(scene);
  return scene;
}

Scene parse_scene_file(const std::string& path, const std::vector<std::string>& overrides) {
  const SourceLoc loc{path, 0, 0};
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw SceneError(loc, "", "is a directory, not a scene file");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw SceneError(loc, "", std::string("cannot open scene file (") + std::strerror(errno) + ")");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw SceneError(loc, "", "cannot read scene file");
  return parse_scene_string(text.str(), path, overrides);
}

}  // namespace clothlab
