// The probe's readout (keys 8 / 9 / 0): the field's value at the probed pixel (interpolated by
// the field pass) and at the nearest or pinned vertex (the solver's exact value), as the lines
// next to the cursor and the short form for the window's title.
#pragma once

#include <optional>
#include <string>

#include "apps/view/control_panel.hpp"
#include "sim/solver.hpp"
#include "vis/passes/field_pass.hpp"

namespace clothlab::vis {

struct ProbeReadout {
  std::string text;   // next to the cursor, several lines
  std::string title;  // one line
};

// `sample`: the field pass's reading at pixel (px, py), or none (off the cloth, or a pinned
// vertex hidden); `vertex`: the vertex the readout names (>= 0); `pinned`: the probe follows it.
ProbeReadout probe_readout(Field field, SolverState& solver,
                           const std::optional<ProbeSample>& sample, int vertex, bool pinned,
                           int px, int py);

}  // namespace clothlab::vis
