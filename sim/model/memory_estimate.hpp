// What a scene will need in memory once built, estimated before it is built, so that a scene that
// cannot fit is refused with the estimate instead of ending in std::bad_alloc midway (issue 21).
// The figures are bytes per vertex measured with `/usr/bin/time -f %M clothlab check` on
// 1000 x 1000 sheets (docs/inputs.md); the estimate is meant to be within a few tens of percent.
#pragma once

#include <cstdint>

#include "sim/scene/scene.hpp"

namespace clothlab {

// Vertices of all the scene's cloths (a mesh cloth's once loaded).
double scene_vertices(const Scene& scene);

// Bytes the built solver of `scene` will hold (all cloths, its integrator and precision).
std::uint64_t estimated_solver_bytes(const Scene& scene);

}  // namespace clothlab
