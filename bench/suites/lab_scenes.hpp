// The canonical scenes of the accuracy and stability suites (docs/design.md, "Accuracy benchmark
// scenes"), built in code so tests and benchmarks share them.
#pragma once

#include "sim/scene/scene.hpp"

namespace clothlab::bench {

inline constexpr double kFrame = 1.0 / 60.0;  // s, one frame at 60 Hz

struct SheetParams {
  int resolution = 32;      // vertices along each side
  double size = 1.0;        // m
  double mass = 0.2;        // kg
  double stiffness = 1000;  // N/m
  double damping = 0.05;    // N*s/m along each spring
};

// A square sheet lying horizontal (x-z plane, y = 0), pinned at the two corners of its j = 0
// edge, released at rest: it falls and swings under gravity ("hanging cloth").
Scene hanging_sheet(const SheetParams& p, IntegratorKind integrator, double dt);

// A 1.5 m x 1 m flag hanging from a vertical pole along its i = 0 edge (every vertex of that edge
// pinned), in a steady wind of (6, 0, 3) m/s (no gusts), 24 x 16 vertices, 0.2 kg, the same
// stiffness and damping as the sheet.
Scene steady_flag(IntegratorKind integrator, double dt);

// Two vertices, the top one pinned: 0.1 kg, 100 N/m, rest length 0.5 m, hanging along gravity.
// Closed form y(t) = -L - A (1 - cos(w t)), A = m g / k, w = sqrt(k / m).
Scene single_spring(IntegratorKind integrator, double dt);

}  // namespace clothlab::bench
