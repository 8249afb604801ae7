#include "sim/contact/feature_contacts.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "sim/core/parallel.hpp"
#include "sim/core/vec3_eigen.hpp"
#include "sim/mesh/closest_point.hpp"

namespace clothlab {
namespace {

using V3 = Eigen::Vector3d;

// Whether world point p lies within the shell of some collider other than `self`: a box's corner
// resting on the floor, a table leg's top under the table top.
bool buried(const V3& p, std::size_t self, const std::vector<Collider>& colliders,
            const std::vector<ColliderSweep>& sweeps) {
  for (std::size_t c = 0; c < colliders.size(); ++c)
    if (c != self &&
        colliders[c].local_distance(sweeps[c].end.to_local(p)).phi < colliders[c].thickness())
      return true;
  return false;
}

// The furthest any feature moves between the collider's start and end poses: the move is affine
// in the local point, so its largest length over the features' box is at one of its corners.
double pose_move(const ColliderSweep& sweep, const SharpFeatures& f) {
  const V3 &lo = f.lo, &hi = f.hi;
  double largest = 0.0;
  for (int k = 0; k < 8; ++k) {
    const V3 q(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
    largest = std::max(largest, (sweep.end.to_world(q) - sweep.start.to_world(q)).norm());
  }
  return largest;
}

template <class T>
V3 unit_normal(const Vec3Array<T>& x, const std::array<int, 3>& t) {
  const V3 a = load3(x, std::size_t(t[0]));
  const V3 n = (load3(x, std::size_t(t[1])) - a).cross(load3(x, std::size_t(t[2])) - a);
  const double length = n.norm();
  return length > 1e-20 ? V3(n / length) : V3::Zero();
}

}  // namespace

template <class T>
FeatureContacts<T>::FeatureContacts(const std::vector<Collider>& colliders, const Model<T>& m,
                                    double edge) {
  if (m.triangles.empty()) return;  // no surface for a feature to touch (a single spring)
  features_.reserve(colliders.size());
  for (const Collider& c : colliders) {
    // A collider at least one edge thick needs none: its vertex contacts keep every vertex
    // that far from its surface, and every point of a triangle lies within 0.58 of its longest
    // edge from a vertex (the equilateral triangle's circumradius), so no feature gets through.
    // With a thickness beyond the collider's size every feature would touch every triangle (a
    // fuzzed chair 2 m thick took 0.36 s a step).
    if (c.thickness() >= edge) {
      features_.emplace_back();
      continue;
    }
    features_.push_back(sharp_features(c.spec(), 0.5 * edge));
    empty_ = empty_ && features_.back().empty();
  }
  if (empty_) return;
  near_.assign(m.n, 0);
  block_move_.assign(block_count(m.n), 0.0);
  moved_.reserve(3 * m.triangles.size());  // one contact a triangle before it grows
}

template <class T>
double FeatureContacts<T>::mark_near(const SharpFeatures& f, const ColliderPose& pose,
                                     const Vec3Array<T>& start, const State<T>& s, int threads) {
  for_each_block_indexed(near_.size(), threads,
                         [&](std::size_t block, std::size_t b, std::size_t e) {
                           double move = 0.0;
                           for (std::size_t i = b; i < e; ++i) {
                             const V3 x = load3(s.pos, i);
                             move = std::max(move, (x - load3(start, i)).squaredNorm());
                             near_[i] = f.near(pose.to_local(x));
                           }
                           block_move_[block] = move;
                         });
  const double move = std::sqrt(*std::max_element(block_move_.begin(), block_move_.end()));
  return move;
}

template <class T>
int FeatureContacts<T>::respond(const std::vector<Collider>& colliders,
                                const std::vector<ColliderSweep>& sweeps, const Model<T>& m,
                                const Vec3Array<T>& start, State<T>& s, int threads) {
  int contacts = 0;
  moved_.clear();
  for (std::size_t c = 0; c < colliders.size(); ++c) {
    const SharpFeatures& f = features_[c];
    if (f.empty()) continue;
    const ColliderSweep& sweep = sweeps[c];
    const double th = colliders[c].thickness();
    const double moved = pose_move(sweep, f);
    // A triangle a feature touches has that feature within its longest edge and the reach
    // (thickness and moves) of each vertex: within the near cells' two rest edges of one vertex
    // while the reach is under a cell (half an edge) and the edge under 1.5 rest edges. Past
    // that reach (a fast substep), every triangle is tested.
    const bool all = mark_near(f, sweep.end, start, s, threads) + moved + th > f.cell;
    for (const std::array<int, 3>& t : m.triangles) {
      if (!all && !(near_[std::size_t(t[0])] | near_[std::size_t(t[1])] | near_[std::size_t(t[2])]))
        continue;
      V3 x[3];
      double step = 0.0;  // the triangle's largest vertex move over the substep
      for (int k = 0; k < 3; ++k) {
        const auto v = std::size_t(t[std::size_t(k)]);
        x[k] = load3(s.pos, v);
        step = std::max(step, (x[k] - load3(start, v)).squaredNorm());
      }
      const Bounds box{x[0].cwiseMin(x[1]).cwiseMin(x[2]), x[0].cwiseMax(x[1]).cwiseMax(x[2])};
      if (!box.overlaps(sweep.box)) continue;
      // A feature that touches the triangle lies within the thickness of it now, or crossed it
      // during the substep, so within their two moves: the triangle's box in the collider's
      // frame at the end, grown by that.
      const double grow = th + std::sqrt(step) + moved;
      const V3 la = sweep.end.to_local(x[0]), lb = sweep.end.to_local(x[1]),
               lc = sweep.end.to_local(x[2]);
      const V3 lo = la.cwiseMin(lb).cwiseMin(lc) - V3::Constant(grow),
               hi = la.cwiseMax(lb).cwiseMax(lc) + V3::Constant(grow);
      std::optional<V3> n0;  // the triangle's normal at `start`, once, when a feature asks
      const auto start_normal = [&]() -> const V3& {
        if (!n0) n0 = unit_normal(start, t);
        return *n0;
      };
      f.for_each_near(lo, hi, [&](int i) {
        const V3& local = f.points[std::size_t(i)];
        if ((local.array() < lo.array()).any() || (local.array() > hi.array()).any()) return;
        const Feature feature{sweep.start.to_world(local), sweep.end.to_world(local),
                              sweep.end.rotate(f.outward[std::size_t(i)])};
        if (touch(colliders[c], sweep.end, feature, grow, t, start_normal, m, start, s,
                  [&] { return buried(feature.end, c, colliders, sweeps); })) {
          ++contacts;
          moved_.insert(moved_.end(), t.begin(), t.end());
        }
      });
    }
  }
  return contacts;
}

template <class T>
template <class StartNormal, class Buried>
bool FeatureContacts<T>::touch(const Collider& collider, const ColliderPose& pose, const Feature& f,
                               double reach, const std::array<int, 3>& t,
                               StartNormal&& start_normal, const Model<T>& m,
                               const Vec3Array<T>& start, State<T>& s, Buried&& is_buried) const {
  V3 n = unit_normal(s.pos, t);
  if (n.isZero()) return false;  // a collapsed triangle: its vertices' own contacts hold it
  // Further from the triangle's plane than the thickness and the two moves (twice, for the
  // plane's turn): neither within the thickness nor through it this substep.
  if (std::abs((load3(s.pos, std::size_t(t[0])) - f.end).dot(n)) > 2.0 * reach) return false;
  // The side the feature started on (its outward direction for one that started on the plane).
  const V3& n0 = start_normal();
  const double start_along = (load3(start, std::size_t(t[0])) - f.start).dot(n0);
  const double side = start_along != 0.0 ? start_along : -f.outward.dot(n0);
  if (side < 0.0) n = -n;  // n now points from the feature's side towards the cloth
  V3 x[3];
  for (int k = 0; k < 3; ++k) x[k] = load3(s.pos, std::size_t(t[std::size_t(k)]));
  const TrianglePoint cp = closest_on_triangle(f.end, x[0], x[1], x[2]);
  const V3 d = cp.point - f.end;
  const double along = d.dot(n), th = collider.thickness();
  V3 dir = n;
  double gap = along;
  if (cp.interior()) {
    if (along >= th) return false;  // clear; or crossed through the face if along < 0
  } else {
    // The closest point on the triangle's edge or corner: a feature under a ridge of the cloth
    // goes straight away from it; one that crossed beside the face belongs to the neighbour.
    const double distance = d.norm();
    if (distance >= th || along < 0.0) return false;
    if (distance > 1e-12) dir = d / distance;
    gap = distance;
  }
  if (is_buried()) return false;
  // Each vertex takes w_i / m_i of the change, scaled so that X takes all of it.
  double k[3], sum = 0.0;
  V3 v[3], vx = V3::Zero();
  for (int j = 0; j < 3; ++j) {
    const auto i = std::size_t(t[std::size_t(j)]);
    k[j] = cp.weights[j] * double(m.inv_mass[i]);
    sum += cp.weights[j] * k[j];
    v[j] = load3(s.vel, i);
    vx += cp.weights[j] * v[j];
  }
  if (sum <= 0.0) return false;  // every vertex with weight is pinned
  const V3 rel = vx - pose.surface_velocity(f.end);
  const double vn = rel.dot(dir);
  V3 dv = V3::Zero();
  if (vn < 0.0) {  // approaching: inelastic, then Coulomb friction with that impulse
    const double dvn = -vn;
    const V3 vt = rel - vn * dir;
    const double speed = vt.norm();
    const ColliderSpec& spec = collider.spec();
    const double keep = speed <= spec.static_friction * dvn
                            ? 0.0
                            : std::max(0.0, 1.0 - spec.kinetic_friction * dvn / speed);
    dv = dvn * dir - (1.0 - keep) * vt;
  }
  const V3 dx = (th - gap) * dir;
  for (int j = 0; j < 3; ++j) {
    if (k[j] == 0.0) continue;
    const auto i = std::size_t(t[std::size_t(j)]);
    store3(s.pos, i, V3(x[j] + (k[j] / sum) * dx));
    store3(s.vel, i, V3(v[j] + (k[j] / sum) * dv));
  }
  return true;
}

template class FeatureContacts<float>;
template class FeatureContacts<double>;

}  // namespace clothlab
