// The parameter table (sim/scene/parameters.hpp): the key table in docs/scene-format.md is its
// output; every bounded range is enforced with the record's key; every documented default is the
// struct's; the parser accepts exactly the table's keys.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sim/scene/parameter_keys.hpp"
#include "sim/scene/parameters.hpp"
#include "sim/scene/scene_parser.hpp"

namespace clothlab {
namespace {

// One cloth, one sphere collider and one scenery sphere, so that every table has an instance.
const std::string kBase =
    "[cloth]\nresolution = [4, 4]\npins = [[0, 0]]\n"
    "[[colliders]]\ntype = \"sphere\"\n"
    "[render]\n[[render.meshes]]\ntype = \"sphere\"\n"
    "[forces.wind]\nvelocity = [1, 0, 0]\n";

// The key path of p's value in kBase: array tables take their first element.
std::string instance_path(const Parameter& p) {
  std::string path = parameter_path(p);
  for (const char* table : {"colliders", "render.meshes"}) {
    const std::string prefix = std::string(table) + ".";
    if (path.rfind(prefix, 0) == 0) path = std::string(table) + "[0]." + path.substr(prefix.size());
  }
  return path;
}

bool in_array_of_keyframes(const Parameter& p) {
  return p.section == Section::keyframe;
}

std::string read_table_file(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(ParameterTable, DocsKeyTableIsTheGeneratedOne) {
  const std::string doc = read_table_file(CLOTHLAB_SOURCE_DIR "/docs/scene-format.md");
  const std::string begin = "<!-- clothlab params: begin -->\n";
  const std::string end = "<!-- clothlab params: end -->";
  const auto from = doc.find(begin);
  const auto to = doc.find(end);
  ASSERT_NE(from, std::string::npos) << "docs/scene-format.md has no generated key table";
  ASSERT_NE(to, std::string::npos);
  EXPECT_EQ(doc.substr(from + begin.size(), to - from - begin.size()), parameters_markdown())
      << "regenerate it: scripts/params-table";
}

TEST(ParameterTable, EveryKeyIsOnceInItsSection) {
  for (const Parameter& p : parameters()) {
    EXPECT_EQ(find_parameter(p.section, p.name), &p) << parameter_path(p) << " is listed twice";
    EXPECT_TRUE(p.read || p.section == Section::friction) << parameter_path(p) << " has no reader";
  }
  EXPECT_GT(parameters().size(), 120u);
}

TEST(ParameterTable, KeyOfNamesTheMember) {
  EXPECT_EQ(key_of<&SolverSpec::cg_tolerance>(), "cg_tolerance");
  EXPECT_EQ(key_of<&ClothSpec::pins_follow>(), "pins_follow");
  EXPECT_EQ(key_of<&ColliderSpec::sdf_resolution>(), "resolution");
  EXPECT_EQ(section_path(Section::keyframe), "colliders.motion.keys");
  EXPECT_EQ(section_path(Section::look), "render.cloth");
  EXPECT_EQ(section_path(Section::friction), "colliders.friction");
}

TEST(ParameterTable, UnknownKeysListTheSectionsKeys) {
  try {
    parse_scene_string(kBase + "[solver]\ncg_tolerence = 1e-3\n", "t.toml");
    FAIL() << "an unknown key was accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.key, "solver.cg_tolerence");
    EXPECT_NE(e.detail.find(key_list(Section::solver)), std::string::npos) << e.what();
  }
}

// A value just outside p's range (for integers, an integer).
std::string outside(const Parameter& p) {
  const Range& r = p.range;
  const bool integral = p.kind == ValueKind::integer || p.kind == ValueKind::integers ||
                        p.form.starts_with("an integer");
  double x = r.lo != -Range::kInf
                 ? (r.lo_open ? r.lo : r.lo - (integral ? 1.0 : 0.5 * (1.0 + std::abs(r.lo))))
                 : (r.hi_open ? r.hi : r.hi + 1.0);
  std::string one = format_number(x);
  if (!integral && one.find_first_not_of("-0123456789") == std::string::npos) one += ".0";
  if (p.count == 1) return one;
  std::string many = "[";
  for (int n = 0; n < p.count; ++n) many += (n ? ", " : "") + one;
  return many + "]";
}

TEST(ParameterTable, EveryBoundedRangeIsEnforcedWithItsKey) {
  int checked = 0;
  for (const Parameter& p : parameters()) {
    if (!p.values || !p.range.bounded() || in_array_of_keyframes(p)) continue;
    const std::string path = instance_path(p);
    const std::string expected = path + (p.count > 1 && !p.whole_key ? "[0]" : "");
    const std::string set = path + "=" + outside(p);
    try {
      parse_scene_string(kBase, "t.toml", {set});
      ADD_FAILURE() << "--set " << set << " was accepted";
    } catch (const SceneError& e) {
      EXPECT_EQ(e.key, expected) << e.what();
      EXPECT_NE(e.detail.find("must be"), std::string::npos) << e.what();
    }
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

// Where the default is written as a value, writing it gives the struct's own default.
TEST(ParameterTable, DocumentedDefaultsAreTheStructDefaults) {
  const Scene base = parse_scene_string(kBase, "t.toml");
  int checked = 0;
  for (const Parameter& p : parameters()) {
    if (!p.values || p.fallback.empty() || in_array_of_keyframes(p)) continue;
    const char first = p.fallback.front();
    if (!(first == '-' || first == '[' || (first >= '0' && first <= '9'))) continue;
    if (p.section == Section::music || p.section == Section::mannequin) continue;  // not in kBase
    if (p.section == Section::trace) continue;                                     // nor this
    if (base.locations.count(instance_path(p))) continue;                          // kBase sets it
    // A tube's keys on kBase's grid are an error of their own.
    if (p.section == Section::cloth && (p.name == "radius" || p.name == "length")) continue;
    const std::string set = instance_path(p) + "=" + std::string(p.fallback);
    const Scene written = parse_scene_string(kBase, "t.toml", {set});
    // The same record on the same instance in both scenes.
    auto object = [&](const Scene& s) -> const void* {
      switch (p.section) {
        case Section::cloth:
          return &s.cloths[0];
        case Section::springs:
          return &s.springs;
        case Section::forces:
          return &s.forces;
        case Section::wind:
          return &s.forces.wind;
        case Section::solver:
          return &s.solver;
        case Section::render:
          return &s.render;
        case Section::light:
          return &s.render.light;
        case Section::sky:
          return &s.render.sky;
        case Section::pole:
          return &s.render.pole;
        case Section::mesh:
          return &s.render.meshes[0];
        case Section::look:
          return &s.render.cloth;
        case Section::camera:
          return &s.render.camera;
        case Section::collider:
        case Section::friction:
          return &s.colliders[0];
        case Section::motion:
          return &s.colliders[0].motion;
        default:
          return nullptr;
      }
    };
    ASSERT_NE(object(base), nullptr) << parameter_path(p);
    double a[3], b[3];
    const int n = p.values(object(base), a);
    ASSERT_EQ(p.values(object(written), b), n) << set;
    for (int e = 0; e < n; ++e) EXPECT_EQ(a[e], b[e]) << set;
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

}  // namespace
}  // namespace clothlab
