// Divergence detection: a run stops with a report instead of writing NaN. Two tests after every
// step, both one pass over the vertices:
//  - every position and velocity component is finite;
//  - kinetic energy stays below kLimitFactor times the scene's energy scale: the initial
//    mechanical energy plus what gravity, wind and pushes can plausibly feed in (a blow-up of the
//    lattice usually shows up in kinetic energy first).
// Wherever the full energy is computed anyway (a trace's energy rows, its summary), its elastic
// and total parts are held to the same limit (check_energy): a step that stretches the lattice
// far beyond the scale before the velocities grow is caught at that step, never written out. A
// per-step elastic check would cost a pass over the springs, as much as the force pass.
#pragma once

#include <string>
#include <vector>

#include "sim/energy.hpp"
#include "sim/integrators/integrator.hpp"

namespace clothlab {

struct VertexRef {
  int cloth = 0, i = 0, j = 0;
};

struct Divergence {
  long step = 0;         // the step after which it was detected (1-based)
  double time = 0.0;     // s, simulated time at that step
  VertexRef vertex;      // the offending (or fastest) vertex
  std::string quantity;  // e.g. "velocity.y = nan", "kinetic energy = 3.1e+09 J"
  std::string message() const;
};

template <class T>
class DivergenceMonitor {
 public:
  static constexpr double kLimitFactor = 1e3;

  DivergenceMonitor(const Model<T>& m, const State<T>& initial, double initial_energy);
  // Energy fed in from outside (a push): raises the allowance.
  void add_energy(double joules) { scale_ += joules; }
  double energy_scale() const { return scale_; }

  // Returns true and fills `out` when the state has diverged. Allocates only on failure.
  bool check(const Model<T>& m, const State<T>& s, long step, double time, int threads,
             Divergence& out);
  // Returns true and fills `out` (the vertex at an end of the spring with the most elastic
  // energy) when `e`, the energy of `s`, has its elastic or total part beyond the limit.
  bool check_energy(const Model<T>& m, const State<T>& s, const Energy& e, long step, double time,
                    Divergence& out) const;
  // Fills `out` for a run that cannot go on (`why`), at the vertex at an end of the spring with
  // the most elastic energy.
  void stuck(const Model<T>& m, const State<T>& s, long step, double time, const std::string& why,
             Divergence& out) const;

 private:
  double scale_ = 0.0;
  std::vector<double> partials_;  // per-block: sum of coordinates, kinetic energy
};

VertexRef vertex_ref_of(const std::vector<ClothRange>& cloths, int index);

}  // namespace clothlab
