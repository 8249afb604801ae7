// Scene: the plain data a scene file (TOML, version 1) is parsed into. Objects are built from it
// afterwards (see sim/solver.hpp). Layout and keys: docs/design.md, docs/scene-format.md.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sim/scene/collider_spec.hpp"
#include "sim/scene/render_spec.hpp"

namespace clothlab {

// Where a value came from: a scene file position, or a --set argument (line 0, file holds the
// argument text). Used by every error that names a value.
struct SourceLoc {
  std::string file;
  int line = 0;
  int column = 0;
};

struct SpringSpec {
  std::string rule = "seed";  // the only rule so far: docs/design.md "seed" rule
  std::string preset;         // the material preset applied ("" none; sim/scene/spring_presets)
  double stiffness = 800.0;   // N/m, k = stiffness * edge / rest_length
  double damping = 0.0;       // N*s/m, along-spring damping
  // Per class of spring (docs/design.md "Spring classes"), each `stiffness` when not given:
  // stretch = axis neighbours and mesh edges, shear = diagonals, bend = the longer ones.
  std::optional<double> stretch, shear, bend;  // N/m for a spring one edge long
};

struct ClothSpec {
  std::string shape = "grid";             // grid | tube | mesh
  std::array<double, 2> size{2.0, 2.0};   // metres along u and v
  std::array<int, 2> resolution{32, 32};  // vertices along u and v, each >= 1
  Vec3d origin{-1.0, 2.5, 0.0};           // world position of vertex (0, 0)
  Vec3d u_axis{1.0, 0.0, 0.0};            // direction of increasing i (normalised on build)
  Vec3d v_axis{0.0, -1.0, 0.0};           // direction of increasing j (normalised on build)
  double mass = 1.0;                      // total kg, spread evenly over all vertices
  std::vector<std::array<int, 2>> pins;   // (i, j) vertices held fixed
  std::optional<SpringSpec> springs;      // per-cloth springs; else Scene::springs applies
  std::optional<double> release_at;       // s: the pins let go at this time (a drop)
  // Indices into [[colliders]]: the pins move with that collider (a waistband on a turning body),
  // keeping their place in its frame; with several, each pin with the one whose centre is
  // nearest at t = 0 (a sheet twisted between two bars); empty: pins stay where they are.
  std::vector<int> pins_follow;
  // As written, per entry: a mannequin part's name (e.g. "pelvis"), resolved once the mannequin
  // is built; empty where an index was written.
  std::vector<std::string> pins_follow_names;
  // Tube (a cylinder or frustum: skirt, sleeve): ring j is centred at origin + j * length /
  // (nv - 1) along v_axis, with radius from radius[0] (first ring) to radius[1] (last ring);
  // vertex i of a ring lies at angle 2 pi i / nu from u_axis, turning towards v_axis x u_axis.
  std::array<double, 2> radius{0.3, 0.3};  // m
  double length = 0.6;                     // m, first ring to last
  // Mesh (cloth from an OBJ file, sim/cloth/mesh_cloth.hpp): the OBJ's coordinates times `scale`,
  // turned by `rotation` (degrees about x, then y, then z) and moved by `origin` (0 unless given).
  // Pins are OBJ vertex numbers, stored as (number - 1, 0); resolution becomes [vertices, 1].
  std::string file;
  double scale = 1.0;
  Vec3d rotation{0.0, 0.0, 0.0};
  std::shared_ptr<const TriangleMesh> mesh;  // read by the load step (load/)
  std::string key;                           // key path prefix for messages: "cloth" or "cloth[1]"
};

struct WindSpec {
  bool enabled = false;
  Vec3d velocity{0.0, 0.0, 0.0};  // m/s, mean wind
  double gust = 0.0;              // relative gust amplitude, >= 0 (0.5 = +-50 %)
  std::uint64_t seed = 0;         // noise seed: the same seed gives the same gusts
  double gust_period = 1.0;       // s, time scale of the gust noise, > 0
  double coefficient = 1.0;       // kg/(m^2 s): F = coefficient * area * ((w - v) . n) n
};

struct ForceSpec {
  Vec3d gravity{0.0, -9.81, 0.0};  // m/s^2
  double drag = 0.0;               // N*s/m per vertex, F = -drag * v
  WindSpec wind;
};

// Explicit methods first, then the large-step ones (docs/solver.md has the papers).
enum class IntegratorKind {
  explicit_euler,
  symplectic_euler,
  seed_hack,
  verlet,
  rk4,
  implicit_euler,  // linearised backward Euler, Baraff & Witkin 1998, PCG solve
  xpbd,            // extended position-based dynamics, Macklin et al. 2016/2019 (small steps)
  local_global,    // fast mass-spring local/global solve, Liu et al. 2013
  vbd,             // vertex block descent on backward Euler, Chen et al. 2024
  bdf2,            // second-order backward differentiation, each step a backward-Euler solve
};
inline constexpr IntegratorKind kAllIntegrators[] = {IntegratorKind::explicit_euler,
                                                     IntegratorKind::symplectic_euler,
                                                     IntegratorKind::seed_hack,
                                                     IntegratorKind::verlet,
                                                     IntegratorKind::rk4,
                                                     IntegratorKind::implicit_euler,
                                                     IntegratorKind::xpbd,
                                                     IntegratorKind::local_global,
                                                     IntegratorKind::vbd,
                                                     IntegratorKind::bdf2};
// True for the methods with a step-size stability limit (explicit_euler ... rk4).
inline bool is_explicit(IntegratorKind k) {
  return k <= IntegratorKind::rk4;
}
enum class Precision { f32, f64 };

// Where the integrator substeps run: the CPU; the GPU's compute shaders (gpu); the GPU's vertex
// shader with transform feedback (docs/gpu-backend.md).
enum class Backend { cpu, gpu, transform_feedback };

// What solves the backward-Euler problem of each bdf2 step.
enum class StepSolver { newton, vbd };

// PCG's preconditioner in the implicit methods' Newton solves
// (sim/integrators/newton/multigrid.hpp).
enum class LinearSolver { automatic, block_jacobi, multigrid };

struct SolverSpec {
  IntegratorKind integrator = IntegratorKind::symplectic_euler;
  double dt = 0.001;     // s, fixed step, > 0 (ignored when dt_auto)
  bool dt_auto = false;  // dt = "auto": the step chosen from the highest frequency
  int substeps = 0;      // integrator steps of dt / substeps per step, >= 1; 0 = "auto"
  // m: an accuracy instead of a step (docs/tuning.md): the commands replace the solver's settings
  // with the cheapest that `clothlab tune` finds within it (0: none; the solver never reads it).
  double tolerance = 0.0;
  int iterations = 0;          // xpbd: per substep (1); local_global: per step (10); vbd: (30)
  bool tethers = true;         // xpbd on grid cloths: long-range attachments to the pins
  bool coarse_stretch = true;  // xpbd on grid cloths: one-sided stretch constraints, coarser grids
  bool stretch_slack = true;   // xpbd: those two allow more stretch as the substeps grow
  double chebyshev_rho = 0.0;  // local_global, vbd: Chebyshev's rho (0: local_global 0.97, vbd 0.9)
  double cg_tolerance = 0.0;   // implicit_euler, bdf2: |r| / |b| that ends PCG (0: automatic)
  int cg_max_iterations = 500;  // implicit_euler: PCG iteration cap per step
  int newton_iterations = 0;    // implicit_euler, bdf2: Newton iterations per step at most (0: 8)
  double newton_tolerance = 0.01;  // implicit_euler, bdf2: stop at |delta v| <= this |v1 - v0|
  StepSolver bdf2_solver = StepSolver::newton;  // bdf2: newton (PCG) or vbd iterations
  LinearSolver linear_solver =
      LinearSolver::automatic;    // implicit_euler, bdf2: PCG's preconditioner
  int threads = 0;                // 0 = auto (sim/core/parallel.hpp)
  bool self_collision = false;    // the cloth keeps its layers apart (sim/contact/self_collision)
  double self_thickness = 0.005;  // m: how far apart two layers stay
  // Triangle contact within and between cloths with the no-crossing fail-safe
  // (sim/contact/triangle_contact.hpp), at self_thickness.
  bool cloth_contact = false;
  Precision precision = Precision::f32;
  // Where the cloth step runs: gpu asks for the OpenGL compute backend (gpu/backend_solver.hpp),
  // which only a program with a GL context can give; everything else steps on the CPU.
  Backend backend = Backend::cpu;
};

// A traced vertex: (cloth, i, j). cloth is 0 in the one-cloth form.
struct TraceVertex {
  int cloth = 0;
  int i = 0;
  int j = 0;
};

struct TraceSpec {
  std::vector<TraceVertex> vertices;
  bool position = true;
  bool velocity = true;
  bool force = true;
  bool energy = true;
  int every = 1;  // write every N steps, >= 1
};

struct MusicTrack;

// [music]: what the mannequin dances to (issue 9). A sound file, or without one the project's own
// drum track at `tempo`; decoded and analysed by the load step (load/).
struct MusicSpec {
  std::string file;       // relative to the scene file; empty: the generated track
  double tempo = 120.0;   // BPM of the generated track
  double seconds = 40.0;  // its length
  std::shared_ptr<const MusicTrack> track;
};

// [mannequin]: the dancing figure (sim/body/): its primitives become colliders named
// "mannequin.<part>" after the scene's [[colliders]], so `pins_follow = "pelvis"` carries a
// waistband with it. It dances to the [music]'s beats, or to a steady 120 BPM without music.
struct MannequinSpec {
  Vec3d position{0.0, 0.0, 0.0};  // where it stands (soles at position.y)
  double facing = 0.0;            // degrees about +y; 0 faces +z
  double settle = 1.5;            // s in the rest pose before the dance blends in
  int blend_beats = 4;            // beats of the blend
  double amplitude = 1.0;         // scales every pose's departure from rest
  double static_friction = 0.8, kinetic_friction = 0.6;
  double thickness = 0.006;  // m
  std::shared_ptr<const BodyMotion> motion;
};

struct Scene {
  std::string file;  // path the scene was read from ("<string>" for in-memory text)
  std::vector<ClothSpec> cloths;
  bool multi_cloth = false;  // true for the [[cloth]] form: traces then name (cloth, i, j)
  SpringSpec springs;
  ForceSpec forces;
  SolverSpec solver;
  std::optional<TraceSpec> trace;       // absent: `clothlab trace` uses its documented default
  std::vector<ColliderSpec> colliders;  // [[colliders]]
  RenderSpec render;                    // [render]: how the scene is shown (vis/ only)
  std::optional<MusicSpec> music;
  std::optional<MannequinSpec> mannequin;
  // Source location of every value read, by key path ("solver.dt", "cloth[1].pins[2]").
  std::map<std::string, SourceLoc> locations;

  // The springs that apply to cloth c.
  const SpringSpec& springs_of(std::size_t c) const {
    return cloths[c].springs ? *cloths[c].springs : springs;
  }
};

const char* to_string(IntegratorKind kind);
std::optional<IntegratorKind> integrator_from_string(const std::string& name);
// solver.backend's names in scene files and messages ("cpu", "gpu", "transform_feedback").
extern const std::array<std::pair<Backend, const char*>, 3> kBackendNames;
const char* to_string(Backend backend);

}  // namespace clothlab
