#include "sim/contact/triangle_bvh.hpp"

#include <algorithm>

namespace clothlab {

TriangleBvh::TriangleBvh(const std::vector<Eigen::Vector3d>& centroids,
                         const std::vector<int>& groups) {
  const std::size_t count = centroids.size();
  leaf_boxes_.assign(count, Box3{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()});
  if (count == 0) return;
  nodes_.reserve(2 * count - 1);
  order_.resize(count);
  for (std::size_t t = 0; t < count; ++t) order_[t] = int(t);
  build(order_, 0, count, centroids, groups);
}

// Median split along the widest axis of the centroids' box; ties broken by triangle index, so the
// tree depends on nothing but the rest shape.
std::size_t TriangleBvh::group_split(std::vector<int>& order, std::size_t begin, std::size_t end,
                                     const std::vector<int>& groups) {
  if (groups.empty()) return 0;
  const auto first = order.begin() + long(begin), last = order.begin() + long(end);
  const auto by_group = [&](int a, int b) {
    const int ga = groups[std::size_t(a)], gb = groups[std::size_t(b)];
    return ga < gb || (ga == gb && a < b);
  };
  if (std::all_of(first, last,
                  [&](int t) { return groups[std::size_t(t)] == groups[std::size_t(*first)]; }))
    return 0;
  std::sort(first, last, by_group);
  // The group boundary nearest the middle.
  const std::size_t mid = begin + (end - begin) / 2;
  std::size_t best = 0;
  for (std::size_t k = begin + 1; k < end; ++k)
    if (groups[std::size_t(order[k])] != groups[std::size_t(order[k - 1])] &&
        (best == 0 || (k > mid ? k - mid : mid - k) < (best > mid ? best - mid : mid - best)))
      best = k;
  return best;
}

int TriangleBvh::build(std::vector<int>& order, std::size_t begin, std::size_t end,
                       const std::vector<Eigen::Vector3d>& centroids,
                       const std::vector<int>& groups) {
  const int index = int(nodes_.size());
  nodes_.push_back(Node{});
  nodes_.back().begin = int(begin);
  nodes_.back().end = int(end);
  if (end - begin == 1) {
    nodes_.back().triangle = order[begin];
    return index;
  }
  if (const std::size_t split = group_split(order, begin, end, groups); split != 0) {
    const int left = build(order, begin, split, centroids, groups);
    const int right = build(order, split, end, centroids, groups);
    link(index, left, right);
    return index;
  }
  Eigen::Vector3d lo = centroids[std::size_t(order[begin])], hi = lo;
  for (std::size_t k = begin + 1; k < end; ++k) {
    lo = lo.cwiseMin(centroids[std::size_t(order[k])]);
    hi = hi.cwiseMax(centroids[std::size_t(order[k])]);
  }
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  const std::size_t mid = begin + (end - begin) / 2;
  std::nth_element(order.begin() + long(begin), order.begin() + long(mid),
                   order.begin() + long(end), [&](int a, int b) {
                     const double ca = centroids[std::size_t(a)][axis];
                     const double cb = centroids[std::size_t(b)][axis];
                     return ca < cb || (ca == cb && a < b);
                   });
  const int left = build(order, begin, mid, centroids, groups);
  const int right = build(order, mid, end, centroids, groups);
  link(index, left, right);
  return index;
}

void TriangleBvh::link(int parent, int left, int right) {
  nodes_[std::size_t(parent)].left = left;
  nodes_[std::size_t(parent)].right = right;
  nodes_[std::size_t(left)].parent = nodes_[std::size_t(right)].parent = parent;
}

void fill_triangle_boxes(const std::vector<std::array<int, 3>>& triangles,
                         const std::vector<Eigen::Vector3d>& x, double pad,
                         std::vector<Box3>& boxes) {
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Eigen::Vector3d &a = x[std::size_t(triangles[t][0])],
                          &b = x[std::size_t(triangles[t][1])],
                          &c = x[std::size_t(triangles[t][2])];
    boxes[t] = {a.cwiseMin(b).cwiseMin(c).array() - pad, a.cwiseMax(b).cwiseMax(c).array() + pad};
  }
}

std::vector<TriangleBvh::Task> TriangleBvh::tasks(int depth, int min_pair_triangles) const {
  std::vector<Task> out;
  if (!nodes_.empty()) split(0, depth, min_pair_triangles, out);
  return out;
}

// self(n) = self(left), self(right), pair(left, right), unrolled `depth` levels.
void TriangleBvh::split(int n, int depth, int min_pair, std::vector<Task>& out) const {
  const Node& node = nodes_[std::size_t(n)];
  if (depth == 0 || node.left < 0) {
    out.push_back({n, n, n});
    return;
  }
  split(node.left, depth - 1, min_pair, out);
  split(node.right, depth - 1, min_pair, out);
  split_pair(node.left, node.right, depth - 1, n, min_pair, out);
}

// pair(a, b) = the four pairs of their children, unrolled `depth` levels (or to a leaf, or to
// pairs smaller than min_pair triangles). Each piece tests its own boxes: an overlap of
// descendants implies one of their ancestors.
void TriangleBvh::split_pair(int a, int b, int depth, int within, int min_pair,
                             std::vector<Task>& out) const {
  const Node &na = nodes_[std::size_t(a)], &nb = nodes_[std::size_t(b)];
  if (depth == 0 || na.left < 0 || nb.left < 0 ||
      (na.end - na.begin) + (nb.end - nb.begin) < min_pair) {
    out.push_back({a, b, within});
    return;
  }
  for (int ca : {na.left, na.right})
    for (int cb : {nb.left, nb.right}) split_pair(ca, cb, depth - 1, within, min_pair, out);
}

void TriangleBvh::refit() {
  for (std::size_t k = nodes_.size(); k-- > 0;) {
    Node& node = nodes_[k];
    if (node.left < 0) {
      node.box = leaf_boxes_[std::size_t(node.triangle)];
    } else {
      const Box3& a = nodes_[std::size_t(node.left)].box;
      const Box3& b = nodes_[std::size_t(node.right)].box;
      node.box = {a.lo.cwiseMin(b.lo), a.hi.cwiseMax(b.hi)};
    }
  }
}

}  // namespace clothlab
