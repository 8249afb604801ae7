// Copies of a scene's cloth for the window's [ and ] keys (issue 10: "more or fewer objects"):
// the scene's cloths and the colliders they fall on, repeated on a square grid in the horizontal
// plane, every copy simulated. Spheres, boxes, capsules and meshes move with their placement (a
// keyframed motion is relative to it); planes stay shared (one floor under all). Each copy sees
// what the original sees, moved: adding copies changes no copy's physics.
#pragma once

#include <string>

#include "sim/scene/scene.hpp"

namespace clothlab {

// Why `scene` cannot be copied (one line), or empty when it can: a mannequin and pins that
// follow a collider are not repeated.
std::string copies_unsupported_reason(const Scene& scene);

// Copy k (0 = the original) sits at offset (col * spacing, 0, -row * spacing), with cols =
// ceil(sqrt(copies)), col = k % cols, row = k / cols.
Vec3d copy_offset(int k, int copies, double spacing);

// The spacing the window and `render --copies` use: the scene's horizontal extent (the larger of
// x and z over its cloths' rest positions, as the solver stores them in float) plus a quarter
// of it, at least 0.25 m. The scene must be loaded (a mesh cloth's OBJ read).
double copy_spacing(const Scene& scene);

// `scene` with `copies` (>= 1) copies of its cloths and non-plane colliders; copies == 1 gives
// `scene` itself. Cloth c of copy k becomes cloth k * cloths + c (traces and pins of the original
// keep their numbers). Throws std::invalid_argument when copies_unsupported_reason is not empty.
Scene with_copies(const Scene& scene, int copies, double spacing);

}  // namespace clothlab
