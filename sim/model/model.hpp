// Model<T>: everything the force kernels read that does not change during a step, in the
// solver's scalar type. Each vertex gathers the forces of its own springs (no atomics, the same
// result for any thread count) from one of two equivalent descriptions of its neighbours:
//  - row_sweep (default): a grid cloth's springs are one stencil of offsets (di, dj) with the
//    same rest length and stiffness everywhere; for one offset and one grid row the neighbours
//    are a contiguous run of memory, so the kernel streams rows with no index array or gather.
//  - neighbour_list: a padded per-vertex neighbour table ("ELL" layout, slot-major: slot s of
//    vertex i is entry s * n + i) that any topology can use; the reference for the row sweep.
// Both add a vertex's springs in the order of the neighbour's index.
#pragma once

#include <algorithm>
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
  bool wrap_u = false;  // a tube: column nu - 1 joins column 0 across the seam
  // A mesh cloth (sim/cloth/mesh_cloth.hpp): no grid; nu is its vertex count and nv 1, and its
  // surface is the model's triangles between offset and offset + nu.
  bool mesh = false;
};

// The cloth of each of n vertices: the index of the range that holds it.
inline std::vector<std::int32_t> vertex_cloths(const std::vector<ClothRange>& cloths,
                                               std::size_t n) {
  std::vector<std::int32_t> out(n, 0);
  for (std::size_t c = 0; c < cloths.size(); ++c)
    std::fill_n(out.begin() + cloths[c].offset,
                std::size_t(cloths[c].nu) * std::size_t(cloths[c].nv), std::int32_t(c));
  return out;
}

enum class SpringKernel { row_sweep, neighbour_list };

// One grid cloth's spring stencil for the row-sweep kernel.
template <class T>
struct GridStencil {
  struct Entry {
    int di = 0, dj = 0;
    long shift = 0;  // di + dj * nu: the neighbour's index minus the vertex's
    T stiffness = 0, rest_length = 0, damping = 0;
    bool first_half = false;  // dj > 0, or dj == 0 and di > 0: counts each spring once
  };
  int offset = 0, nu = 0, nv = 0;
  std::vector<Entry> entries;  // both signs of every offset, sorted by shift
};

template <class T>
struct Model {
  std::size_t n = 0;                // vertices, all cloths
  AlignedVector<T> mass, inv_mass;  // kg and 1/kg; inv_mass is 0 for pinned vertices
  std::vector<int> pinned;          // global indices

  SpringKernel kernel = SpringKernel::row_sweep;
  std::size_t spring_count = 0;
  bool has_damping = false;
  std::vector<GridStencil<T>> grids;  // row_sweep: one per cloth

  // neighbour_list: `slots` entries per vertex; unused entries point at the vertex itself with
  // zero stiffness, damping and rest length, which the kernel turns into zero force.
  int slots = 0;
  std::vector<std::int32_t> neighbour;
  AlignedVector<T> stiffness, rest_length, damping;

  // Surface for the wind force and normals.
  std::vector<std::array<int, 3>> triangles;
  // Triangles around each vertex, padded to `incident_slots` per vertex (slot-major, like the
  // neighbour table); padding points at index triangles.size(), a zero-area dummy the wind pass
  // keeps in its face arrays, so the gather loop has a fixed trip count and vectorises.
  int incident_slots = 0;
  std::vector<std::int32_t> incident_triangle;

  std::array<T, 3> gravity{0, 0, 0};
  T drag = 0;
  WindSpec wind;  // evaluated in double: gusts are a function of time and position

  std::vector<ClothRange> cloths;
  Vec3Array<T> rest_positions;  // the built (initial) positions
};

// Every spring once, as (a, b) with a < b, whichever kernel the model uses (for drawing springs).
template <class T>
std::vector<std::array<int, 2>> spring_pairs(const Model<T>& m);

// Every spring once with its parameters, in the order of spring_pairs(): the edge list the
// implicit, constraint and local/global integrators build their own structures from.
template <class T>
struct SpringList {
  std::vector<std::array<int, 2>> ends;  // (a, b), a < b
  AlignedVector<T> stiffness, rest_length, damping;
  std::size_t size() const { return ends.size(); }
};
template <class T>
SpringList<T> spring_list(const Model<T>& m);

template <class T>
Model<T> build_model(const Scene& scene, SpringKernel kernel = SpringKernel::row_sweep);

}  // namespace clothlab
