// A bounding-volume hierarchy over a cloth's triangles for contact's broad phase (docs/contact.md
// section 7). Built once from the rest shape (median splits of the triangles' centroids along the
// widest axis), so each node is a patch of material; each substep refits the boxes bottom-up from
// the current (swept, padded) triangle boxes. A patch's box is bounded by its material size
// however the cloth folds, which is why a refitted material-space tree stays useful (the classic
// cloth choice: Volino & Magnenat-Thalmann 1994; Bridson et al. 2002 section 5).
// The self traversal (a node against itself: its two children each against themselves and
// against each other) reports every unordered pair of distinct triangles whose boxes meet, in an
// order fixed by the tree, so results do not depend on the thread count; the callback returns
// false to stop it. A cull may skip whole nodes, which then report no pair within them (a patch
// that cannot touch itself, sim/contact/flat_patches.hpp), and pairs of nodes, which then report
// no pair between them; pairs between a skipped node and the rest are still reported.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "sim/core/parallel.hpp"

namespace clothlab {

struct Box3 {
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
  bool overlaps(const Box3& o) const {
    return lo.x() <= o.hi.x() && o.lo.x() <= hi.x() && lo.y() <= o.hi.y() && o.lo.y() <= hi.y() &&
           lo.z() <= o.hi.z() && o.lo.z() <= hi.z();
  }
  double half_area() const {
    const Eigen::Vector3d d = hi - lo;
    return d.x() * d.y() + d.y() * d.z() + d.z() * d.x();
  }
};

// The box of each triangle at positions x, grown by `pad` on every side, into boxes (one per
// triangle, already sized): the leaf boxes of a tree over exact triangles.
void fill_triangle_boxes(const std::vector<std::array<int, 3>>& triangles,
                         const std::vector<Eigen::Vector3d>& x, double pad,
                         std::vector<Box3>& boxes);

class TriangleBvh {
 public:
  TriangleBvh() = default;
  // centroids: one per triangle, in the shape the hierarchy is cut from. groups (empty, or one
  // per triangle): the nodes first split between groups (cloths), so each cloth has its own
  // subtrees, then by centroid.
  explicit TriangleBvh(const std::vector<Eigen::Vector3d>& centroids,
                       const std::vector<int>& groups = {});

  std::size_t triangle_count() const { return leaf_boxes_.size(); }
  // The leaf boxes to fill before refit(): box(t) for triangle t.
  std::vector<Box3>& leaf_boxes() { return leaf_boxes_; }
  // Every inner node's box as the union of its children's (children come after their parent).
  void refit();
  const Box3& root_box() const { return nodes_.front().box; }
  const Box3& node_box(int n) const { return nodes_[std::size_t(n)].box; }

  // fn(ta, tb) for every pair of distinct triangles whose boxes meet, each once, until fn
  // returns false. Returns false when stopped.
  template <class Fn>
  bool self_pairs(Fn&& fn) const {
    return nodes_.empty() || self(0, NoCull{}, fn);
  }

  // The nodes, pre-order (the root is 0): each covers the triangles triangles(n), its children's
  // ranges side by side.
  std::size_t node_count() const { return nodes_.size(); }
  int left(int n) const { return nodes_[std::size_t(n)].left; }
  int right(int n) const { return nodes_[std::size_t(n)].right; }
  int parent(int n) const { return nodes_[std::size_t(n)].parent; }
  const int* triangles_begin(int n) const { return order_.data() + nodes_[std::size_t(n)].begin; }
  const int* triangles_end(int n) const { return order_.data() + nodes_[std::size_t(n)].end; }

  // The same traversal cut into independent pieces for threads: the nodes `depth` levels down
  // each against themselves, and the pairs of siblings above them against each other, each such
  // pair cut again into the pairs of their descendants down to that depth (two cloths against
  // each other are one pair of siblings at the root: uncut, it was one piece holding most of
  // the work). The pieces report every pair self_pairs does, each once; run in the listed
  // order, in an order that depends on the tree alone.
  struct Task {
    int a = 0, b = 0;  // a == b: node a against itself
    int within = 0;  // the node the piece lies in (a, or the siblings' parent a and b descend from)
  };
  // A pair is cut only while its two nodes hold at least min_pair_triangles triangles together
  // (each piece costs a little to start: a small cloth's pieces would cost more than they gain).
  std::vector<Task> tasks(int depth, int min_pair_triangles = 0) const;
  // cull.self(n): node n reports no pair within itself (nor do the nodes under it);
  // cull.pair(a, b): nodes a and b report no pair between them (nor do the nodes under them: a
  // cull must then hold for every pair of their descendants too, since a piece may start below).
  struct NoCull {
    bool self(int) const { return false; }
    bool pair(int, int) const { return false; }
  };
  template <class Cull, class Fn>
  bool run(const Task& t, const Cull& cull, Fn&& fn) const {
    for (int n = t.within; n >= 0; n = parent(n))
      if (cull.self(n)) return true;
    return t.a == t.b ? self(t.a, cull, fn) : pair(t.a, t.b, cull, fn);
  }

 private:
  struct Node {
    Box3 box;
    int left = -1, right = -1;  // children; -1 for a leaf
    int parent = -1;            // -1 for the root
    int triangle = -1;          // the leaf's triangle
    int begin = 0, end = 0;     // its triangles: order_[begin, end)
  };
  void split(int n, int depth, int min_pair, std::vector<Task>& out) const;
  void split_pair(int a, int b, int depth, int within, int min_pair, std::vector<Task>& out) const;
  int build(std::vector<int>& order, std::size_t begin, std::size_t end,
            const std::vector<Eigen::Vector3d>& centroids, const std::vector<int>& groups);
  // A split of order[begin, end) between groups nearest its middle; 0 when it holds one group.
  void link(int parent, int left, int right);
  static std::size_t group_split(std::vector<int>& order, std::size_t begin, std::size_t end,
                                 const std::vector<int>& groups);

  template <class Cull, class Fn>
  bool self(int n, const Cull& cull, Fn& fn) const {
    const Node& node = nodes_[std::size_t(n)];
    if (node.left < 0 || cull.self(n)) return true;
    return self(node.left, cull, fn) && self(node.right, cull, fn) &&
           pair(node.left, node.right, cull, fn);
  }
  template <class Cull, class Fn>
  bool pair(int a, int b, const Cull& cull, Fn& fn) const {
    const Node& na = nodes_[std::size_t(a)];
    const Node& nb = nodes_[std::size_t(b)];
    if (!na.box.overlaps(nb.box) || cull.pair(a, b)) return true;
    const bool leaf_a = na.left < 0, leaf_b = nb.left < 0;
    if (leaf_a && leaf_b) return fn(na.triangle, nb.triangle);
    if (leaf_a || (!leaf_b && nb.box.half_area() > na.box.half_area()))
      return pair(a, nb.left, cull, fn) && pair(a, nb.right, cull, fn);
    return pair(na.left, b, cull, fn) && pair(na.right, b, cull, fn);
  }

  std::vector<Node> nodes_;  // pre-order: the root first, a parent before its children
  std::vector<int> order_;   // the triangles in the order the nodes' ranges cover them
  std::vector<Box3> leaf_boxes_;
};

}  // namespace clothlab
