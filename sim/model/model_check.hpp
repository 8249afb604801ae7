// The built state checked once before the first step: a scene whose every value is in range can
// still build a cloth the solver's precision cannot hold (cloth.size = [1e30, 1e30] on 4000 x
// 4000 vertices has finite positions but elastic energies beyond a double; cloth.mass = 1e-44
// gives vertex masses that are 0 as floats). Issue 21: such a scene is a scene error naming its
// cloth and the keys that built it, never a run that writes nan.
#pragma once

#include "sim/model/model.hpp"
#include "sim/scene/scene.hpp"

namespace clothlab {

// Throws SceneError, located at the offending cloth's key, when a built position, mass, rest
// length, stiffness or damping is not finite (or a mass is not positive) in precision T, or the
// initial energy `energy` (J) is not finite.
template <class T>
void check_built_model(const Model<T>& m, const Scene& scene, double energy);

// Throws SceneError (at the cloth's key) when a force of the built state is not finite.
template <class T>
void check_built_forces(const Vec3Array<T>& f, const Model<T>& m, const Scene& scene);

// Throws SceneError (at solver.self_thickness) when triangle contact is on and the thickness is
// more than the cloths' mean rest edge: every neighbour within a few rings would be a contact
// pair, and a fuzzed 2e9 m made every pair of the cloth one.
template <class T>
void check_contact_thickness(const Model<T>& m, const Scene& scene);

// Throws SceneError (at solver.dt) when the step the solver will take is not a positive, finite
// number of seconds (an automatic step that came out 0 for drag = 1e38).
void check_step(double dt, int substeps, const Scene& scene);

}  // namespace clothlab
