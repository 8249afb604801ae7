// Wind with deterministic gusts. The wind velocity at time t and position x is
//   w(t, x) = W (1 + gust * g((t - (x . W^) / |W|) / period)),
// a gust field that travels with the mean wind W, so a flag ripples instead of breathing.
// g is seeded value noise in [-1, 1]: the same seed gives the same gusts, so traces repeat.
// Force on vertex i (a linear pressure model on the cloth's surface normal):
//   F_i = coefficient * A_i * ((w - v_i) . n_i) n_i,
// with A_i a third of the area of the triangles around i and n_i their area-weighted normal.
#pragma once

#include <cstdint>

namespace clothlab {

// Seeded smooth noise in [-1, 1] (quintic-interpolated value noise, two octaves).
double gust_noise(std::uint64_t seed, double s);

}  // namespace clothlab
