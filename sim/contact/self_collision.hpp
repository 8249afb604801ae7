// Cloth self-collision (docs/contact.md section 2): vertices are spheres, two vertices of the cloth
// stay at least `thickness` (solver.self_thickness) apart.
//  - Broad phase once per solver step (not per substep): a spatial hash of the vertex positions
//    (Teschner et al. 2003, "Optimized Spatial Hashing for Collision Detection of Deformable
//    Objects"; the dense counting-sort layout of Mueller's "Ten Minute Physics" hash: a cell
//    start array and one entry array, no per-frame allocation) queried with the radius
//    thickness + 2 vmax dt, so two vertices that may meet during the step, each moving at most
//    vmax, are already in the pair list, which every substep of the step reuses.
//  - Skipped pairs: two vertices of the same cloth whose rest distance is under 1.5 thickness
//    or under the longest spring (every spring-connected pair, as the seed rule joins all pairs
//    closer than its longest spring): neighbours in the grid are always that close and their
//    springs already keep them apart. Vertices of different cloths are never skipped.
//  - Response after every substep, after the collider response (docs/contact.md section 1, the same
//    steps as sim/contact/contact_response.hpp, between two moving vertices): along the pair's
//    direction n, the relative normal velocity may close the gap beyond the thickness within the
//    next substep (gap / h) but no more, an inelastic impulse split by inverse mass (a pinned
//    vertex does not move), so a pair cannot pass through itself between two checks
//    (a speculative contact; Bridson, Fedkiw & Anderson 2002 use a repulsion of 0.1 d / dt); then
//    Coulomb friction on the relative tangential velocity with that impulse; then what is still
//    closer than the thickness is pushed apart to it, split by inverse mass, leaving the
//    velocities alone.
//  - Determinism: the hash is filled serially in vertex order and each block of vertices
//    writes its own pairs (in vertex, cell, entry order) into its own slice of the pair buffer,
//    so the pair list does not depend on the thread count; the response visits the pairs
//    serially in that order (Gauss-Seidel, pairs share vertices). The pair buffer is a fixed
//    generous bound (kPairsPerVertex per vertex); pairs beyond it are dropped and counted.
// Vertex-vertex only: a vertex passes between the four vertices of a grid square of another
// layer unless the thickness is at least about 0.71 of the grid spacing (half the square's
// diagonal); min_thickness() reports that bound for the model.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "sim/contact/contact_stats.hpp"
#include "sim/integrators/integrator.hpp"
#include "sim/scene/scene.hpp"

namespace clothlab {

template <class T>
class SelfCollision {
 public:
  // Candidate pairs kept per vertex on average (the buffer's bound).
  static constexpr int kPairsPerVertex = 32;
  // Cloth on cloth (cotton on cotton is about 0.3 to 0.5).
  static constexpr double kFriction = 0.3;

  SelfCollision(const Model<T>& m, const SolverSpec& spec);

  // Once per step of length dt, before its substeps: hashes the positions and collects the
  // pairs closer than thickness + 2 vmax dt.
  void find_pairs(const Model<T>& m, const State<T>& s, double dt, int threads);
  // After a substep of length h: responds to the pairs found. Returns true when it changed some
  // vertex. Serial (see above).
  bool respond(const Model<T>& m, State<T>& s, double h);

  const SelfCollisionStats& last() const { return stats_; }
  double thickness() const { return thickness_; }
  // Two vertices of the same cloth closer than this at rest are never a pair.
  double skip_distance() const { return skip_distance_; }
  // The thickness under which a vertex can slip through a grid square of another layer.
  double min_thickness() const { return min_thickness_; }
  // The pairs found, in response order (for tests): last().pairs of them, block by block.
  struct Pair {
    std::int32_t a = 0, b = 0;  // a < b
  };
  template <class Fn>
  void for_each_pair(Fn&& fn) const {
    for (std::size_t b = 0; b < block_pairs_.size(); ++b)
      for (int k = 0; k < block_pairs_[b]; ++k) fn(pairs_[b * block_capacity_ + std::size_t(k)]);
  }

 private:
  struct Cell {
    std::int32_t x = 0, y = 0, z = 0;
    bool operator==(const Cell&) const = default;
  };
  static const std::array<Cell, 14> kHalfStencil;
  std::uint32_t hash(const Cell& c) const;
  bool skipped(std::size_t i, std::size_t j, const Model<T>& m) const;
  // The steps of find_pairs: the query radius from the fastest vertex, the vertices' cells sorted
  // into the hash's buckets, and each block's pairs.
  double query_radius(const State<T>& s, double dt, int threads);
  void bucket_vertices(const State<T>& s, double inv_cell, int threads);
  void collect_pairs(const Model<T>& m, const State<T>& s, double radius, int threads);

  double thickness_ = 0.0;
  double skip_distance_ = 0.0;
  double min_thickness_ = 0.0;
  std::vector<std::int32_t> cloth_of_;  // per vertex
  // The hash: 2^table_bits_ buckets (at least 2 n), cell_start_[h] .. cell_start_[h + 1] the
  // entries of bucket h. An entry carries its vertex's cell and position, so that a query reads
  // a bucket from one run of memory rather than gathering by vertex index.
  int table_bits_ = 0;
  std::vector<std::int32_t> cell_start_;
  struct Entry {
    Cell cell;
    std::int32_t vertex = 0;
    T x = 0, y = 0, z = 0;
  };
  std::vector<Entry> entries_;
  std::vector<Cell> cell_;  // per vertex: its cell this step
  std::vector<std::uint32_t> bucket_;
  std::vector<double> block_speed2_;  // per block: the largest squared speed
  // Pairs: block b owns pairs_[b * block_capacity_, + block_pairs_[b]).
  std::size_t block_capacity_ = 0;
  std::vector<Pair> pairs_;
  std::vector<int> block_pairs_, block_dropped_;
  SelfCollisionStats stats_;
};

extern template class SelfCollision<float>;
extern template class SelfCollision<double>;

}  // namespace clothlab
