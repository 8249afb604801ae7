// The scalars the cloth can be coloured by (ViewSettings::color): per-vertex values computed on
// the CPU from the solver's state, only while they are shown. Plain data out, no GL.
#pragma once

#include <array>
#include <optional>
#include <string_view>
#include <vector>

#include "sim/forces/force_source.hpp"
#include "vis/render/view_settings.hpp"

namespace clothlab {
class SolverState;
}

namespace clothlab::vis {

std::string_view scalar_field_name(ScalarField field);  // "none", "force", "speed", ...
std::optional<ScalarField> parse_scalar_field(std::string_view name);
std::string_view scalar_field_unit(ScalarField field);   // "N", "m/s", "" (strain), "m"
std::string_view scalar_field_title(ScalarField field);  // "|force|", "|velocity|", ...
// Signed fields (strain) read best on a diverging map with a symmetric range.
bool scalar_field_signed(ScalarField field);

// Computes one scalar per vertex. Built for one cloth topology (rebuild after Solver resets that
// change it); compute() never allocates once `out` has the vertex count.
class ScalarFieldSampler {
 public:
  explicit ScalarFieldSampler(const SolverState& solver);

  // |force| (of `source`, after solver.update_force_field(source)), |velocity|, strain or height
  // (world y). Strain at a vertex is the mean engineering strain (l - l0) / l0 of the springs
  // that end there, l0 the spring's built length (the seed rule's rest length).
  void compute(SolverState& solver, ScalarField field, ForceSource source, std::vector<float>& out);

 private:
  std::vector<std::array<int, 2>> springs_;
  std::vector<float> rest_length_;  // per spring, m
  std::vector<float> inv_degree_;   // per vertex, 1 / springs ending there (0 for none)
  std::vector<float> xyz_;          // scratch: positions or velocities
};

}  // namespace clothlab::vis
