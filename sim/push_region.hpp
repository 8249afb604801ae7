// Where a push lands by default (the window's P, clothlab.Simulation.push): the cloth's mean
// position and a quarter of its bounding box's diagonal, at least 5 cm: a hand-sized push on the
// middle, not a shove of the whole sheet.
#pragma once

#include "sim/solver.hpp"

namespace clothlab {

struct PushRegion {
  Vec3d center{0.0, 0.0, 0.0};  // m
  double radius = 0.05;         // m
};

PushRegion default_push_region(const SolverState& solver);

}  // namespace clothlab
