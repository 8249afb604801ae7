#include "sim/scene/special_values.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "sim/scene/name_list.hpp"
#include "sim/scene/spring_presets.hpp"
#include "sim/scene/trace_fields.hpp"

// GCC 12 at -O3 reports a false -Wrestrict inside std::string for `"text" + std::string(...)`
// (GCC bug 105329); the message texts below are built that way throughout.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ == 12
#pragma GCC diagnostic ignored "-Wrestrict"
#endif

namespace clothlab::special {
namespace {

// One number is both coefficients; a table names them (Section::friction's records, static
// first, then kinetic).
void read_friction(TomlReader& in, double& static_friction, double& kinetic_friction) {
  const toml::node& n = in.node();
  const std::string& k = in.key();
  if (!n.is_table()) {
    static_friction = kinetic_friction = in.number(n, k);
    return;
  }
  const toml::table& t = in.table(n, k);
  in.check_keys(t, k, Section::friction);
  double* out[] = {&static_friction, &kinetic_friction};
  int index = 0;
  for (const Parameter& p : parameters()) {
    if (p.section != Section::friction) continue;
    if (const toml::node* value = t.get(p.name)) {
      const std::string key = join_key(k, p.name);
      in.note(key, *value);
      *out[index] = in.number(*value, key);
    }
    ++index;
  }
}

}  // namespace

void read_cloths(TomlReader& in, void* object) {
  Scene& scene = *static_cast<Scene*>(object);
  const toml::node& node = in.node();
  if (const toml::table* one = node.as_table()) {
    scene.multi_cloth = false;
    ClothSpec cloth;
    cloth.key = in.key();
    in.read_section(*one, cloth.key, Section::cloth, &cloth);
    scene.cloths.push_back(std::move(cloth));
    return;
  }
  const toml::array& many = in.array(node, in.key(), std::nullopt, " of tables ([[cloth]])");
  if (many.empty()) in.fail(in.key(), node, "the scene has no cloth; [[cloth]] list is empty");
  scene.multi_cloth = true;
  in.read_tables(node, in.key(), " of tables ([[cloth]])", Section::cloth, scene.cloths);
}

void read_trace(TomlReader& in, void* object) {
  Scene& scene = *static_cast<Scene*>(object);
  scene.trace.emplace();
  in.read_section(in.table(in.node(), in.key()), in.key(), Section::trace, &*scene.trace);
}

void read_music(TomlReader& in, void* object) {
  Scene& scene = *static_cast<Scene*>(object);
  scene.music.emplace();
  in.read_section(in.table(in.node(), in.key()), in.key(), Section::music, &*scene.music);
}

void read_mannequin(TomlReader& in, void* object) {
  Scene& scene = *static_cast<Scene*>(object);
  scene.mannequin.emplace();
  in.read_section(in.table(in.node(), in.key()), in.key(), Section::mannequin, &*scene.mannequin);
}

// [i, j] pairs on a grid or tube; on a mesh cloth OBJ vertex numbers (1 = the file's first v
// line, as its f lines count), kept as (number - 1, 0). The shape is read before the pins.
void read_pins(TomlReader& in, void* object) {
  ClothSpec& cloth = *static_cast<ClothSpec*>(object);
  const bool mesh = cloth.shape == "mesh";
  const toml::array& a = in.array(in.node(), in.key(), std::nullopt,
                                  mesh ? " of OBJ vertex numbers" : " of [i, j] pairs");
  cloth.pins.clear();
  for (std::size_t n = 0; n < a.size(); ++n) {
    const std::string k = in.key() + "[" + std::to_string(n) + "]";
    in.note(k, *a.get(n));
    if (mesh) {
      // Refused here, before number - 1 could overflow (the fuzz pass's -2147483648).
      const int number = in.small_integer(*a.get(n), k);
      if (number < 1)
        in.fail(
            k, *a.get(n),
            "pin " + std::to_string(number) + " is not an OBJ vertex number (they count from 1)");
      cloth.pins.push_back({number - 1, 0});
    } else {
      const std::vector<int> ij = in.index_tuple(*a.get(n), k, 2, 2, "an [i, j] pair of integers");
      cloth.pins.push_back({ij[0], ij[1]});
    }
  }
}

// One radius (a cylinder) or [first ring, last ring] (a frustum).
void read_radius(TomlReader& in, void* object) {
  ClothSpec& cloth = *static_cast<ClothSpec*>(object);
  if (in.node().is_array()) {
    cloth.radius = in.numbers<2>(in.node(), in.key());
  } else {
    const double r = in.number(in.node(), in.key());
    cloth.radius = {r, r};
  }
}

int radius_values(const void* object, double* out) {
  const ClothSpec& cloth = *static_cast<const ClothSpec*>(object);
  out[0] = cloth.radius[0];
  out[1] = cloth.radius[1];
  return 2;
}

// A collider's index, or a mannequin part's name (resolved once the mannequin is read); or an
// array of them.
void read_pins_follow(TomlReader& in, void* object) {
  ClothSpec& cloth = *static_cast<ClothSpec*>(object);
  const auto one = [&](const toml::node& node, const std::string& key) {
    if (node.is_string()) {
      cloth.pins_follow_names.push_back(in.text(node, key));
      cloth.pins_follow.push_back(-1);
    } else {
      cloth.pins_follow_names.emplace_back();
      cloth.pins_follow.push_back(in.small_integer(node, key));
    }
  };
  const toml::array* list = in.node().as_array();
  if (!list) return one(in.node(), in.key());
  if (list->empty()) in.fail(in.key(), in.node(), "name at least one collider");
  for (std::size_t n = 0; n < list->size(); ++n)
    one(*list->get(n), in.key() + "[" + std::to_string(n) + "]");
}

// A cloth's own springs start from the top-level [springs], so they need name only what
// differs (the top level is read before the cloths).
void read_cloth_springs(TomlReader& in, void* object) {
  ClothSpec& cloth = *static_cast<ClothSpec*>(object);
  SpringSpec springs = in.scene().springs;
  in.read_section(in.table(in.node(), in.key()), in.key(), Section::springs, &springs);
  cloth.springs = springs;
}

std::string_view spring_preset_names() {
  static const std::string names =
      comma_list(spring_presets(), [](const SpringPreset& p) { return p.name; });
  return names;
}

void read_spring_preset(TomlReader& in, void* object) {
  const std::string name = in.text(in.node(), in.key());
  const std::optional<SpringPreset> preset = find_spring_preset(name);
  if (!preset)
    in.fail(in.key(), in.node(),
            "unknown preset \"" + name + "\" (valid: " + std::string(spring_preset_names()) + ")");
  apply_spring_preset(*preset, *static_cast<SpringSpec*>(object));
}

// -1 (no entry shown) when no preset was applied.
int spring_preset_index(const void* object) {
  const std::string& name = static_cast<const SpringSpec*>(object)->preset;
  const auto presets = spring_presets();
  for (std::size_t i = 0; i < presets.size(); ++i)
    if (presets[i].name == name) return static_cast<int>(i);
  return -1;
}

void choose_spring_preset(void* object, int index) {
  apply_spring_preset(spring_presets()[static_cast<std::size_t>(index)],
                      *static_cast<SpringSpec*>(object));
}

std::string_view integrator_names() {
  static const std::string names =
      comma_list(kAllIntegrators, [](IntegratorKind k) { return std::string_view(to_string(k)); });
  return names;
}

void read_integrator(TomlReader& in, void* object) {
  const std::string name = in.text(in.node(), in.key());
  const std::optional<IntegratorKind> kind = integrator_from_string(name);
  if (!kind)
    in.fail(in.key(), in.node(),
            "unknown integrator \"" + name + "\" (valid: " + std::string(integrator_names()) + ")");
  static_cast<SolverSpec*>(object)->integrator = *kind;
}

int integrator_index(const void* object) {
  return static_cast<int>(static_cast<const SolverSpec*>(object)->integrator);
}

void choose_integrator(void* object, int index) {
  static_cast<SolverSpec*>(object)->integrator = kAllIntegrators[index];
}

void read_dt(TomlReader& in, void* object) {
  SolverSpec& s = *static_cast<SolverSpec*>(object);
  if (in.node().is_string()) {
    if (in.text(in.node(), in.key()) != "auto")
      in.fail(in.key(), in.node(),
              "expected a number of seconds or \"auto\", got " + describe(in.node()));
    s.dt_auto = true;
  } else {
    s.dt = in.number(in.node(), in.key());
    s.dt_auto = false;
  }
}

// dt has an upper bound even when automatic (the fixed value is kept but unused then; checked
// only for its upper bound as before).
int dt_values(const void* object, double* out) {
  const SolverSpec& s = *static_cast<const SolverSpec*>(object);
  if (s.dt_auto) return 0;
  out[0] = s.dt;
  return 1;
}

void read_substeps(TomlReader& in, void* object) {
  SolverSpec& s = *static_cast<SolverSpec*>(object);
  if (in.node().is_string()) {
    if (in.text(in.node(), in.key()) != "auto")
      in.fail(in.key(), in.node(), "expected an integer or \"auto\", got " + describe(in.node()));
    s.substeps = 0;
    return;
  }
  const std::int64_t n = in.integer(in.node(), in.key());
  // 0 is how "auto" is stored, so a count below 1 is refused here; the range names the top.
  if (n < 1)
    in.fail(in.key(), in.node(), "must be at least 1, or \"auto\" (got " + std::to_string(n) + ")");
  s.substeps = static_cast<int>(std::min<std::int64_t>(n, 1 << 30));
}

int substeps_values(const void* object, double* out) {
  const SolverSpec& s = *static_cast<const SolverSpec*>(object);
  if (s.substeps == 0) return 0;
  out[0] = s.substeps;
  return 1;
}

void read_seed(TomlReader& in, void* object) {
  const std::int64_t seed = in.integer(in.node(), in.key());
  if (seed < 0) in.fail(in.key(), in.node(), "must be >= 0 (got " + std::to_string(seed) + ")");
  static_cast<WindSpec*>(object)->seed = static_cast<std::uint64_t>(seed);
}

void read_collider_friction(TomlReader& in, void* object) {
  ColliderSpec& c = *static_cast<ColliderSpec*>(object);
  read_friction(in, c.static_friction, c.kinetic_friction);
}

void read_mannequin_friction(TomlReader& in, void* object) {
  MannequinSpec& m = *static_cast<MannequinSpec*>(object);
  read_friction(in, m.static_friction, m.kinetic_friction);
}

int static_friction_values(const void* object, double* out) {
  out[0] = static_cast<const ColliderSpec*>(object)->static_friction;
  return 1;
}

int kinetic_friction_values(const void* object, double* out) {
  out[0] = static_cast<const ColliderSpec*>(object)->kinetic_friction;
  return 1;
}

// [i, j] names a vertex of cloth 0; [c, i, j] one of cloth c (the multi-cloth form).
void read_trace_vertices(TomlReader& in, void* object) {
  TraceSpec& trace = *static_cast<TraceSpec*>(object);
  const bool multi = in.scene().multi_cloth;
  const std::string form = multi ? "[c, i, j] or [i, j]" : "[i, j]";
  const toml::array& a = in.array(in.node(), in.key(), std::nullopt, " of " + form + " vertices");
  trace.vertices.clear();
  for (std::size_t n = 0; n < a.size(); ++n) {
    const std::string k = in.key() + "[" + std::to_string(n) + "]";
    in.note(k, *a.get(n));
    const std::vector<int> v =
        in.index_tuple(*a.get(n), k, 2, multi ? 3 : 2, form + " of integers");
    trace.vertices.push_back(v.size() == 2 ? TraceVertex{0, v[0], v[1]}
                                           : TraceVertex{v[0], v[1], v[2]});
  }
}

void read_trace_fields(TomlReader& in, void* object) {
  TraceSpec& trace = *static_cast<TraceSpec*>(object);
  const toml::array& a = in.array(in.node(), in.key(), std::nullopt, " of field names");
  if (a.empty()) in.fail(in.key(), in.node(), "name at least one of " + trace_field_list());
  trace.position = trace.velocity = trace.force = trace.energy = false;
  for (std::size_t n = 0; n < a.size(); ++n) {
    const std::string k = in.key() + "[" + std::to_string(n) + "]";
    const std::string name = in.text(*a.get(n), k);
    bool* flag = trace_field(trace, name);
    if (!flag)
      in.fail(k, *a.get(n), "unknown field \"" + name + "\" (valid: " + trace_field_list() + ")");
    if (*flag) in.fail(k, *a.get(n), "field \"" + name + "\" is listed twice");
    *flag = true;
  }
}

}  // namespace clothlab::special
