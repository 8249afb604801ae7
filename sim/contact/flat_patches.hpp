// Normal-cone culling for cloth contact (docs/contact.md section 7.3; Volino & Magnenat-Thalmann
// 1994, with the swept normals of Tang et al. 2009). A patch of the contact tree is skipped by the
// broad phase, within itself (not against the rest), while it provably cannot touch itself:
//  - it is a disk of material (sim/contact/patch_topology.hpp);
//  - over the substep's straight motion from x0 to x1 every triangle's normal keeps a positive
//    component along the patch's axis: the normal of a moving triangle is a quadratic in time whose
//    Bernstein coefficients n(x0), (e1(x0) x e2(x1) + e1(x1) x e2(x0)) / 2 and n(x1) bound it,
//    so all three must clear a bound along the axis;
//  - the rim, projected onto the plane across the axis, never touches itself during the substep:
//    each rim edge sweeps a region inside the hull of its four end positions (the common motion
//    of the rim taken away, which changes nothing), and the hulls of rim edges that share no
//    vertex are separated along one of their edge normals or the plane's axes, by a margin.
// Then the projection maps the patch one-to-one onto the plane at every instant of the substep
// (positive orientation everywhere and a simple rim: the degree of the map is 1 inside the rim),
// so no two of its points meet: no crossing and no contact within it. A flat or gently curved
// sheet is one patch and costs one pass over its triangles a substep instead of its pairs.
// Patches are chosen when the pairs are collected with every normal within 60 degrees of the
// axis (clearing half the rest area), and kept while every normal clears a tenth of it (about 84
// degrees); the pairs are collected again when a kept patch fails that.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "sim/contact/patch_topology.hpp"
#include "sim/core/vec3_array.hpp"

namespace clothlab {

template <class T>
class FlatPatches {
 public:
  static constexpr double kChooseBound = 0.5;  // of each triangle's rest area (times two)
  static constexpr double kKeepBound = 0.1;
  // Smaller nodes are never skipped (their few pairs cost less than the test).
  static constexpr std::size_t kMinTriangles = 16;
  // Patches whose rims are worth a second thread (a rim's test takes microseconds).
  static constexpr std::size_t kParallelRims = 16;

  // margin: m, how far apart in the plane the rim's edges must stay.
  FlatPatches(const TriangleBvh& bvh, const SurfaceFeatures& f, const Vec3Array<T>& rest,
              double margin);

  // Chooses the topmost nodes that are flat over the motion x0 -> x1.
  void choose(const TriangleBvh& bvh, const SurfaceFeatures& f, const Vec3Array<T>& x0,
              const Vec3Array<T>& x1, int threads);
  // None chosen.
  void clear();
  // Whether every chosen patch is still flat over the motion x0 -> x1.
  bool still_flat(const SurfaceFeatures& f, const Vec3Array<T>& x0, const Vec3Array<T>& x1,
                  int threads);

  bool skipped(int node) const { return chosen_[std::size_t(node)] != 0; }
  // The chosen patch that holds the triangle, or -1.
  std::int32_t patch_of(int t) const { return patch_of_[std::size_t(t)]; }
  bool covers_all() const { return !chosen_.empty() && chosen_.front() != 0; }
  std::size_t patch_count() const { return patches_.size(); }
  std::size_t triangles_covered() const { return work_.size(); }

 private:
  using Axis = Eigen::Matrix<T, 3, 1>;
  struct Patch {
    int node = 0;
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  };
  struct RimEdge {
    std::array<double, 2> lo{}, hi{};
    std::array<std::int32_t, 2> v{};
    std::array<Eigen::Vector2d, 4>
        p;  // a and b at x0, then at x1 (the rim's mean motion taken away)
  };
  void visit(int node, std::size_t hint, const TriangleBvh& bvh, const SurfaceFeatures& f,
             const Vec3Array<T>& x0, const Vec3Array<T>& x1, int threads);
  template <class Fails>
  std::size_t first_failure(std::size_t size, int threads, const Fails& fails);
  void choose_node(int node, const Eigen::Vector3d& axis, const SurfaceFeatures& f,
                   const int* begin, std::size_t size);
  void node_normals(const TriangleBvh& bvh, const SurfaceFeatures& f, const Vec3Array<T>& x,
                    int threads);
  bool clears(const std::array<int, 3>& t, const Axis& axis, T bound, const Vec3Array<T>& x0,
              const Vec3Array<T>& x1) const;
  // Whether the chosen triangles [lo, hi) of work_ all clear their keep bound (clears(), one
  // vector lane a triangle: no early exit, the block fails or passes as a whole).
  bool block_clears(std::size_t lo, std::size_t hi, const Vec3Array<T>& x0,
                    const Vec3Array<T>& x1) const;
  bool rim_simple(int node, const Eigen::Vector3d& axis, const Vec3Array<T>& x0,
                  const Vec3Array<T>& x1, std::vector<RimEdge>& rim) const;
  // Whether every patch's rim stays simple (rim_simple), the patches shared among the threads.
  bool rims_simple(const Vec3Array<T>& x0, const Vec3Array<T>& x1, int threads);
  bool apart(const RimEdge& a, const RimEdge& b) const;

  PatchTopology topology_;
  std::vector<T> rest_area2_;  // per triangle: |n| at rest (twice its area)
  double margin_ = 0.0;
  std::vector<std::uint8_t> chosen_;          // per node
  std::vector<Eigen::Vector3d> node_normal_;  // per node: its triangles' normals summed (x1)
  std::vector<Patch> patches_;
  std::vector<std::int32_t> work_;  // the chosen patches' triangles
  // The same, as the test every substep reads them: each triangle's vertices, its patch's axis
  // and its keep bound, one array each.
  std::array<std::vector<std::int32_t>, 3> work_vertex_;
  std::array<std::vector<T>, 3> work_axis_;
  std::vector<T> work_bound_;
  std::vector<std::int32_t> patch_of_;      // per triangle: its chosen patch, or -1
  std::vector<std::uint8_t> block_ok_;      // per block of a parallel test
  std::vector<std::size_t> block_failure_;  // per block: its first failing triangle
  std::vector<std::vector<RimEdge>> rims_;  // per thread: scratch for one rim
  std::size_t longest_rim_ = 0;
};

extern template class FlatPatches<float>;
extern template class FlatPatches<double>;

}  // namespace clothlab
