#include "sim/contact/flat_patches.hpp"

#include <omp.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <cmath>

#include "sim/core/parallel.hpp"
#include "sim/core/vec3_eigen.hpp"

namespace clothlab {
namespace {

using V3 = Eigen::Vector3d;
using V2 = Eigen::Vector2d;

// The three Bernstein coefficients of a moving triangle's normal along the axis (a, its edges
// e and f from its first vertex at x0 and at x1), each against the bound: axis . (e x f) =
// e . (f x axis). In the solver's scalar; one lane a triangle in block_clears.
template <class T>
[[gnu::always_inline]] inline bool coefficients_clear(T e0x, T e0y, T e0z, T f0x, T f0y, T f0z,
                                                      T e1x, T e1y, T e1z, T f1x, T f1y, T f1z,
                                                      T ax, T ay, T az, T bound) {
  const T g0x = f0y * az - f0z * ay, g0y = f0z * ax - f0x * az, g0z = f0x * ay - f0y * ax;
  const T g1x = f1y * az - f1z * ay, g1y = f1z * ax - f1x * az, g1z = f1x * ay - f1y * ax;
  const T c0 = e0x * g0x + e0y * g0y + e0z * g0z;
  const T c1 = e1x * g1x + e1y * g1y + e1z * g1z;
  const T cm = T(0.5) * ((e0x * g1x + e0y * g1y + e0z * g1z) + (e1x * g0x + e1y * g0y + e1z * g0z));
  return (c0 >= bound) & (c1 >= bound) & (cm >= bound);
}

template <class T>
V3 normal_at(const std::array<int, 3>& t, const Vec3Array<T>& x) {
  const V3 a = load3(x, std::size_t(t[0]));
  return (load3(x, std::size_t(t[1])) - a).cross(load3(x, std::size_t(t[2])) - a);
}

}  // namespace

template <class T>
FlatPatches<T>::FlatPatches(const TriangleBvh& bvh, const SurfaceFeatures& f,
                            const Vec3Array<T>& rest, double margin)
    : topology_(patch_topology(bvh, f, rest.size())), margin_(margin) {
  rest_area2_.resize(f.triangles.size());
  for (std::size_t t = 0; t < f.triangles.size(); ++t)
    rest_area2_[t] = T(normal_at(f.triangles[t], rest).norm());
  chosen_.assign(bvh.node_count(), 0);
  node_normal_.assign(bvh.node_count(), V3::Zero());
  patches_.reserve(bvh.node_count());
  work_.reserve(f.triangles.size());
  for (auto& v : work_vertex_) v.reserve(f.triangles.size());
  for (auto& a : work_axis_) a.reserve(f.triangles.size());
  work_bound_.reserve(f.triangles.size());
  patch_of_.assign(f.triangles.size(), -1);
  block_ok_.assign(block_count(f.triangles.size()), 1);
  block_failure_.assign(block_count(f.triangles.size()), 0);
  for (std::size_t n = 0; n + 1 < topology_.rim_begin.size(); ++n)
    longest_rim_ =
        std::max(longest_rim_, std::size_t(topology_.rim_begin[n + 1] - topology_.rim_begin[n]));
  rims_.resize(1);
  rims_[0].reserve(longest_rim_);
}

template <class T>
void FlatPatches<T>::clear() {
  for (const Patch& p : patches_) chosen_[std::size_t(p.node)] = 0;
  for (const std::int32_t t : work_) patch_of_[std::size_t(t)] = -1;
  patches_.clear();
  work_.clear();
  for (auto& v : work_vertex_) v.clear();
  for (auto& a : work_axis_) a.clear();
  work_bound_.clear();
}

// Each node's normals summed at x (its axis), bottom-up: children come after their parents.
template <class T>
void FlatPatches<T>::node_normals(const TriangleBvh& bvh, const SurfaceFeatures& f,
                                  const Vec3Array<T>& x, int threads) {
  const std::size_t nodes = bvh.node_count();
  for_each_block(nodes, threads_for(nodes, threads), [&](std::size_t begin, std::size_t end) {
    for (std::size_t n = begin; n < end; ++n)
      if (bvh.left(int(n)) < 0)
        node_normal_[n] = normal_at(f.triangles[std::size_t(*bvh.triangles_begin(int(n)))], x);
  });
  for (std::size_t n = nodes; n-- > 0;)
    if (bvh.left(int(n)) >= 0)
      node_normal_[n] = node_normal_[std::size_t(bvh.left(int(n)))] +
                        node_normal_[std::size_t(bvh.right(int(n)))];
}

template <class T>
void FlatPatches<T>::choose(const TriangleBvh& bvh, const SurfaceFeatures& f,
                            const Vec3Array<T>& x0, const Vec3Array<T>& x1, int threads) {
  clear();
  if (bvh.node_count() == 0) return;
  node_normals(bvh, f, x1, threads);
  visit(0, std::size_t(-1), bvh, f, x0, x1, threads);
}

// Top-down: a node flat over the motion is chosen (and nothing under it); otherwise its children
// are tried. `hint` is the position (in the tree's triangle order) of a triangle that failed the
// parent: tested first, it usually fails the child that holds it at once (a crease stays where
// it is), so a node that is not flat rarely costs a pass over its triangles.
template <class T>
void FlatPatches<T>::visit(int node, std::size_t hint, const TriangleBvh& bvh,
                           const SurfaceFeatures& f, const Vec3Array<T>& x0, const Vec3Array<T>& x1,
                           int threads) {
  const int* begin = bvh.triangles_begin(node);
  const std::size_t size = std::size_t(bvh.triangles_end(node) - begin);
  if (size < kMinTriangles) return;
  const std::size_t first = std::size_t(begin - bvh.triangles_begin(0));
  const V3 sum = node_normal_[std::size_t(node)];
  std::size_t failed = hint;
  if (topology_.disk[std::size_t(node)] && sum.squaredNorm() > 0.0) {
    const V3 axis = sum.normalized();
    const Axis axis_t = axis.cast<T>();
    const auto fails = [&](std::size_t k) {
      return !clears(f.triangles[std::size_t(begin[k])], axis_t,
                     T(kChooseBound) * rest_area2_[std::size_t(begin[k])], x0, x1);
    };
    if (hint >= first && hint < first + size && fails(hint - first)) {
      failed = hint;
    } else {
      failed = first + first_failure(size, threads, fails);
      if (failed == first + size && rim_simple(node, axis, x0, x1, rims_[0])) {
        choose_node(node, axis, f, begin, size);
        return;
      }
    }
  }
  if (bvh.left(node) < 0) return;
  visit(bvh.left(node), failed, bvh, f, x0, x1, threads);
  visit(bvh.right(node), failed, bvh, f, x0, x1, threads);
}

// The first k in [0, size) with fails(k), or size: blocks in parallel, each to its first failure.
template <class T>
template <class Fails>
std::size_t FlatPatches<T>::first_failure(std::size_t size, int threads, const Fails& fails) {
  for_each_block_indexed(size, threads_for(size, threads),
                         [&](std::size_t b, std::size_t lo, std::size_t hi) {
                           std::size_t k = lo;
                           while (k < hi && !fails(k)) ++k;
                           block_failure_[b] = k < hi ? k : size;
                         });
  return *std::min_element(block_failure_.begin(),
                           block_failure_.begin() + long(block_count(size)));
}

template <class T>
void FlatPatches<T>::choose_node(int node, const V3& axis, const SurfaceFeatures& f,
                                 const int* begin, std::size_t size) {
  chosen_[std::size_t(node)] = 1;
  const auto patch = std::int32_t(patches_.size());
  patches_.push_back({node, axis});
  const Axis axis_t = axis.cast<T>();
  for (std::size_t k = 0; k < size; ++k) {
    const auto t = std::size_t(begin[k]);
    work_.push_back(begin[k]);
    patch_of_[t] = patch;
    for (std::size_t j = 0; j < 3; ++j) {
      work_vertex_[j].push_back(f.triangles[t][j]);
      work_axis_[j].push_back(axis_t[long(j)]);
    }
    work_bound_.push_back(T(kKeepBound) * rest_area2_[t]);
  }
}

template <class T>
bool FlatPatches<T>::still_flat(const SurfaceFeatures& f, const Vec3Array<T>& x0,
                                const Vec3Array<T>& x1, int threads) {
  if (patches_.empty()) return true;
  for_each_block_indexed(work_.size(), contact_threads(work_.size(), threads),
                         [&](std::size_t b, std::size_t lo, std::size_t hi) {
                           block_ok_[b] = block_clears(lo, hi, x0, x1) ? 1 : 0;
                         });
  if (!std::all_of(block_ok_.begin(), block_ok_.begin() + long(block_count(work_.size())),
                   [](std::uint8_t ok) { return ok != 0; }))
    return false;
  return rims_simple(x0, x1, threads);
}

// The rims of the patches in parallel (dynamic: their lengths differ), each thread with its own
// scratch; all stop once one fails. Whether all pass is the same for any thread count.
template <class T>
bool FlatPatches<T>::rims_simple(const Vec3Array<T>& x0, const Vec3Array<T>& x1, int threads) {
  const int team = threads_for(patches_.size(), threads, kParallelRims);
  while (rims_.size() < std::size_t(team)) {  // once, the first time a team is this large
    rims_.emplace_back();
    rims_.back().reserve(longest_rim_);
  }
  std::atomic<bool> failed{false};
  const long count = long(patches_.size());
  run_team(team, [&] {
    std::vector<RimEdge>& rim = rims_[std::size_t(omp_get_thread_num())];
#pragma omp for schedule(dynamic, 4)
    for (long k = 0; k < count; ++k) {
      if (failed.load(std::memory_order_relaxed)) continue;
      const Patch& p = patches_[std::size_t(k)];
      if (!rim_simple(p.node, p.axis, x0, x1, rim)) failed.store(true, std::memory_order_relaxed);
    }
  });
  return !failed.load();
}

// The three Bernstein coefficients of the triangle's normal along the axis over the motion
// x0 -> x1 (its normal at time s is n0 (1-s)^2 + 2 m s (1-s) + n1 s^2): each must clear the bound.
template <class T>
bool FlatPatches<T>::clears(const std::array<int, 3>& t, const Axis& axis, T bound,
                            const Vec3Array<T>& x0, const Vec3Array<T>& x1) const {
  const auto at = [](const Vec3Array<T>& x, int i) {
    return Axis(x.x[std::size_t(i)], x.y[std::size_t(i)], x.z[std::size_t(i)]);
  };
  const Axis a0 = at(x0, t[0]), a1 = at(x1, t[0]);
  const Axis e0 = at(x0, t[1]) - a0, f0 = at(x0, t[2]) - a0;
  const Axis e1 = at(x1, t[1]) - a1, f1 = at(x1, t[2]) - a1;
  return coefficients_clear(e0.x(), e0.y(), e0.z(), f0.x(), f0.y(), f0.z(), e1.x(), e1.y(), e1.z(),
                            f1.x(), f1.y(), f1.z(), axis.x(), axis.y(), axis.z(), bound);
}

template <class T>
bool FlatPatches<T>::block_clears(std::size_t lo, std::size_t hi, const Vec3Array<T>& x0,
                                  const Vec3Array<T>& x1) const {
  const std::int32_t* __restrict va = work_vertex_[0].data();
  const std::int32_t* __restrict vb = work_vertex_[1].data();
  const std::int32_t* __restrict vc = work_vertex_[2].data();
  const T* __restrict ax = work_axis_[0].data();
  const T* __restrict ay = work_axis_[1].data();
  const T* __restrict az = work_axis_[2].data();
  const T* __restrict bound = work_bound_.data();
  const T* __restrict px = x0.x.data();
  const T* __restrict py = x0.y.data();
  const T* __restrict pz = x0.z.data();
  const T* __restrict qx = x1.x.data();
  const T* __restrict qy = x1.y.data();
  const T* __restrict qz = x1.z.data();
  int ok = 1;
#pragma omp simd reduction(& : ok)
  for (std::size_t k = lo; k < hi; ++k) {
    const std::int32_t a = va[k], b = vb[k], c = vc[k];
    ok &= int(coefficients_clear(px[b] - px[a], py[b] - py[a], pz[b] - pz[a], px[c] - px[a],
                                 py[c] - py[a], pz[c] - pz[a], qx[b] - qx[a], qy[b] - qy[a],
                                 qz[b] - qz[a], qx[c] - qx[a], qy[c] - qy[a], qz[c] - qz[a], ax[k],
                                 ay[k], az[k], bound[k]));
  }
  return ok != 0;
}

// Whether the node's rim, projected onto the plane across the axis, stays clear of itself over
// the motion: rim edges that share no vertex and whose boxes meet are tested for a separating
// line (sort and sweep along the plane's first axis).
template <class T>
bool FlatPatches<T>::rim_simple(int node, const V3& axis, const Vec3Array<T>& x0,
                                const Vec3Array<T>& x1, std::vector<RimEdge>& rim) const {
  const std::size_t begin = std::size_t(topology_.rim_begin[std::size_t(node)]);
  const std::size_t end = std::size_t(topology_.rim_begin[std::size_t(node) + 1]);
  const V3 u = axis.unitOrthogonal(), w = axis.cross(u);
  V3 motion = V3::Zero();
  for (std::size_t k = begin; k < end; ++k)
    for (std::int32_t v : topology_.rim[k])
      motion += load3(x1, std::size_t(v)) - load3(x0, std::size_t(v));
  motion /= double(2 * (end - begin));
  const auto plane = [&](const V3& x) { return V2(u.dot(x), w.dot(x)); };
  rim.clear();
  for (std::size_t k = begin; k < end; ++k) {
    RimEdge e;
    e.v = topology_.rim[k];
    for (std::size_t j = 0; j < 2; ++j) {
      e.p[j] = plane(load3(x0, std::size_t(e.v[j])));
      e.p[2 + j] = plane(load3(x1, std::size_t(e.v[j])) - motion);
    }
    e.lo = {e.p[0].x(), e.p[0].y()};
    e.hi = e.lo;
    for (const V2& p : e.p)
      for (std::size_t a = 0; a < 2; ++a) {
        e.lo[a] = std::min(e.lo[a], p[long(a)]);
        e.hi[a] = std::max(e.hi[a], p[long(a)]);
      }
    rim.push_back(e);
  }
  std::sort(rim.begin(), rim.end(),
            [](const RimEdge& a, const RimEdge& b) { return a.lo[0] < b.lo[0]; });
  for (std::size_t i = 0; i < rim.size(); ++i)
    for (std::size_t j = i + 1; j < rim.size() && rim[j].lo[0] <= rim[i].hi[0] + margin_; ++j) {
      const RimEdge &a = rim[i], &b = rim[j];
      const bool touch =
          a.v[0] == b.v[0] || a.v[0] == b.v[1] || a.v[1] == b.v[0] || a.v[1] == b.v[1];
      if (touch || a.lo[1] > b.hi[1] + margin_ || b.lo[1] > a.hi[1] + margin_) continue;
      if (!apart(a, b)) return false;
    }
  return true;
}

// Whether the hulls of two rim edges' end positions are separated, by the margin, along one of the
// edges at x0 or at x1 or across it (the edges of a straight rim are apart along it).
template <class T>
bool FlatPatches<T>::apart(const RimEdge& a, const RimEdge& b) const {
  const std::array<V2, 4> directions = {a.p[1] - a.p[0], a.p[3] - a.p[2], b.p[1] - b.p[0],
                                        b.p[3] - b.p[2]};
  for (std::size_t k = 0; k < 8; ++k) {
    const V2& d = directions[k / 2];
    const double len = d.norm();
    if (len == 0.0) continue;
    const V2 n = k % 2 == 0 ? V2(d / len) : V2(-d.y() / len, d.x() / len);
    double a_lo = n.dot(a.p[0]), a_hi = a_lo, b_lo = n.dot(b.p[0]), b_hi = b_lo;
    for (std::size_t j = 1; j < 4; ++j) {
      a_lo = std::min(a_lo, n.dot(a.p[j]));
      a_hi = std::max(a_hi, n.dot(a.p[j]));
      b_lo = std::min(b_lo, n.dot(b.p[j]));
      b_hi = std::max(b_hi, n.dot(b.p[j]));
    }
    if (a_hi + margin_ < b_lo || b_hi + margin_ < a_lo) return true;
  }
  return false;
}

template class FlatPatches<float>;
template class FlatPatches<double>;

}  // namespace clothlab
