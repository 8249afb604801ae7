// One run of a scene for `clothlab tune` (docs/tuning.md): the scene file read with a setting's
// --set lines, stepped to each sample time, its positions and energy kept there, and the wall
// time its steps took (building the solver is not counted). A run stops early on divergence or
// once its wall time passes a limit, and says which.
#pragma once

#include <string>
#include <vector>

#include "sim/scene/scene.hpp"

namespace clothlab::tune {

using Positions = std::vector<Vec3d>;

// A candidate setting: its family (explicit, implicit, constraints, descent), a label for people
// and the --set lines that make it from the user's scene.
struct Setting {
  std::string family;
  std::string label;
  std::vector<std::string> overrides;
};

struct SampledRun {
  std::vector<Positions> at;   // positions at each sample time reached
  std::vector<double> energy;  // J: total energy there
  double wall = 0.0;           // s of wall time stepping
  std::string failure;         // the divergence report, or why it stopped; empty when it finished
  bool timed_out = false;      // stopped at the wall-time limit
  bool finished() const { return failure.empty(); }
};

// Steps `scene` on the CPU to each of `times` (s, ascending, multiples of its step) and records
// the state there. `wall_limit` (s, 0: none): stop once stepping has taken longer.
SampledRun run_sampled(const Scene& scene, const std::vector<double>& times, double wall_limit);

// RMS and largest distance between two position sets of the same vertices (m).
struct Distance {
  double rms = 0.0, max = 0.0;
};
// With `per_vertex`, each vertex's distance too (resized to the vertex count).
Distance distance(const Positions& a, const Positions& b, std::vector<float>* per_vertex = nullptr);

}  // namespace clothlab::tune
