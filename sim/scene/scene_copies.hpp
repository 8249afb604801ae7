// Copies of a scene's cloth for the window's [ and ] keys (issue 10: "more or fewer objects"):
// the scene's cloths and the colliders they fall on, repeated on a square grid in the horizontal
// plane, every copy simulated. Planes stay shared (one floor under all). Each copy sees exactly
// what the original sees, moved: adding copies changes no copy's physics.
#pragma once

#include <string>

#include "sim/scene/scene.hpp"

namespace clothlab {

// Why `scene` cannot be copied (one line), or empty when it can: a mannequin, pins that follow a
// collider and mesh colliders are not repeated.
std::string copies_unsupported_reason(const Scene& scene);

// Copy k (0 = the original) sits at offset (col * spacing, 0, -row * spacing), with cols =
// ceil(sqrt(copies)), col = k % cols, row = k / cols.
Vec3d copy_offset(int k, int copies, double spacing);

// `scene` with `copies` (>= 1) copies of its cloths and non-plane colliders; copies == 1 gives
// `scene` itself. Cloth c of copy k becomes cloth k * cloths + c (traces and pins of the original
// keep their numbers). Throws std::invalid_argument when copies_unsupported_reason is not empty.
Scene with_copies(const Scene& scene, int copies, double spacing);

}  // namespace clothlab
