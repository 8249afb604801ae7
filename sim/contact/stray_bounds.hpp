// What triangle contact's Verlet list knows about how far the vertices have moved since its pairs
// were collected at xc (sim/contact/triangle_contact.hpp, docs/contact.md section 7): each vertex
// is measured after the best rigid motion of all vertices since xc is taken away
// (sim/contact/rigid_fit.hpp), since a rigid motion changes no distance.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace clothlab {

// A vertex-triangle or edge-edge pair of the list.
struct ContactPair {
  std::array<std::int32_t, 4> v{};  // point, triangle; or edge, edge
  bool edge_edge = false;
  float dist = 0.0f;  // m: at the collection positions xc (rounded down)
};

// A pair's answer to the last parallel test of triangle contact: clear by the thickness over the
// substep; hit (needs a push, or in the fail-safe's first round, meets); or near, neither. An
// enumeration rather than a byte: a store through a char type may alias anything, and made the
// test's loop reload every array it reads after each flag it wrote.
enum class PairFlag : std::uint8_t { clear, hit, near };

// x is near to + rotation (xc - from).
struct RigidFit {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d from = Eigen::Vector3d::Zero(), to = Eigen::Vector3d::Zero();
};

// The strays of one set of positions.
struct StraySummary {
  double most = 0.0;    // m: the largest stray
  double excess = 0.0;  // m: the largest stray beyond its vertex's allowance (> 0: collect)
};

struct StrayBounds {
  // m, per vertex: how far it may stray from xc (after the rigid fit) while the pairs hold: a
  // pair left out was farther apart at xc than the thickness plus its two sides' largest
  // allowances, so while every vertex strays less than `shrink` times its allowance less
  // (1 - shrink) half thicknesses, no pair left out comes within the thickness.
  std::vector<float> allow;
  // m: how far the substep's start x0 and its end x1 have strayed from xc (each from its own
  // rigid fit), the largest and each vertex's. On the straight motion between them a vertex
  // strays no farther than the larger of its two, so a pair's distance is at least `shrink` times
  // its distance at xc less the largest of that over its first side and the same over its
  // other: a pair farther apart than the thickness (or eta) that way needs neither a push nor a
  // collision test in the substep.
  double stray0 = 0.0, stray1 = 0.0;
  double excess1 = 0.0;  // m: see StraySummary
  std::vector<float> dev0, dev1;
  // The rigid fits' rotations from xc to x0 and to x1, and the factor by which the straight
  // motion between them can shrink a distance at xc (sim/contact/rigid_fit.hpp).
  Eigen::Matrix3d rotation0 = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d rotation1 = Eigen::Matrix3d::Identity();
  double shrink = 1.0;

  [[gnu::always_inline]] float moved_by(std::int32_t v) const {
    return std::max(dev0[std::size_t(v)], dev1[std::size_t(v)]);
  }
  // A lower bound on the pair's distance over the whole substep.
  // (Inlined: the proximity pass and the fail-safe call it for every pair, every pass.)
  [[gnu::always_inline]] double margin(const ContactPair& p) const {
    const float first =
        p.edge_edge ? std::max(moved_by(p.v[0]), moved_by(p.v[1])) : moved_by(p.v[0]);
    const float other =
        std::max(moved_by(p.v[2]),
                 p.edge_edge ? moved_by(p.v[3]) : std::max(moved_by(p.v[1]), moved_by(p.v[3])));
    return shrink * double(p.dist) - double(first) - double(other);
  }
  // Whether the pair is certainly more than d apart over the whole substep.
  bool clear_by(const ContactPair& p, double d) const { return margin(p) > d; }
};

// The proximity pass's margins at one moment S, so that later substeps can skip the pairs still
// clear by them (triangle_contact.cpp, respond): a pair's clear_by quantity
// shrink dist - first - other can fall after S by no more than (shrink_S - shrink) dist plus the
// growth of its two sides' strays, each at most the largest growth of any vertex's
// moved_by() since S.
struct PairMargins {
  std::vector<float>
      slack;  // per pair: its clear_by quantity at S less the thickness, rounded down
  std::vector<float> moved;  // per vertex: moved_by() at S
  double shrink = 1.0;       // StrayBounds::shrink at S
  double max_dist = 0.0;     // m: the longest ContactPair::dist of the list
  bool valid = false;        // false after a collection (new pairs) until the next full pass
};

}  // namespace clothlab
