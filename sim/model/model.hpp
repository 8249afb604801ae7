// Model<T>: everything the force kernels read that does not change during a step, in the
// solver's scalar type. Springs are stored as a padded per-vertex neighbour table ("ELL" layout,
// slot-major): slot s of vertex i is entry s * n + i. Each vertex gathers its own spring forces,
// so the force pass needs no atomics and is deterministic for any thread count.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "sim/cloth/seed_springs.hpp"
#include "sim/core/vec3_array.hpp"
#include "sim/scene/scene.hpp"

namespace clothlab {

// Where one cloth's vertices live in the global arrays.
struct ClothRange {
  int offset = 0;  // global index of vertex (0, 0)
  int nu = 0, nv = 0;
};

template <class T>
struct Model {
  std::size_t n = 0;                // vertices, all cloths
  AlignedVector<T> mass, inv_mass;  // kg and 1/kg; inv_mass is 0 for pinned vertices
  std::vector<int> pinned;          // global indices

  // Neighbour table: `slots` entries per vertex; unused entries point at the vertex itself with
  // zero stiffness, damping and rest length, which the kernel turns into zero force.
  int slots = 0;
  std::vector<std::int32_t> neighbour;
  AlignedVector<T> stiffness, rest_length, damping;
  bool has_damping = false;
  std::vector<Spring> springs;  // the unique springs (double), for counts and tests

  // Surface for the wind force and normals.
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> incident_offset, incident_triangle;  // CSR: triangles around each vertex

  std::array<T, 3> gravity{0, 0, 0};
  T drag = 0;
  WindSpec wind;  // evaluated in double: gusts are a function of time and position

  std::vector<ClothRange> cloths;
  Vec3Array<T> rest_positions;  // the built (initial) positions
};

template <class T>
Model<T> build_model(const Scene& scene);

}  // namespace clothlab
