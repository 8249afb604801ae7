// Edits the window makes to a Scene (the panel and the keys change plain data; the solver is
// rebuilt from it afterwards, like from a parsed file). No GL here.
#pragma once

#include <array>

#include "sim/scene/scene.hpp"

namespace clothlab::vis {

// Copies the values that leave the cloth's topology alone -- integrator, dt, springs, drag,
// wind -- from `from` to `to`. A solver built from the result can take over the running
// motion with load_state.
void copy_dynamics(const Scene& from, Scene& to);

// Scales every cloth's resolution by `factor` (the ] / [ keys), rounded and clamped to 2..512
// per axis; a count of 1 (a strip) stays 1. Returns false when nothing changed.
bool scale_resolution(Scene& scene, double factor);

// After a resolution change: moves pins and traced vertices to the same relative place on the
// grid, (i, j) scaled from `base`'s resolution to `scene`'s, so the top corners stay pinned at
// any resolution. Always maps from the parsed scene, so repeated +/- do not drift.
void remap_grid_indices(Scene& scene, const Scene& base);

// Wind speed: the length of the mean wind velocity. Setting it keeps the direction (along +x
// when the wind was zero).
double wind_speed(const Scene& scene);
void set_wind_speed(Scene& scene, double speed);

// The total mass of all cloths (kg), for scaling the default push.
double total_mass(const Scene& scene);

}  // namespace clothlab::vis
