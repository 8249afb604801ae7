// Scene parser and validator: the default scene, each class of bad input, --set overrides and the
// multi-cloth form. Every error must be a SceneError that names the key (and, for file errors,
// the file and line).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "load/scene_load.hpp"
#include "sim/mesh/triangle_mesh.hpp"
#include "sim/scene/scene_parser.hpp"

namespace clothlab {
namespace {

const std::string kDefaultScene = std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/default.toml";

// A small valid one-cloth scene; tests append or replace lines to break it.
const std::string kMinimal = R"(
[cloth]
size = [1.0, 1.0]
resolution = [4, 3]
pins = [[0, 0]]

[solver]
dt = 0.001
)";

// Parses text and returns the SceneError it must throw.
SceneError parse_error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    read_scene_string(text, "t.toml", overrides);
  } catch (const SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "no SceneError for:\n" << text;
  return SceneError({}, "", "");
}

// Expects an error for key at line (0: do not check the line) whose message contains `words`.
void expect_error(const std::string& text, const std::string& key, int line,
                  const std::string& words = "", const std::vector<std::string>& overrides = {}) {
  const SceneError e = parse_error_of(text, overrides);
  const std::string what = e.what();
  EXPECT_EQ(e.key, key) << what;
  EXPECT_NE(what.find(key), std::string::npos) << what;
  EXPECT_NE(what.find(words), std::string::npos) << what;
  if (line > 0) {
    EXPECT_EQ(e.loc.file, "t.toml") << what;
    EXPECT_EQ(e.loc.line, line) << what;
    EXPECT_EQ(what.rfind("t.toml:" + std::to_string(line) + ":", 0), 0u) << what;
  }
}

TEST(SceneParser, DefaultSceneHasDocumentedValues) {
  const Scene s = read_scene_file(kDefaultScene);
  EXPECT_EQ(s.file, kDefaultScene);
  ASSERT_EQ(s.cloths.size(), 1u);
  EXPECT_FALSE(s.multi_cloth);
  const ClothSpec& c = s.cloths[0];
  EXPECT_EQ(c.key, "cloth");
  EXPECT_EQ(c.shape, "grid");
  EXPECT_EQ(c.size, (std::array<double, 2>{2.0, 2.0}));
  EXPECT_EQ(c.resolution, (std::array<int, 2>{32, 32}));
  EXPECT_EQ(c.origin, (Vec3d{-1.0, 2.5, 0.0}));
  EXPECT_EQ(c.u_axis, (Vec3d{1, 0, 0}));
  EXPECT_EQ(c.v_axis, (Vec3d{0, -1, 0}));
  EXPECT_EQ(c.mass, 1.0);
  EXPECT_EQ(c.pins, (std::vector<std::array<int, 2>>{{0, 0}, {31, 0}}));
  EXPECT_FALSE(c.springs.has_value());
  EXPECT_EQ(s.springs.rule, "seed");
  EXPECT_EQ(s.springs.stiffness, 800.0);
  EXPECT_EQ(s.springs.damping, 0.05);
  EXPECT_EQ(&s.springs_of(0), &s.springs);
  EXPECT_EQ(s.forces.gravity, (Vec3d{0, -9.81, 0}));
  EXPECT_EQ(s.forces.drag, 0.001);
  EXPECT_TRUE(s.forces.wind.enabled);
  EXPECT_EQ(s.forces.wind.velocity, (Vec3d{3, 0, 1}));
  EXPECT_EQ(s.forces.wind.gust, 0.5);
  EXPECT_EQ(s.forces.wind.seed, 7u);
  EXPECT_EQ(s.forces.wind.gust_period, 1.0);
  EXPECT_EQ(s.forces.wind.coefficient, 1.0);
  EXPECT_EQ(s.solver.integrator, IntegratorKind::symplectic_euler);
  EXPECT_TRUE(s.solver.dt_auto);
  EXPECT_EQ(s.solver.threads, 0);
  EXPECT_EQ(s.solver.precision, Precision::f32);
  ASSERT_TRUE(s.trace.has_value());
  ASSERT_EQ(s.trace->vertices.size(), 1u);
  EXPECT_EQ(s.trace->vertices[0].cloth, 0);
  EXPECT_EQ(s.trace->vertices[0].i, 16);
  EXPECT_EQ(s.trace->vertices[0].j, 31);
  EXPECT_TRUE(s.trace->position && s.trace->velocity && s.trace->force && s.trace->energy);
  EXPECT_EQ(s.trace->every, 20);
}

TEST(SceneParser, RecordsSourceLocations) {
  const Scene s = read_scene_file(kDefaultScene);
  const SourceLoc& dt = s.locations.at("solver.dt");
  EXPECT_EQ(dt.file, kDefaultScene);
  EXPECT_GT(dt.line, 0);
  EXPECT_GT(dt.column, 0);
  EXPECT_GT(s.locations.at("solver.dt").line, s.locations.at("cloth.pins").line);
  EXPECT_EQ(s.locations.at("cloth.pins[1]").line, s.locations.at("cloth.pins").line);
  for (const char* key : {"cloth.size", "cloth.resolution", "cloth.mass", "springs.preset",
                          "forces.wind", "forces.wind.seed", "trace.vertices", "trace.every"})
    EXPECT_TRUE(s.locations.count(key)) << key;

  const Scene m = read_scene_string(kMinimal, "t.toml");
  EXPECT_EQ(m.locations.at("cloth.resolution").line, 4);
  EXPECT_EQ(m.locations.at("cloth.resolution").column, 14);  // the value, after "resolution = "
  EXPECT_EQ(m.locations.at("solver.dt").line, 8);
}

TEST(SceneParser, OmittedKeysTakeDefaults) {
  const Scene s = read_scene_string("[cloth]\npins = [[0, 0]]\n", "t.toml");
  EXPECT_EQ(s.cloths[0].resolution, (std::array<int, 2>{32, 32}));
  EXPECT_FALSE(s.forces.wind.enabled);
  EXPECT_FALSE(s.trace.has_value());
  EXPECT_EQ(s.solver.integrator, IntegratorKind::symplectic_euler);
  // A wind table needs only velocity.
  const Scene w = read_scene_string(kMinimal + "[forces]\nwind = { velocity = [1, 2, 3] }\n", "t");
  EXPECT_TRUE(w.forces.wind.enabled);
  EXPECT_EQ(w.forces.wind.gust, 0.0);
  EXPECT_EQ(w.forces.wind.seed, 0u);
  // Integers are fine where floats are meant.
  EXPECT_EQ(read_scene_string(kMinimal + "[springs]\nstiffness = 5\n", "t").springs.stiffness, 5.0);
}

TEST(SceneParser, IntegratorNamesRoundTrip) {
  for (const char* name : {"explicit_euler", "symplectic_euler", "seed_hack", "verlet", "rk4"}) {
    const auto kind = integrator_from_string(name);
    ASSERT_TRUE(kind.has_value()) << name;
    EXPECT_STREQ(to_string(*kind), name);
  }
  EXPECT_FALSE(integrator_from_string("RK4").has_value());
  EXPECT_FALSE(integrator_from_string("").has_value());
}

TEST(SceneParser, WrongTypes) {
  expect_error(kMinimal + "[springs]\nstiffness = \"stiff\"\n", "springs.stiffness", 10,
               "expected a number, got string");
  expect_error(kMinimal + "[forces]\ndrag = true\n", "forces.drag", 10, "expected a number");
  // Floats are not integers: a resolution of 4.0 is refused, naming the element.
  expect_error("[cloth]\nresolution = [4.0, 3]\n", "cloth.resolution[0]", 2,
               "expected an integer, got float 4");
  expect_error(kMinimal + "[trace]\nevery = 2.5\n", "trace.every", 10, "expected an integer");
  expect_error("[cloth]\nsize = [1.0, 1.0, 1.0]\n", "cloth.size", 2, "expected 2 elements");
  expect_error("[cloth]\norigin = 3\n", "cloth.origin", 2, "expected an array");
  expect_error(kMinimal + "[forces]\nwind = 3\n", "forces.wind", 10, "expected a table");
  expect_error("[cloth]\npins = [[0, 0, 0]]\n", "cloth.pins[0]", 2, "[i, j]");
  expect_error("[cloth]\npins = [[0, 0.5]]\n", "cloth.pins[0][1]", 2, "expected an integer");
  expect_error("solver = 3\n[cloth]\n", "solver", 1, "expected a table");
  expect_error(kMinimal + "[trace]\nfields = [1]\n", "trace.fields[0]", 10, "expected a string");
}

TEST(SceneParser, NonFiniteNumbers) {
  expect_error(kMinimal + "[springs]\nstiffness = inf\n", "springs.stiffness", 10,
               "must be finite (got inf)");
  expect_error(kMinimal + "[forces]\ngravity = [0, nan, 0]\n", "forces.gravity[1]", 10,
               "must be finite");
  expect_error("[cloth]\nmass = -inf\n", "cloth.mass", 2, "must be finite");
  expect_error(kMinimal + "[forces]\nwind = { velocity = [inf, 0, 0] }\n",
               "forces.wind.velocity[0]", 10, "must be finite");
}

TEST(SceneParser, OutOfRange) {
  expect_error("[cloth]\nmass = 0\n", "cloth.mass", 2, "must be > 0 (got 0)");
  expect_error("[cloth]\nsize = [1.0, -2]\n", "cloth.size", 2, "must be > 0 (got -2)");
  expect_error("[cloth]\nresolution = [0, 3]\n", "cloth.resolution", 2, ">= 1");
  expect_error("[cloth]\nresolution = [5000, 5000]\n", "cloth.resolution", 2, "at most 16000000");
  expect_error("[cloth]\nresolution = [5000000000, 1]\n", "cloth.resolution[0]", 2, "out of range");
  expect_error("[cloth]\nu_axis = [0, 0, 0]\n", "cloth.u_axis", 2, "zero vector");
  expect_error("[cloth]\nu_axis = [1, 0.1, 0]\n", "cloth.v_axis", 0, "orthogonal");
  expect_error(kMinimal + "[springs]\ndamping = -0.1\n", "springs.damping", 10, ">= 0");
  expect_error(kMinimal + "[springs]\nrule = \"mass_spring\"\n", "springs.rule", 10, "seed");
  expect_error(kMinimal + "[forces]\ndrag = -1\n", "forces.drag", 10, ">= 0");
  expect_error(kMinimal + "[forces]\nwind = { velocity = [1, 0, 0], gust = -0.5 }\n",
               "forces.wind.gust", 10, ">= 0");
  expect_error(kMinimal + "[forces]\nwind = { velocity = [1, 0, 0], seed = -1 }\n",
               "forces.wind.seed", 10, ">= 0");
  expect_error(kMinimal + "[forces]\nwind = { velocity = [1, 0, 0], gust_period = 0 }\n",
               "forces.wind.gust_period", 10, ">= 1e-06");
  expect_error(kMinimal + "[forces]\nwind = { gust = 0.5 }\n", "forces.wind.velocity", 10,
               "missing");
  expect_error(kMinimal + "threads = 2000\n", "solver.threads", 9, "between 0");
  expect_error(kMinimal + "threads = -1\n", "solver.threads", 9, "between 0");
  expect_error(kMinimal + "[trace]\nevery = 0\n", "trace.every", 10, ">= 1");
  expect_error(kMinimal + "[trace]\nfields = []\n", "trace.fields", 10, "at least one");
  expect_error(kMinimal + "[trace]\nfields = [\"position\", \"heat\"]\n", "trace.fields[1]", 10,
               "unknown field \"heat\"");
  expect_error(kMinimal + "[trace]\nvertices = [[4, 0]]\n", "trace.vertices[0]", 10,
               "outside the 4 x 3 grid");
  expect_error(kMinimal + "[trace]\nvertices = [[0, 0], [0, 0]]\n", "trace.vertices[1]", 10,
               "twice");
  expect_error("[cloth]\nshape = \"mesh\"\n", "cloth.file", 1, "missing (a mesh cloth needs file");
  expect_error("[cloth]\nshape = \"cone\"\n", "cloth.shape", 2,
               "unknown (valid: grid, tube, mesh)");
  expect_error(kMinimal + "precision = \"half\"\n", "solver.precision", 9, "float, double");
  expect_error(kMinimal + "backend = \"opencl\"\n", "solver.backend", 9, "valid: cpu, gpu");
  EXPECT_EQ(read_scene_string(kMinimal + "backend = \"cpu\"\n", "t").solver.backend, Backend::cpu);
  EXPECT_EQ(read_scene_string(kMinimal + "backend = \"gpu\"\n", "t").solver.backend, Backend::gpu);
}

TEST(SceneParser, TimeStep) {
  const std::string no_dt = "[cloth]\npins = [[0, 0]]\n[solver]\n";
  expect_error(no_dt + "dt = 0\n", "solver.dt", 4, "must be > 0 (got 0)");
  expect_error(no_dt + "dt = -1\n", "solver.dt", 4, "must be > 0 (got -1)");
  expect_error(no_dt + "dt = 2\n", "solver.dt", 4, "<= 1");
  EXPECT_EQ(read_scene_string(no_dt + "dt = 1\n", "t").solver.dt, 1.0);
}

TEST(SceneParser, Pins) {
  expect_error("[cloth]\nresolution = [4, 3]\npins = [[0, 0], [4, 0]]\n", "cloth.pins[1]", 3,
               "outside the 4 x 3 grid");
  expect_error("[cloth]\nresolution = [4, 3]\npins = [[0, -1]]\n", "cloth.pins[0]", 3, "outside");
  expect_error("[cloth]\nresolution = [4, 3]\npins = [[1, 2], [3, 0], [1, 2]]\n", "cloth.pins[2]",
               3, "listed twice");
  expect_error("[cloth]\nresolution = [2, 1]\npins = [[0, 0], [1, 0]]\n", "cloth.pins", 3,
               "every vertex is pinned");
  // No pins at all is fine (a falling sheet).
  EXPECT_TRUE(read_scene_string("[cloth]\n", "t").cloths[0].pins.empty());
}

TEST(SceneParser, UnknownKeys) {
  expect_error(kMinimal + "gravity = [0, -1, 0]\n", "solver.gravity", 9, "unknown key");
  expect_error("colour = \"red\"\n" + kMinimal, "colour", 1, "unknown top-level key");
  expect_error(kMinimal + "[physics]\ndt = 1\n", "physics", 9, "unknown top-level key");
  expect_error("[cloth]\nmass = 1\nmas = 2\n", "cloth.mas", 3, "unknown key");
  expect_error(kMinimal + "[forces]\nwind = { velocity = [1, 0, 0], gusts = 1 }\n",
               "forces.wind.gusts", 10, "unknown key");
  expect_error(kMinimal + "[[colliders]]\ntype = \"sphere\"\nradiu = 1\n", "colliders[0].radiu", 11,
               "unknown key");
  expect_error(kMinimal + "[music]\nfil = \"a.wav\"\n", "music.fil", 10, "unknown key");
  expect_error(kMinimal + "[music]\ntempo = 20\n", "music.tempo", 10, "between 40 and 240");
  expect_error(kMinimal + "[mannequin]\nsettle = -1\n", "mannequin.settle", 10, "between 0 and 60");
  expect_error("[cloth]\npins = [[0, 0]]\npins_follow = \"pelvis\"\n", "cloth.pins_follow", 3,
               "no [mannequin]");
  expect_error("[cloth]\npins = [[0, 0]]\npins_follow = \"tail\"\n[mannequin]\n",
               "cloth.pins_follow", 3, "no mannequin part \"tail\" (parts: pelvis, chest");
  expect_error("[cloth]\npins = [[0, 0]]\npins_follow = []\n", "cloth.pins_follow", 3,
               "name at least one collider");
  expect_error("[cloth]\npins = [[0, 0]]\npins_follow = [0, 1.5]\n[[colliders]]\n",
               "cloth.pins_follow[1]", 3, "integer");
  expect_error("[cloth]\npins = [[0, 0]]\npins_follow = [0, 3]\n[[colliders]]\ntype = \"sphere\"\n",
               "cloth.pins_follow[1]", 3, "names collider 3, but the scene has 1");
  expect_error("[cloth]\npins = [[0, 0]]\npins_follow = [0, \"tail\"]\n[mannequin]\n",
               "cloth.pins_follow[1]", 3, "no mannequin part \"tail\"");
  expect_error(kMinimal + "[render]\nshade = 3\n", "render.shade", 10, "unknown key");
  expect_error(kMinimal + "[render.light]\nkind = \"spot\"\n", "render.light.kind", 10,
               "unknown key");
  expect_error("[[cloth]]\n[[cloth]]\nwidth = 2\n", "cloth[1].width", 3, "unknown key");
  expect_error("[cloth]\nsprings = { stiffness = 1, damp = 2 }\n", "cloth.springs.damp", 2,
               "unknown key");
}

// [render]: every value read, and bad ones named with their key and line.
// [[colliders]]: every shape's keys, friction as a number or a table, motion by velocities or
// keyframes, and a cloth's release time.
TEST(SceneParser, Colliders) {
  const Scene s = read_scene_string(kMinimal + R"(
[[colliders]]
type = "plane"
point = [0, -1, 0]
normal = [0, 2, 0]
friction = 0.3

[[colliders]]
type = "box"
center = [0, 0.5, 0]
half_extents = [0.4, 0.1, 0.3]
rotation = [0, 45, 0]
rounding = 0.02
friction = { static = 0.8, kinetic = 0.5 }
thickness = 0.004
motion = { velocity = [0.5, 0, 0], angular_velocity = [0, 1, 0] }

[[colliders]]
type = "capsule"
a = [-1, 1, 0]
b = [1, 1, 0]
radius = 0.05
motion = { keys = [{ time = 0, offset = [0, 0, 0] }, { time = 1, offset = [0, 0, 2], rotation = [0, 90, 0] }] }
)",
                                    "t.toml", {"cloth.release_at=0.5"});
  ASSERT_EQ(s.colliders.size(), 3u);
  EXPECT_EQ(s.colliders[0].kind, ColliderKind::plane);
  EXPECT_EQ(s.colliders[0].normal, (Vec3d{0, 2, 0}));
  EXPECT_EQ(s.colliders[0].static_friction, 0.3);
  EXPECT_EQ(s.colliders[0].kinetic_friction, 0.3);
  const ColliderSpec& box = s.colliders[1];
  EXPECT_EQ(box.kind, ColliderKind::box);
  EXPECT_EQ(box.rotation, (Vec3d{0, 45, 0}));
  EXPECT_EQ(box.rounding, 0.02);
  EXPECT_EQ(box.static_friction, 0.8);
  EXPECT_EQ(box.kinetic_friction, 0.5);
  EXPECT_EQ(box.thickness, 0.004);
  EXPECT_EQ(box.motion.angular_velocity, (Vec3d{0, 1, 0}));
  const ColliderSpec& rod = s.colliders[2];
  EXPECT_EQ(rod.b, (Vec3d{1, 1, 0}));
  ASSERT_EQ(rod.motion.keys.size(), 2u);
  EXPECT_EQ(rod.motion.keys[1].rotation, (Vec3d{0, 90, 0}));
  EXPECT_EQ(rod.key, "colliders[2]");
  EXPECT_EQ(s.cloths[0].release_at, 0.5);
  expect_error(kMinimal + R"(
[[colliders]]
type = "capsule"
motion = { keys = [{ time = 1 }, { time = 0.5 }] }
)",
               "colliders[0].motion.keys[1].time", 12, "must increase");
}

TEST(SceneParser, RenderSection) {
  const Scene s = read_scene_string(kMinimal + R"([render]
mode = 7
shadows = "pcss"
shadow_map_size = 1024
light = { type = "directional", direction = [0, -1, -1], color = [1, 1, 1], intensity = 2, size = 0.02 }
sky = { enabled = false, turbidity = 5 }
pole = { radius = 0.03 }
[render.cloth]
roughness = 0.8
threads = "silver"
[[render.meshes]]
type = "torus_knot"
center = [1, 0.5, 0]
radius = 0.4
color = [0.2, 0.4, 0.8]
[[render.meshes]]
type = "box"
half_extents = [0.1, 0.2, 0.3]
rotation = [0, 45, 0]
)",
                                    "t.toml");
  const RenderSpec& r = s.render;
  EXPECT_EQ(r.mode, 7);
  EXPECT_EQ(r.shadows, ShadowFilter::pcss);
  EXPECT_EQ(r.shadow_map_size, 1024);
  EXPECT_EQ(r.light.type, LightType::directional);
  EXPECT_EQ(r.light.direction, (Vec3d{0, -1, -1}));
  EXPECT_EQ(r.light.intensity, 2.0);
  EXPECT_EQ(r.light.size, 0.02);
  EXPECT_FALSE(r.sky.enabled);
  EXPECT_EQ(r.sky.turbidity, 5.0);
  EXPECT_TRUE(r.pole.enabled);
  EXPECT_EQ(r.pole.radius, 0.03);
  EXPECT_EQ(r.cloth.roughness, 0.8);
  EXPECT_EQ(r.cloth.threads, ThreadMetal::silver);
  ASSERT_EQ(r.meshes.size(), 2u);
  EXPECT_EQ(r.meshes[0].kind, MeshKind::torus_knot);
  EXPECT_EQ(r.meshes[0].center, (Vec3d{1, 0.5, 0}));
  EXPECT_EQ(r.meshes[1].kind, MeshKind::box);
  EXPECT_EQ(r.meshes[1].half_extents, (Vec3d{0.1, 0.2, 0.3}));
  EXPECT_EQ(r.meshes[1].key, "render.meshes[1]");
  // Defaults without a [render] table.
  const Scene d = read_scene_string(kMinimal, "t.toml");
  EXPECT_EQ(d.render.mode, 3);
  EXPECT_EQ(d.render.shadows, ShadowFilter::pcf);
  EXPECT_TRUE(d.render.meshes.empty());

  expect_error(kMinimal + "[render]\nmode = 9\n", "render.mode", 10, "from 1 to 7");
  expect_error(kMinimal + "[render]\nshadows = \"vsm\"\n", "render.shadows", 10,
               "unknown shadow filter \"vsm\" (valid: none, pcf, pcss)");
  expect_error(kMinimal + "[render]\nshadow_map_size = 100\n", "render.shadow_map_size", 10,
               "between 256 and 8192");
  expect_error(kMinimal + "[render.light]\nintensity = -1\n", "render.light.intensity", 10, ">= 0");
  expect_error(kMinimal + "[render.light]\nposition = [0, 1, 0]\ntarget = [0, 1, 0]\n",
               "render.light.target", 11, "must differ");
  expect_error(kMinimal + "[render.sky]\nturbidity = 20\n", "render.sky.turbidity", 10,
               "between 1.7 and 10");
  expect_error(kMinimal + "[render.pole]\nradius = 0\n", "render.pole.radius", 10, "between");
  expect_error(kMinimal + "[[render.meshes]]\ntype = \"sphere\"\nradius = -1\n",
               "render.meshes[0].radius", 11, "> 0");
  expect_error(kMinimal + "[[render.meshes]]\ntype = \"box\"\nhalf_extents = [1, 0, 1]\n",
               "render.meshes[0].half_extents[1]", 11, "> 0");
  // A missing key is reported at its table's header.
  expect_error(kMinimal + "[[render.meshes]]\nradius = 1\n", "render.meshes[0].type", 9, "missing");
  expect_error(kMinimal + "[[render.meshes]]\ntype = \"teapot\"\n", "render.meshes[0].type", 10,
               "unknown mesh type \"teapot\"");
  expect_error(kMinimal + "[render.cloth]\nopacity = 1.5\n", "render.cloth.opacity", 10,
               "between 0 and 1");
  // OBJ scenery: the file is read with the scene, so a missing one is the scene's error.
  expect_error(kMinimal + "[[render.meshes]]\ntype = \"obj\"\n", "render.meshes[0].file", 9,
               "missing");
  expect_error(kMinimal + "[[render.meshes]]\ntype = \"obj\"\nfile = \"no_such_vase.obj\"\n",
               "render.meshes[0].file", 11, "no_such_vase.obj");
  expect_error(kMinimal + "[[render.meshes]]\ntype = \"obj\"\nfile = \"v.obj\"\nscale = 0\n",
               "render.meshes[0].scale", 12, "> 0");
}

// An OBJ mesh as scenery is read (scaled) with the scene.
TEST(SceneParser, ObjSceneryIsReadWithTheScene) {
  const std::string path = ::testing::TempDir() + "clothlab_parser_tri.obj";
  {
    std::ofstream obj(path);
    obj << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  }
  const Scene s = read_scene_string(kMinimal + "[[render.meshes]]\ntype = \"obj\"\nfile = \"" +
                                        path + "\"\nscale = 0.5\nsmooth = true\n",
                                    "t.toml");
  std::remove(path.c_str());
  ASSERT_EQ(s.render.meshes.size(), 1u);
  const MeshSpec& m = s.render.meshes[0];
  EXPECT_EQ(m.kind, MeshKind::obj);
  EXPECT_TRUE(m.smooth);
  ASSERT_TRUE(m.obj);
  EXPECT_EQ(m.obj->triangles.size(), 4u);
  EXPECT_DOUBLE_EQ(m.obj->positions[1].x(), 0.5);
}

TEST(SceneParser, UnknownIntegratorListsValidNames) {
  expect_error(kMinimal + "integrator = \"leapfrog\"\n", "solver.integrator", 9,
               "unknown integrator \"leapfrog\" (valid: explicit_euler, symplectic_euler, "
               "seed_hack, verlet, rk4, implicit_euler, xpbd, local_global, vbd, bdf2)");
}

TEST(SceneParser, FileErrors) {
  try {
    read_scene_file("/nonexistent/dir/scene.toml");
    FAIL() << "no error for a missing file";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.loc.file, "/nonexistent/dir/scene.toml");
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/scene.toml"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_scene_file(CLOTHLAB_SOURCE_DIR), SceneError);  // a directory

  const SceneError e = parse_error_of("[cloth]\nmass = 1\nsize = [1, \n");
  EXPECT_EQ(e.loc.file, "t.toml");
  EXPECT_GE(e.loc.line, 3);
  EXPECT_NE(std::string(e.what()).find("TOML syntax error"), std::string::npos) << e.what();
  const SceneError dup = parse_error_of("[cloth]\nmass = 1\nmass = 2\n");
  EXPECT_EQ(dup.loc.line, 3) << dup.what();
  EXPECT_EQ(std::string(dup.what()).rfind("t.toml:3:", 0), 0u) << dup.what();
}

TEST(SceneParser, SyntaxErrorInFileNamesFileAndLine) {
  const std::string path = std::string(CLOTHLAB_SOURCE_DIR) + "/tests/bad_scenes/syntax_error.toml";
  try {
    read_scene_file(path);
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.loc.file, path);
    EXPECT_GT(e.loc.line, 0);
    EXPECT_EQ(std::string(e.what()).rfind(path + ":" + std::to_string(e.loc.line) + ":", 0), 0u)
        << e.what();
  }
}

TEST(SceneParser, MissingCloth) {
  expect_error("[solver]\ndt = 0.001\n", "cloth", 0, "no cloth");
  expect_error("cloth = []\n", "cloth", 1, "empty");
  expect_error("cloth = 3\n", "cloth", 1, "expected an array");
}

TEST(SceneOverrides, ChangeValues) {
  const Scene s = read_scene_file(
      kDefaultScene, {"solver.dt=0.0005", "solver.integrator=rk4", "solver.precision=\"double\"",
                      "cloth.pins=[[0, 0]]", "forces.wind={ velocity = [0, 0, 2] }",
                      " cloth.resolution = [8, 4] ", "trace.vertices=[[7, 3]]"});
  EXPECT_EQ(s.solver.dt, 0.0005);
  EXPECT_EQ(s.solver.integrator, IntegratorKind::rk4);
  EXPECT_EQ(s.solver.precision, Precision::f64);
  EXPECT_EQ(s.cloths[0].pins, (std::vector<std::array<int, 2>>{{0, 0}}));
  EXPECT_EQ(s.forces.wind.velocity, (Vec3d{0, 0, 2}));
  EXPECT_EQ(s.forces.wind.gust, 0.0);  // the whole wind table was replaced
  EXPECT_EQ(s.cloths[0].resolution, (std::array<int, 2>{8, 4}));
  EXPECT_EQ(s.locations.at("solver.dt").file, "--set solver.dt=0.0005");
  EXPECT_EQ(s.locations.at("solver.dt").line, 0);
  EXPECT_EQ(s.locations.at("forces.wind.velocity").file,
            "--set forces.wind={ velocity = [0, 0, 2] }");
  EXPECT_EQ(s.locations.at("cloth.mass").file, kDefaultScene);  // untouched values keep theirs
  // Later overrides win; a plain word is a string; keys can be created where allowed.
  const Scene t = read_scene_string(
      kMinimal, "t.toml",
      {"solver.dt=0.1", "solver.dt=0.2", "springs.damping=1", "forces.wind.velocity=[1,1,1]",
       "cloth.pins[0]=[3, 2]", "cloth.size[1]=0.5"});
  EXPECT_EQ(t.solver.dt, 0.2);
  EXPECT_EQ(t.springs.damping, 1.0);
  EXPECT_TRUE(t.forces.wind.enabled);
  EXPECT_EQ(t.cloths[0].pins[0], (std::array<int, 2>{3, 2}));
  EXPECT_EQ(t.cloths[0].size, (std::array<double, 2>{1.0, 0.5}));
  EXPECT_EQ(t.locations.at("cloth.pins[0]").file, "--set cloth.pins[0]=[3, 2]");
}

TEST(SceneOverrides, ErrorsNameTheSetArgument) {
  const std::string file = kMinimal;
  // Range error on an overridden value.
  SceneError e = parse_error_of(file, {"solver.dt=-1"});
  EXPECT_EQ(std::string(e.what()), "--set solver.dt=-1: solver.dt: must be > 0 (got -1)");
  EXPECT_EQ(e.loc.line, 0);
  // Type error: text that is not TOML becomes a string, which is not a number.
  e = parse_error_of(file, {"solver.dt=fast"});
  EXPECT_EQ(e.key, "solver.dt");
  EXPECT_NE(std::string(e.what()).find("--set solver.dt=fast"), std::string::npos);
  EXPECT_NE(
      std::string(e.what()).find("expected a number of seconds or \"auto\", got string \"fast\""),
      std::string::npos);
  e = parse_error_of(file, {"cloth.resolution=[2.5, 3]"});
  EXPECT_EQ(e.key, "cloth.resolution[0]");
  EXPECT_EQ(e.loc.file, "--set cloth.resolution=[2.5, 3]");
  // Unknown keys, created by the override, are refused by the same check as in a file.
  expect_error(file, "solver.dtt", 0, "unknown key", {"solver.dtt=0.1"});
  EXPECT_EQ(parse_error_of(file, {"solver.dtt=0.1"}).loc.file, "--set solver.dtt=0.1");
  expect_error(file, "physics", 0, "unknown top-level key", {"physics.dt=0.1"});
  EXPECT_EQ(parse_error_of(file, {"physics.dt=0.1"}).loc.file, "--set physics.dt=0.1");
  expect_error(file, "music.file", 0, "no_such.wav", {"music.file=no_such.wav"});
  expect_error(file, "solver.integrator", 0, "unknown integrator", {"solver.integrator=rk5"});
  // A value error in the file is still reported at the file when another key is overridden.
  e = parse_error_of(file + "threads = -3\n", {"solver.dt=0.01"});
  EXPECT_EQ(e.loc.file, "t.toml");
  EXPECT_EQ(e.loc.line, 9);
  // A cross-field error names the key that is now invalid, where that key was written.
  e = parse_error_of(file, {"cloth.resolution=[1, 1]"});
  EXPECT_EQ(e.key, "cloth.pins");
  EXPECT_EQ(e.loc.file, "t.toml");
}

TEST(SceneOverrides, MalformedArguments) {
  for (const char* bad : {"solver.dt", "=3", " = 3", "solver..dt=1", "solver.=1", ".dt=1",
                          "solver dt=1", "cloth[x].mass=1", "cloth[1.mass=1", "cloth[]=1"}) {
    try {
      read_scene_string(kMinimal, "t.toml", {bad});
      ADD_FAILURE() << "no error for --set " << bad;
    } catch (const SceneError& e) {
      EXPECT_EQ(e.loc.file, std::string("--set ") + bad) << e.what();
      EXPECT_EQ(e.loc.line, 0);
    }
  }
  // Paths that do not fit the scene's shape.
  expect_error(kMinimal, "cloth", 0, "single table", {"cloth[0].mass=2"});
  expect_error(kMinimal, "solver.dt", 0, "not a table", {"solver.dt.x=2"});
  expect_error(kMinimal, "cloth.size", 0, "name one element as cloth.size[N]", {"cloth.size.x=2"});
  expect_error(kMinimal, "cloth.mass", 0, "expected a number, got a table", {"cloth.mass.x=2"});
  expect_error(kMinimal, "cloth.pins[5]", 0, "out of range", {"cloth.pins[5]=[0, 0]"});
}

const std::string kTwoCloths = R"(
[springs]
stiffness = 500
damping = 0.1

[[cloth]]
resolution = [4, 4]
pins = [[0, 0]]

[[cloth]]
resolution = [3, 2]
origin = [0, 1, 0]
mass = 0.5
springs = { stiffness = 1200 }

[trace]
vertices = [[1, 2, 1], [3, 3]]
fields = ["energy", "position"]
)";

TEST(MultiCloth, PerClothSpringsAndTraces) {
  const Scene s = read_scene_string(kTwoCloths, "two.toml");
  EXPECT_TRUE(s.multi_cloth);
  ASSERT_EQ(s.cloths.size(), 2u);
  EXPECT_EQ(s.cloths[0].key, "cloth[0]");
  EXPECT_EQ(s.cloths[1].key, "cloth[1]");
  EXPECT_EQ(s.cloths[1].mass, 0.5);
  EXPECT_EQ(s.cloths[1].resolution, (std::array<int, 2>{3, 2}));
  // Cloth 0 uses [springs]; cloth 1 its own, inheriting what it does not name.
  EXPECT_EQ(s.springs_of(0).stiffness, 500.0);
  EXPECT_EQ(s.springs_of(1).stiffness, 1200.0);
  EXPECT_EQ(s.springs_of(1).damping, 0.1);
  EXPECT_EQ(s.locations.at("cloth[1].mass").line, 13);
  EXPECT_EQ(s.locations.at("cloth[1].springs.stiffness").line, 14);
  ASSERT_TRUE(s.trace.has_value());
  ASSERT_EQ(s.trace->vertices.size(), 2u);
  EXPECT_EQ(s.trace->vertices[0].cloth, 1);
  EXPECT_EQ(s.trace->vertices[0].i, 2);
  EXPECT_EQ(s.trace->vertices[0].j, 1);
  EXPECT_EQ(s.trace->vertices[1].cloth, 0);  // [i, j] means cloth 0
  EXPECT_EQ(s.trace->vertices[1].i, 3);
  EXPECT_TRUE(s.trace->energy && s.trace->position);
  EXPECT_FALSE(s.trace->velocity || s.trace->force);
}

TEST(MultiCloth, ErrorsNameTheCloth) {
  expect_error(kTwoCloths, "cloth[1].mass", 0, "> 0", {"cloth[1].mass=-1"});
  expect_error(kTwoCloths, "cloth[2]", 0, "out of range", {"cloth[2].mass=1"});
  expect_error(kTwoCloths, "cloth", 0, "array", {"cloth.mass=1"});
  SceneError e = parse_error_of(kTwoCloths, {"trace.vertices=[[2, 0, 0]]"});
  EXPECT_EQ(e.key, "trace.vertices[0]");
  EXPECT_NE(std::string(e.what()).find("cloth index 2 is out of range"), std::string::npos);
  e = parse_error_of(kTwoCloths, {"trace.vertices=[[1, 3, 0]]"});
  EXPECT_NE(std::string(e.what()).find("outside the 3 x 2 grid of cloth[1]"), std::string::npos)
      << e.what();
  expect_error(kTwoCloths, "cloth[1].springs.stiffness", 0, ">= 0",
               {"cloth[1].springs.stiffness=-5"});
  // The file's own lines are named for per-cloth errors.
  std::string bad = kTwoCloths;
  bad.replace(bad.find("mass = 0.5"), 10, "mass = 0.0");
  expect_error(bad, "cloth[1].mass", 13, "> 0");
  // The one-cloth form names vertices as [i, j] only.
  expect_error(kMinimal + "[trace]\nvertices = [[0, 1, 1]]\n", "trace.vertices[0]", 10, "[i, j]");
}

TEST(Validate, SceneBuiltInCode) {
  Scene s;
  s.file = "code";
  s.cloths.push_back(ClothSpec{});
  s.cloths[0].key = "cloth";
  EXPECT_NO_THROW(validate_scene(s));
  s.solver.dt = 0.0;
  try {
    validate_scene(s);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "code: solver.dt: must be > 0 (got 0)");
  }
}

}  // namespace
}  // namespace clothlab

namespace clothlab {
namespace {

// The scene stays plain data: the parser reads no file a scene names and leaves every loaded
// part empty; the load step (load/) alone fills them (docs/design.md, "Data flow").
TEST(SceneParser, ParserLeavesTheLoadedPartsToTheLoadStep) {
  const std::string dir = std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/";
  for (const char* name : {"chair.toml", "round_cloth.toml", "dance.toml"}) {
    SCOPED_TRACE(name);
    const Scene parsed = parse_scene_file(dir + name);
    for (const ClothSpec& c : parsed.cloths) EXPECT_EQ(c.mesh, nullptr);
    for (const ColliderSpec& c : parsed.colliders) {
      EXPECT_EQ(c.mesh, nullptr);
      EXPECT_EQ(c.body, nullptr);
    }
    for (const MeshSpec& m : parsed.render.meshes) EXPECT_EQ(m.obj, nullptr);
    if (parsed.music) {
      EXPECT_EQ(parsed.music->track, nullptr);
    }
    if (parsed.mannequin) {
      EXPECT_EQ(parsed.mannequin->motion, nullptr);
    }

    const Scene loaded = read_scene_file(dir + name);
    int filled = 0;
    for (const ClothSpec& c : loaded.cloths) filled += c.mesh != nullptr;
    for (const ColliderSpec& c : loaded.colliders)
      filled += (c.mesh != nullptr) + (c.body != nullptr);
    for (const MeshSpec& m : loaded.render.meshes) filled += m.obj != nullptr;
    if (loaded.music) filled += loaded.music->track != nullptr;
    if (loaded.mannequin) filled += loaded.mannequin->motion != nullptr;
    EXPECT_GT(filled, 0) << "the load step filled nothing";
  }
}

}  // namespace
}  // namespace clothlab
