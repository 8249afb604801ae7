// Cloth against cloth, within a cloth and between cloths, with triangles (docs/contact.md section
// 7; solver.cloth_contact). After every pass, on the positions x1 and velocities the integrator
// (and the colliders) made from the pass's start x0. A pass is one substep, or several while no
// vertex moves fast relative to the rest (pass_span); below, "substep" means the pass:
//  1. Broad phase: a material-space tree over the triangles (sim/contact/triangle_bvh.hpp)
//     refitted to each triangle's box swept from x0 to x1 yields the pairs of triangles within
//     a thickness, and of those the vertex-triangle and edge-edge pairs (each once,
//     sim/contact/surface_features.hpp) whose distance there is within the thickness and a skin
//     on each side (a Verlet list, Verlet 1967; each vertex its own skin, allow_): the pairs stay
//     valid, and the broad phase is skipped, for as long as no vertex strays beyond its skin from
//     where they were collected once the best rigid motion of all vertices is taken away (a rigid
//     motion changes no distance), so a pile at rest and a sheet falling or swinging as one are
//     collected once in many substeps.
//  2. Proximity (Bridson, Fedkiw & Anderson 2002, section 7.1; as position constraints, Mueller
//     et al. 2007 section 4.4): a pair closer than the thickness is pushed apart to it along the
//     direction between its closest points, taken on the side the pair was at x0 when it has
//     passed through since, split by inverse mass with the closest points' weights (none to a
//     vertex a collider holds, into that collider: sim/contact/collider_touches.hpp), with Coulomb
//     friction on the pair's relative tangential motion. Gauss-Seidel over the pairs in their
//     fixed order, kProximityIterations sweeps. Velocities take the position change over h.
//     A tangle beyond kMaxPairsPerTriangle or kMaxPairs (an exploding cloth) undoes the whole
//     substep (after a try with the least skins): every free vertex returns to x0 with zero
//     velocity, which keeps the guarantee at a bounded cost.
//  3. Fail-safe (the no-crossing guarantee): each pair's straight motion from x0 to its final
//     x1 is tested with conservative continuous collision detection (sim/contact/ccd.hpp: does it
//     come within eta of contact, give or take eta, with eta a hundredth of the thickness); the
//     vertices of a pair that would meet return to x0 with zero velocity (a rollback, as
//     Harmon et al. 2008 fall back to when impact zones fail), and the pairs of returned vertices
//     are tested again until none meets (after kMaxRounds rounds every free vertex returns). A
//     returned vertex does not move, so each round returns new vertices and the loop ends; if x0
//     had no crossing, x1 has none.
// Pairs of one cloth closer than the thickness at rest are left to the springs in step 2 (but not
// in step 3). Pinned vertices never move in either step. The tests of every pair (does it need a
// push, does it meet) run in parallel into a flag per pair; the pushes and returns run serially
// in the pairs' fixed order: the same bytes for any thread count.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "sim/contact/collider_touches.hpp"
#include "sim/contact/contact_stats.hpp"
#include "sim/contact/flat_patches.hpp"
#include "sim/contact/pair_pool.hpp"
#include "sim/contact/push_halves.hpp"
#include "sim/contact/stray_bounds.hpp"
#include "sim/contact/surface_features.hpp"
#include "sim/contact/triangle_bvh.hpp"
#include "sim/integrators/integrator.hpp"
#include "sim/scene/scene.hpp"

namespace clothlab {

// What triangle contact's constructor reads from the rest shape once: each vertex's and
// triangle's cloth and the triangles' centroids.
struct ContactRestLayout {
  std::vector<std::int32_t> vertex_cloth;
  std::vector<int> triangle_cloth;
  std::vector<Eigen::Vector3d> centroids;
};

// A box in float, around a feature's vertices at the collection positions.
struct ContactFloatBox {
  std::array<float, 3> lo{}, hi{};
};

template <class T>
class TriangleContact {
 public:
  TriangleContact(const Model<T>& m, const SolverSpec& spec);

  using RestLayout = ContactRestLayout;
  TriangleContact(const Model<T>& m, const SolverSpec& spec, const RestLayout& rest);

  // How many of the next substeps (each of length h, at most `most`) one pass spans: as many as
  // keep every vertex's motion, at its speed now relative to the mean velocity of all vertices,
  // within kPassReach thicknesses over the pass, and within kMaxPassTime; at least one.
  int pass_span(const State<T>& s, double h, int most, int threads);
  // Before a pass: where it starts.
  void begin(const State<T>& s, int threads);
  // After the pass (duration h) and the colliders' `touches`. True when it changed some vertex.
  bool respond(const Model<T>& m, State<T>& s, double h, int threads,
               const ColliderTouches* touches = nullptr);

  const ClothContactStats& last() const { return stats_; }
  double thickness() const { return thickness_; }
  // The separation the fail-safe's collision detection counts as contact.
  double eta() const { return eta_; }

  using Pair = ContactPair;
  const std::vector<Pair>& pairs() const { return pairs_; }

 private:
  using FloatBox = ContactFloatBox;
  // Returns false when the tangle was beyond the bound.
  bool collect_pairs(const State<T>& s, int threads);
  // The pairs again when a vertex strayed past its skin or a flat patch bent (with `flag` set in
  // the stats); false when the tangle was beyond the bound.
  bool recollect_if_needed(const State<T>& s, int threads, bool& flag);
  // Whether every flat patch of both trees is still flat over the motion x0_ -> x.
  bool still_flat(const Vec3Array<T>& x, int threads);
  bool all_flat() const { return flat_.covers_all(); }  // one flat patch covers every triangle
  // Every free vertex back to x0 with zero velocity; returns how many.
  int return_all(const Model<T>& m, State<T>& s);
  bool undo(const Model<T>& m, State<T>& s);
  using Stray = StraySummary;
  RigidFit fit_rigid(const Vec3Array<T>& x, int threads);
  Stray deviations(const Vec3Array<T>& x, const RigidFit& fit, std::vector<float>& dev,
                   const std::vector<float>* also, int threads);
  void set_allowances(double growth, int threads);
  bool gather_pairs(int threads);
  bool still_tangled(const State<T>& s, int threads);
  // The proximity pass: flag_ for every pair.
  void flag_proximity(const State<T>& s, int threads);
  // The largest growth of any vertex's moved_by() since margins_ were taken.
  double growth_since_margins(int threads);
  // The substep's end against xc: stray1_, dev1_, excess1_ and the shrink factor.
  void measure_stray1(const State<T>& s, int threads);
  FloatBox point_box(int v) const;
  void seam_patches();
  // What a run of the broad phase's pieces found: every pair, more than the bound, or more
  // than the pool has room for.
  enum class Gathered { all, tangle, out_of_room };
  template <class Cull>
  Gathered run_pieces(int threads, std::size_t bound, const Cull& cull);
  bool add_pairs(int ta, int tb, PairPool::List& out);  // false: the pool has no room left
  bool keep_if_close(Pair p, PairPool::List& out);      // the same
  void feature_boxes(int threads);
  bool needs_push(const Pair& p, const Vec3Array<T>& x) const;
  // Pushes the pair apart if it needs it, stamping its vertices with `stamp` and listing those
  // pushed for the first time in this pass in `moved`; whether it did.
  bool push_apart(const Model<T>& m, State<T>& s, const Pair& p, std::uint64_t stamp,
                  std::vector<std::int32_t>& moved);
  void count_hits(std::size_t block, std::size_t lo, std::size_t hi);  // of a block of pairs
  void list_hits(int threads);  // push_.hits and push_.begin from the flags and counts
  // The sweeps of pushes over the pairs flagged hit; returns the pushes.
  int push_sweeps(const Model<T>& m, State<T>& s, int threads);
  // One sweep over the hits of one half (or across the cut); returns its pushes.
  int push_sweep(const Model<T>& m, State<T>& s, int sweep, int half);
  bool meets(const Pair& p, const Vec3Array<T>& x) const;
  template <class Test>
  void flag_pairs(int threads, Test&& test);
  void return_vertex(State<T>& s, std::size_t i) const;
  bool return_vertices(const Model<T>& m, State<T>& s, const Pair& p, int round);
  // near_only: only the pairs the proximity pass left flagged (respond() says when that holds).
  int fail_safe(const Model<T>& m, State<T>& s, int threads, bool near_only);
  // The fail-safe, and again while its returns bent a flat patch; false on a tangle.
  bool guarantee(const Model<T>& m, State<T>& s, int threads, bool near_only);
  // Velocities take the pushes' position change over h; returns the longest change.
  double update_velocities(State<T>& s, double h);

  double thickness_ = 0.0;
  double eta_ = 0.0;
  SurfaceFeatures features_;
  TriangleBvh bvh_;
  FlatPatches<T> flat_;
  // A second tree cut a third of the way across each cloth from the first (its material
  // coordinates shifted round), whose flat patches cover the seams between the first tree's:
  // a pair of triangles inside one of them cannot touch either.
  TriangleBvh shifted_bvh_;
  FlatPatches<T> shifted_flat_;
  std::vector<std::int32_t> seam_patch_;  // per node of the first tree: see seam_patches()
  std::vector<std::int32_t> cloth_of_;    // per vertex
  Vec3Array<T> x0_;                       // the substep's start
  Vec3Array<T> x_step_;                   // what the integrator made, of the vertices pushed
  Vec3Array<T> xc_;                       // where the pairs were collected
  StrayBounds strays_;                    // how far the vertices moved since
  PairMargins margins_;                   // the proximity pass's, at its last full pass
  std::vector<FloatBox> triangle_box_, edge_box_;  // around their vertices at xc
  std::vector<TriangleBvh::Task> tasks_;           // the broad phase's pieces for threads
  PairPool pool_;                                  // the pairs the pieces found
  std::vector<PairPool::List> task_lists_;         // per piece: its pairs in the pool
  bool stale_ = true;                              // a vertex left its box between substeps
  int span_ = 1;                                   // substeps in the pass under way
  bool tangled_ = false;                           // the last collection, at xc, was a tangle
  int kept_choices_ = 0;  // collections since the flat patches were last chosen
  std::vector<Pair> pairs_;
  std::vector<PairFlag> flag_;  // per pair: the last parallel test's answer
  // Per block of vertices: kBlockSums partial sums for the rigid fit, or the largest stray and
  // excess (triangle_contact.cpp).
  std::vector<double> block_sums_;
  PushSweeps<T> push_;                        // the pushes' bookkeeping within a pass
  const ColliderTouches* touches_ = nullptr;  // respond()'s: what the colliders hold
  std::vector<int> returned_round_;  // per vertex: the fail-safe round that returned it (0: none)
  std::vector<int> returned_;        // the vertices returned this substep
  ClothContactStats stats_;
};

extern template class TriangleContact<float>;
extern template class TriangleContact<double>;

}  // namespace clothlab
