// How near cloth comes to cloth, per vertex: the contact view's scalar (docs/contact.md section 7,
// "Seeing contact"). A vertex's gap is the distance of the closest vertex-triangle or edge-edge
// pair it belongs to (the pairs triangle contact keeps apart, sharing no vertex; Bridson, Fedkiw &
// Anderson 2002), except the pairs of one cloth whose triangles' boxes lay within `range` of
// each other at rest (neighbours in the cloth, which its springs keep apart), and `range` where
// no pair is nearer. The vertices of an edge that passes through a triangle, and of that
// triangle, get NaN (drawn in the warning colour): they have crossed, and no distance says how
// far. Independent of the contact code (its own tree and the crossing count's), so the view works
// with contact off.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "sim/contact/intersections.hpp"
#include "sim/contact/triangle_bvh.hpp"

namespace clothlab {

class SolverState;

class ContactGaps {
 public:
  // The triangles and rest positions of `solver` (rebuild when its topology changes).
  explicit ContactGaps(const SolverState& solver);

  std::size_t vertex_count() const { return x_.size(); }

  // One gap per vertex (m) at `xyz` (3 floats per vertex), at most `range`, on `threads` threads
  // (the same values for any count). Allocates nothing once `out` has vertex_count() entries and
  // the thread count and the crossings fit what an earlier call held.
  void per_vertex(const std::vector<float>& xyz, double range, int threads,
                  std::vector<float>& out);

 private:
  // Pieces of the tree's traversal for threads: 2^kTaskDepth nodes and the pairs above them.
  static constexpr int kTaskDepth = 6;
  // Each pair nearer than `range` into its thread's nearest_ (filled with `range` before).
  void nearest_pairs(double range, int threads);

  std::vector<Eigen::Vector3d> x_;  // positions now (at rest when built)
  IntersectionCounter crossings_;
  std::vector<int> triangle_cloth_;
  TriangleBvh bvh_;                        // split between cloths first
  std::vector<int> node_cloth_;            // per node: its cloth, or -1 for several
  std::vector<Box3> rest_boxes_;           // per tree node, its box at rest
  std::vector<Box3> rest_triangle_boxes_;  // per triangle, its box at rest
  std::vector<TriangleBvh::Task> tasks_;
  std::vector<std::vector<float>> nearest_;  // per thread, per vertex
  std::vector<Crossing> crossing_;
};

}  // namespace clothlab
