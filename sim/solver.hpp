// The solver as the rest of ClothLab sees it: built from a validated Scene, advanced by a
// simulated duration (never by wall-clock time), read through plain values. The scalar type
// (float or double, the scene's solver.precision) is hidden behind this interface.
#pragma once

#include <memory>
#include <optional>

#include "sim/contact/contact_stats.hpp"
#include "sim/divergence.hpp"
#include "sim/energy.hpp"
#include "sim/forces/force_source.hpp"
#include "sim/scene/scene.hpp"

namespace clothlab {

class DeviceCloth;        // sim/step_backend.hpp
enum class SpringKernel;  // sim/model/model.hpp

// Iterative work summed since the solver was built or reset (PCG iterations for
// implicit_euler, sweeps for xpbd and local_global).
struct SolveTotals {
  long substeps = 0;        // integrator steps taken
  long iterations = 0;      // summed over those steps
  long solves = 0;          // linear solves (Newton iterations), summed over those steps
  int max_iterations = 0;   // in one step
  double max_residual = 0;  // relative, largest after any step
  long unconverged = 0;     // steps that stopped at the iteration cap
};

struct AdvanceResult {
  long steps = 0;                        // steps taken by this call
  std::optional<Divergence> divergence;  // set when the run stopped on divergence
  bool ok() const { return !divergence; }
};

// The solver's roles, each an interface of its own, so that code asks for only the role it
// needs: renderers, probes and exporters read the state (SolverState), the window's hand acts on
// the cloth (SolverInteraction), clocks and benchmarks step it (SolverStepping). A Solver is all
// three.

// Advancing in simulated time, and what that costs.
class SolverStepping {
 public:
  virtual ~SolverStepping() = default;

  // Runs every whole step that fits into the time asked for plus the remainder carried from the
  // previous call, and carries the new remainder: calling advance(1/30) thirty times and
  // advance(1) once take the same steps. Stops early on divergence.
  virtual AdvanceResult advance(double duration) = 0;
  // Runs exactly `count` steps (or until divergence).
  virtual AdvanceResult step(long count) = 0;

  virtual double time() const = 0;  // s: steps taken * dt
  virtual long step_count() const = 0;
  virtual double dt() const = 0;              // s, one step (chosen by the solver for dt = "auto")
  virtual int substeps() const = 0;           // integrator steps of dt / substeps per step
  virtual SolveStats last_solve() const = 0;  // the integrator's last substep
  virtual const SolveTotals& solve_totals() const = 0;

  virtual void set_threads(int threads) = 0;  // 0 = auto (kParallelMinVertices)
  virtual int threads() const = 0;
  virtual void reset() = 0;  // back to the built state at t = 0, pins held again
};

// The state and what is computed from it, for renderers, probes, traces and checks.
// (Read-only views: vis/ reads the state, never changes the physics.)
class SolverState {
 public:
  virtual ~SolverState() = default;

  virtual std::size_t vertex_count() const = 0;
  virtual std::size_t spring_count() const = 0;
  virtual int vertex_index(const VertexRef& v) const = 0;
  virtual VertexRef vertex_ref(int index) const = 0;

  virtual Vec3d position(int vertex) const = 0;
  virtual Vec3d velocity(int vertex) const = 0;
  virtual Vec3d rest_position(int vertex) const = 0;  // as built
  virtual double mass(int vertex) const = 0;          // kg (a pinned vertex keeps its mass)
  virtual bool pinned(int vertex) const = 0;          // held in place (its force is the support's)
  // Fills the force field at the current state; only called when something displays, probes or
  // traces forces, so a plain run never pays for it. `source` picks the total force (what the
  // integrators see; for pinned vertices the support reaction) or one source alone (springs,
  // gravity m_i g, drag -c v_i, wind); the sources add up to the total. Allocates nothing.
  virtual void update_force_field(ForceSource source = ForceSource::total) = 0;
  virtual Vec3d force(int vertex) const = 0;  // from the last update_force_field()
  // The source the last update_force_field() filled (total before any update).
  virtual ForceSource force_field_source() const = 0;
  virtual Energy energy() = 0;
  // The divergence `e` (this state's energy()) shows, if any: its elastic or total part beyond
  // the monitor's limit (sim/divergence.hpp). For callers that computed the energy anyway.
  virtual std::optional<Divergence> energy_divergence(const Energy& e) const = 0;

  virtual void copy_positions(float* xyz) const = 0;       // 3 floats per vertex
  virtual void copy_rest_positions(float* xyz) const = 0;  // the built positions
  virtual void copy_normals(float* xyz) = 0;  // unit area-weighted normals of the current state
  virtual const std::vector<std::array<int, 3>>& triangles() const = 0;
  virtual std::vector<std::array<int, 2>> spring_pairs() const = 0;  // every spring once
  virtual const std::vector<ClothRange>& cloths() const = 0;
  virtual void copy_velocities(float* xyz) const = 0;
  // The collision response of the last substep (zero without colliders).
  virtual ContactStats last_contacts() const = 0;
  // Self-collision's last step; none without solver.self_collision.
  virtual std::optional<SelfCollisionStats> last_self_collision() const = 0;
  // Triangle contact's last substep; none without solver.cloth_contact.
  virtual std::optional<ClothContactStats> last_cloth_contact() const = 0;
  // Crossing (edge, triangle) pairs of the cloth surfaces now (sim/contact/intersections.hpp).
  virtual long intersections() const = 0;
  // solver.self_thickness: how far apart layers of cloth stay (m), with contact on or off.
  virtual double self_thickness() const = 0;
  // Where the state lives in device buffers (the GPU backend): the renderer draws from them.
  // Null on the CPU.
  virtual DeviceCloth* device_cloth() const = 0;
};

class Solver;

// What a user does to the cloth: push it, drop it, pull it, or hand it another solver's motion.
class SolverInteraction {
 public:
  virtual ~SolverInteraction() = default;

  // A push (the window's P key): adds momentum `impulse` (N*s) to the free vertices within
  // `radius` of `center`, weighted by (1 - r^2/R^2)^2 and normalised so the total momentum
  // change is exactly `impulse`; with no free vertex in reach the nearest free vertex takes it.
  virtual void apply_impulse(const Vec3d& center, double radius, const Vec3d& impulse) = 0;
  // Lets every cloth go of its pins now (the window's D: drop onto the colliders below); a
  // cloth with release_at lets go by itself at that time. reset() pins them again.
  virtual void release_pins() = 0;
  virtual bool pins_released() const = 0;
  // Ctrl + drag in the window: pulls `vertex` towards `target` (m) like a stiff, critically
  // damped spring (a free vertex closes the gap with a time constant of 4 ms, whatever its
  // mass; against the cloth's pull it stays a little short, as a spring does) until
  // release_grab(). A pinned vertex cannot be grabbed (returns false).
  virtual bool grab(int vertex, const Vec3d& target) = 0;
  virtual void release_grab() = 0;
  virtual std::optional<int> grabbed() const = 0;
  // Takes over another solver's positions, velocities, time and step count (same vertex
  // count), e.g. when a view changes a parameter without restarting the motion.
  virtual void load_state(const Solver& other) = 0;
  // Replaces every vertex's position (m) and velocity (m/s), one of each per vertex, e.g. a
  // disturbed start; time and pins stay. What the integrator cached from the old state is
  // forgotten, and the energy written joins the divergence monitor's allowance.
  virtual void set_state(const std::vector<Vec3d>& positions,
                         const std::vector<Vec3d>& velocities) = 0;
};

// Built from a validated, loaded Scene; every role in one object.
class Solver : public SolverStepping, public SolverState, public SolverInteraction {
 public:
  ~Solver() override = default;
};

// "GPU" when `solver` steps on the compute-shader backend, "GPU transform feedback" on the vertex
// shader's, else "CPU".
const char* backend_name(const SolverState& solver);

std::unique_ptr<Solver> make_solver(const Scene& scene);
// With a chosen spring kernel: tests and benchmarks compare the row sweep (the default) with the
// neighbour list.
std::unique_ptr<Solver> make_solver(const Scene& scene, SpringKernel kernel);

}  // namespace clothlab
