#include "sim/contact/contact_response.hpp"

#include <algorithm>
#include <cmath>

#include "sim/core/parallel.hpp"
#include "sim/core/vec3_eigen.hpp"
#include "sim/mesh/mesh_edges.hpp"

namespace clothlab {
namespace {

using V3 = Eigen::Vector3d;

// The first point of the local path p0 -> p1 on the shell phi = thickness, by sphere tracing
// (each march as long as the distance to the shell, which no exact signed distance overshoots).
// Returns false when the path stays outside.
bool first_touch(const Collider& c, const V3& p0, const V3& p1, double thickness,
                 LocalDistance& at) {
  const V3 path = p1 - p0;
  const double length = path.norm();
  const double tolerance = 1e-9 + 1e-6 * thickness;
  double s = 0.0;
  for (int k = 0; k < 32; ++k) {
    at = c.local_distance(p0 + s * path);
    const double gap = at.phi - thickness;
    if (gap <= tolerance) return true;
    if (length == 0.0) return false;
    s += gap / length;
    if (s > 1.0) return false;
  }
  // Still approaching after 32 marches: a path grazing the shell. It touched if it ended inside.
  at = c.local_distance(p1);
  return at.phi < thickness;
}

}  // namespace

template <class T>
ContactResponse<T>::ContactResponse(const std::vector<ColliderSpec>& colliders, const Model<T>& m,
                                    double hold_reach)
    : hold_reach_(hold_reach) {
  colliders_.reserve(colliders.size());
  for (const ColliderSpec& spec : colliders) colliders_.emplace_back(spec);
  sweeps_.resize(colliders_.size());
  if (colliders_.empty()) return;
  start_.resize(m.n);
  touches_.resize(m.n);
  blocks_.resize(block_count(m.n));
  // Edge midpoints join in when some collider is thinner than the cloth's longest grid edge at
  // rest: a rod or a thin box edge could otherwise pass between two rows of vertices.
  double longest = 0.0;
  // A mesh cloth's edges are its triangles' (the model's, between its offset and offset + nu).
  std::vector<std::array<int, 3>> mesh_triangles;
  for (const auto& t : m.triangles)
    for (const ClothRange& c : m.cloths)
      if (c.mesh && t[0] >= c.offset && t[0] < c.offset + c.nu) mesh_triangles.push_back(t);
  const std::vector<std::array<int, 2>> mesh_edge_list = mesh_edges(mesh_triangles);
  for (const auto& e : mesh_edge_list)
    longest = std::max(longest, (load3(m.rest_positions, std::size_t(e[0])) -
                                 load3(m.rest_positions, std::size_t(e[1])))
                                    .norm());
  for (const ClothRange& c : m.cloths)
    if (!c.mesh)
      for (int j = 0; j < c.nv; ++j)
        for (int i = 0; i < c.nu; ++i) {
          const auto v = static_cast<std::size_t>(c.offset + i + j * c.nu);
          const V3 x = load3(m.rest_positions, v);
          if (i + 1 < c.nu)
            longest = std::max(longest, (load3(m.rest_positions, v + 1) - x).norm());
          if (j + 1 < c.nv)
            longest =
                std::max(longest, (load3(m.rest_positions, v + std::size_t(c.nu)) - x).norm());
        }
  for (const Collider& c : colliders_) {
    const ColliderSpec& spec = c.spec();
    double feature = INFINITY;  // the collider's thinnest dimension
    if (spec.kind == ColliderKind::sphere || spec.kind == ColliderKind::capsule)
      feature = 2.0 * spec.radius;
    if (spec.kind == ColliderKind::box)
      feature = 2.0 * std::min({spec.half_extents[0], spec.half_extents[1], spec.half_extents[2],
                                2.0 * spec.rounding + 0.5 * longest});  // sharp edges poke too
    if (spec.kind == ColliderKind::mesh) feature = 0.0;  // a mesh may have any sharp edge
    edges_ = edges_ || feature < 2.0 * longest;
  }
  features_ = FeatureContacts<T>(colliders_, m, longest);
  if (!edges_) return;
  mesh_edges_ = mesh_edge_list;
  for (const ClothRange& c : m.cloths) {
    if (c.mesh) continue;
    for (int j = 0; j < c.nv; ++j) {
      const int row = c.offset + j * c.nu;
      if (c.nu > 1) rows_.push_back({row, 1, c.nu - 1});
      if (j + 1 < c.nv) columns_.push_back({row, c.nu, c.nu});
    }
  }
}

template <class T>
void ContactResponse<T>::begin(const State<T>& s, double t, double h, int threads) {
  if (colliders_.empty()) return;
  // The cheap test first: the cloth's box now, grown by twice the fastest vertex's move over the
  // next window_substeps(h) substeps and a centimetre (no spring accelerates a vertex that far
  // meanwhile), against every collider over those substeps. When nothing can be reached, the answer
  // holds for the whole window: no start is kept, respond() does nothing, and a collider far from
  // the cloth costs one pass over the state every kWindow substeps.
  if (!active_ && quiet_substeps_ > 0) {
    --quiet_substeps_;
    return;
  }
  active_ = false;
  const int substeps = window_substeps(h);
  const double window = substeps * h;
  const std::size_t n = s.pos.size();
  T lo[3], hi[3], speed2 = T(0);
  for (int a = 0; a < 3; ++a) {
    const T* x = s.pos.axis(a).data();
    T l = x[0], u = x[0];
#pragma omp simd reduction(min : l) reduction(max : u)
    for (std::size_t i = 0; i < n; ++i) {
      l = std::min(l, x[i]);
      u = std::max(u, x[i]);
    }
    lo[a] = l;
    hi[a] = u;
  }
  {
    const T *vx = s.vel.x.data(), *vy = s.vel.y.data(), *vz = s.vel.z.data();
#pragma omp simd reduction(max : speed2)
    for (std::size_t i = 0; i < n; ++i)
      speed2 = std::max(speed2, vx[i] * vx[i] + vy[i] * vy[i] + vz[i] * vz[i]);
  }
  const double margin = 2.0 * std::sqrt(double(speed2)) * window + 0.01;
  const Bounds cloth{V3(lo[0], lo[1], lo[2]) - V3::Constant(margin),
                     V3(hi[0], hi[1], hi[2]) + V3::Constant(margin)};
  for (std::size_t c = 0; c < colliders_.size() && !active_; ++c) {
    const Collider& collider = colliders_[c];
    const double th = collider.thickness();
    // Its poses at the window's start, middle and end (a turn or a keyframe in between); for a
    // bounded shape the box round all three, which holds its path when it moves in a line.
    Bounds swept{V3::Constant(INFINITY), V3::Constant(-INFINITY)};
    for (double f : {0.0, 0.5, 1.0}) {
      const ColliderPose pose = collider.pose(t + f * window);
      if (collider.spec().kind == ColliderKind::plane) {
        active_ = active_ || collider.reaches(cloth, pose, th);
      } else {
        const Bounds b = collider.bounds(pose, th);
        swept = {swept.lo.cwiseMin(b.lo), swept.hi.cwiseMax(b.hi)};
      }
    }
    if (collider.spec().kind != ColliderKind::plane) active_ = active_ || cloth.overlaps(swept);
  }
  if (!active_) {
    quiet_substeps_ = substeps - 1;
    return;
  }
  for_each_block(n, threads, [&](std::size_t b, std::size_t e) {
    for (int a = 0; a < 3; ++a)
      std::copy(s.pos.axis(a).begin() + long(b), s.pos.axis(a).begin() + long(e),
                start_.axis(a).begin() + long(b));
  });
}

template <class T>
bool ContactResponse<T>::point(const V3& x0, V3& x1, V3& v, double h, double& depth, V3& normal,
                               V3* near) const {
  bool changed = false;
  // Left alone but within reach of the shell: held all the same (see hold_reach_).
  const auto note = [&](const ColliderSweep& sweep, const LocalDistance& d, double th) {
    if (near && d.phi < th + hold_reach_) *near = sweep.end.rotate(d.normal);
  };
  for (std::size_t c = 0; c < colliders_.size(); ++c) {
    const Collider& collider = colliders_[c];
    const ColliderSweep& sweep = sweeps_[c];
    // This point's path against the collider's box over the substep.
    const Bounds path{x0.cwiseMin(x1), x0.cwiseMax(x1)};
    if (!path.overlaps(sweep.reach_box)) continue;
    const double th = collider.thickness();
    // A plane's box is unbounded: its own test of the path's box, as respond()'s blocks take it,
    // at both poses. A path that stays farther than the shell and the hold's reach leaves
    // nothing to do (no contact, nothing held) and skips the changes of frame and distances
    // below, which every vertex above a floor paid; the slack keeps it clear of rounding.
    if (collider.spec().kind == ColliderKind::plane) {
      const double beyond = th + hold_reach_ + 1e-9 + 1e-6 * (th + hold_reach_);
      if (!collider.reaches(path, sweep.start, beyond) &&
          !collider.reaches(path, sweep.end, beyond))
        continue;
    }
    if (!path.overlaps(sweep.box)) {  // no contact; only the hold's reach
      if (near) note(sweep, collider.local_distance(sweep.end.to_local(x1)), th);
      continue;
    }
    const V3 p0 = sweep.start.to_local(x0), p1 = sweep.end.to_local(x1);
    const LocalDistance d0 = collider.local_distance(p0);
    LocalDistance touch = collider.local_distance(p1);
    if (d0.phi >= th) {
      // Outside at the start: it is a contact only if the relative path reached the shell, and
      // the normal is where it first did (the side it came from).
      if (touch.phi >= th && (p1 - p0).norm() <= d0.phi - th) {
        note(sweep, touch, th);
        continue;
      }
      const LocalDistance end = touch;
      if (!first_touch(collider, p0, p1, th, touch)) {
        note(sweep, end, th);
        continue;
      }
    } else {
      // Started on (or in) the shell, as a resting vertex does: it leaves only by moving outwards;
      // moving inwards it is a contact even if its path ends beyond the far side (it must not
      // pass through a thin collider), and the normal is the start's unless the end is inside on
      // the same side.
      if (touch.phi >= th && (p1 - p0).dot(d0.normal) >= 0.0) {
        note(sweep, touch, th);
        continue;
      }
      if (touch.phi >= th || touch.normal.dot(d0.normal) < 0.0) touch = d0;
    }
    const V3 n = sweep.end.rotate(touch.normal);
    normal = n;
    const V3 vc = sweep.end.surface_velocity(x1);
    V3 rel = v - vc;
    const double vn = rel.dot(n);
    // The relative normal velocity may close the gap it had, no more (inelastic).
    const double vn_min = -std::max(0.0, d0.phi - th) / h;
    if (vn < vn_min) {
      const double dvn = vn_min - vn;  // the normal impulse per unit mass
      V3 vt = rel - vn * n;
      const double speed = vt.norm();
      const ColliderSpec& spec = collider.spec();
      // Coulomb: the impulse's friction cone holds the tangential velocity, or takes mu_k dv_n.
      if (speed <= spec.static_friction * dvn)
        vt.setZero();
      else
        vt *= std::max(0.0, 1.0 - spec.kinetic_friction * dvn / speed);
      rel = vt + vn_min * n;
      v = vc + rel;
      x1 = x0 + h * v;  // the move redone with the filtered velocity
    }
    // Whatever still lies inside the shell goes out along the normal; the velocity stays.
    LocalDistance now = collider.local_distance(sweep.end.to_local(x1));
    if (now.phi < th) {
      // Past the middle of a thin shape the nearest face is the far one: keep the contact's side.
      const V3 out = now.normal.dot(touch.normal) >= 0.0 ? sweep.end.rotate(now.normal) : n;
      x1 += (th - now.phi) * out;
      normal = out;
      now = collider.local_distance(sweep.end.to_local(x1));
    }
    depth = std::max(depth, th - now.phi);
    changed = true;
  }
  return changed;
}

template <class T>
bool ContactResponse<T>::vertex(std::size_t i, const Model<T>& m, State<T>& s, double h,
                                double& depth) {
  if (m.inv_mass[i] == T(0)) return false;  // pinned: held where it is
  V3 x1 = load3(s.pos, i), v = load3(s.vel, i), normal, near = V3::Zero();
  if (!point(load3(start_, i), x1, v, h, depth, normal, &near)) {
    if (near.squaredNorm() > 0.0) touches_.hold(i, near);
    return false;
  }
  touches_.hold(i, normal);
  store3(s.pos, i, x1);
  store3(s.vel, i, v);
  return true;
}

// The midpoint of the edge a-b as a contact point (a collider thinner than the cloth's spacing
// would otherwise pass between two vertices): its correction moves both ends alike (pinned ends
// stay).
template <class T>
bool ContactResponse<T>::edge(std::size_t a, std::size_t b, const Model<T>& m, State<T>& s,
                              double h, double& depth) {
  const bool free_a = m.inv_mass[a] != T(0), free_b = m.inv_mass[b] != T(0);
  if (!free_a && !free_b) return false;
  const V3 x0 = 0.5 * (load3(start_, a) + load3(start_, b));
  const V3 xa = load3(s.pos, a), xb = load3(s.pos, b), va = load3(s.vel, a), vb = load3(s.vel, b);
  const V3 mid = 0.5 * (xa + xb), v_mid = 0.5 * (va + vb);
  V3 x1 = mid, v = v_mid, normal;
  if (!point(x0, x1, v, h, depth, normal)) return false;
  // With one end pinned the free end moves twice as far, so that the midpoint gets its move.
  const double scale = free_a && free_b ? 1.0 : 2.0;
  const V3 dx = scale * (x1 - mid), dv = scale * (v - v_mid);
  if (free_a) {
    touches_.hold(a, normal);
    store3(s.pos, a, V3(xa + dx));
    store3(s.vel, a, V3(va + dv));
  }
  if (free_b) {
    touches_.hold(b, normal);
    store3(s.pos, b, V3(xb + dx));
    store3(s.vel, b, V3(vb + dv));
  }
  return true;
}

// The vertices of the blocks near a collider, each against every collider. Blocks resting on a
// collider cost far more than those that only pass its box test (the stack on the ball's lower
// sheet, the first 1600 vertices, against its upper one): balanced, not halved by index.
template <class T>
void ContactResponse<T>::respond_vertices(const Model<T>& m, State<T>& s, double h, int threads) {
  for_each_block_balanced(s.pos.size(), threads,
                          [&](std::size_t block, std::size_t b, std::size_t e) {
                            BlockResult& r = blocks_[block];
                            if (!r.near) return;
                            for (std::size_t i = b; i < e; ++i) {
                              double depth = 0.0;
                              if (vertex(i, m, s, h, depth)) {
                                ++r.contacts;
                                r.max_depth = std::max(r.max_depth, depth);
                              }
                            }
                          });
  for (const BlockResult& r : blocks_) {
    stats_.contacts += r.contacts;
    stats_.max_depth = std::max(stats_.max_depth, r.max_depth);
  }
}

template <class T>
bool ContactResponse<T>::respond(const Model<T>& m, State<T>& s, double t, double h, int threads) {
  stats_ = {};
  ++touches_.now;              // what an earlier response held is held no longer
  if (!active_) return false;  // begin() found nothing within reach
  for (std::size_t c = 0; c < colliders_.size(); ++c) {
    ColliderSweep& sweep = sweeps_[c];
    sweep.start = colliders_[c].pose(t);
    sweep.end = colliders_[c].pose(t + h);
    const double th = colliders_[c].thickness();
    const Bounds a = colliders_[c].bounds(sweep.start, th), b = colliders_[c].bounds(sweep.end, th);
    sweep.box = {a.lo.cwiseMin(b.lo), a.hi.cwiseMax(b.hi)};
    // Out to the hold's reach beyond the shell (hold_reach_), where vertices are held too.
    const V3 reach = V3::Constant(hold_reach_);
    sweep.reach_box = {sweep.box.lo - reach, sweep.box.hi + reach};
  }
  // Which blocks of vertices come near a collider: the block's box over the substep against
  // each collider's; most blocks of a cloth far from every collider stop here.
  for_each_block_indexed(s.pos.size(), threads,
                         [&](std::size_t block, std::size_t b, std::size_t e) {
                           Bounds box{V3::Constant(INFINITY), V3::Constant(-INFINITY)};
                           for (std::size_t i = b; i < e; ++i) {
                             const V3 x0 = load3(start_, i), x1 = load3(s.pos, i);
                             box.lo = box.lo.cwiseMin(x0.cwiseMin(x1));
                             box.hi = box.hi.cwiseMax(x0.cwiseMax(x1));
                           }
                           BlockResult& r = blocks_[block];
                           r = {};
                           for (std::size_t c = 0; c < colliders_.size() && !r.near; ++c) {
                             const double th = colliders_[c].thickness() + hold_reach_;
                             // Bounded shapes: their box over the whole substep (a fast one
                             // sweeps the space between its poses).
                             r.near = colliders_[c].spec().kind == ColliderKind::plane
                                          ? colliders_[c].reaches(box, sweeps_[c].start, th) ||
                                                colliders_[c].reaches(box, sweeps_[c].end, th)
                                          : box.overlaps(sweeps_[c].reach_box);
                           }
                         });
  // Edge midpoints first, then the vertices, so that what an edge's correction moves is checked
  // again and no vertex is left inside a shell.
  if (edges_) respond_edges(m, s, h, threads);
  respond_vertices(m, s, h, threads);
  // Then the colliders' corners and edges against the triangles between the vertices, and once
  // more each vertex they moved: a corner's correction moves a triangle's three vertices by
  // weights and could leave one inside the shell (the thin table's top, at its corner).
  if (features_.empty()) return stats_.contacts > 0;
  stats_.contacts += features_.respond(colliders_, sweeps_, m, start_, s, threads);
  for (const std::int32_t i : features_.moved()) {
    double depth = 0.0;
    if (vertex(std::size_t(i), m, s, h, depth))
      stats_.max_depth = std::max(stats_.max_depth, depth);
  }
  return stats_.contacts > 0;
}

// The grid's edges in four rounds - along u from even then odd columns, along v from even then
// odd rows - so that no two edges of a round share a vertex and a round runs in parallel with
// the same result for any thread count. Only edges with an end in a block near a collider.
template <class T>
void ContactResponse<T>::respond_edges(const Model<T>& m, State<T>& s, double h, int threads) {
  auto near = [&](std::size_t v) { return blocks_[v / kBlockSize].near; };
  for (int round = 0; round < 4; ++round) {
    const std::vector<EdgeRun>& runs = round < 2 ? rows_ : columns_;
    const int parity = round % 2;
    int contacts = 0;
    double depth = 0.0;
    const long count = static_cast<long>(runs.size());
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1) \
    reduction(+ : contacts) reduction(max : depth)
    for (long k = 0; k < count; ++k) {
      const EdgeRun& run = runs[static_cast<std::size_t>(k)];
      // A run of edges (first + e step, first + e step + step): along u, consecutive vertices
      // of a row; along v, a row's vertices to the next row's.
      if (run.step == 1) {
        for (int e = parity; e < run.count; e += 2) {
          const auto a = static_cast<std::size_t>(run.first + e), b = a + 1;
          if ((near(a) || near(b)) && edge(a, b, m, s, h, depth)) ++contacts;
        }
      } else if ((k % 2) == parity) {
        for (int e = 0; e < run.count; ++e) {
          const auto a = static_cast<std::size_t>(run.first + e), b = a + std::size_t(run.step);
          if ((near(a) || near(b)) && edge(a, b, m, s, h, depth)) ++contacts;
        }
      }
    }
    stats_.contacts += contacts;
    stats_.max_depth = std::max(stats_.max_depth, depth);
  }
  // A mesh cloth's edges have no colouring into independent rounds: one after another, on one
  // thread (the same result for any thread count).
  double depth = 0.0;
  for (const auto& e : mesh_edges_) {
    const auto a = static_cast<std::size_t>(e[0]), b = static_cast<std::size_t>(e[1]);
    if ((near(a) || near(b)) && edge(a, b, m, s, h, depth)) ++stats_.contacts;
  }
  stats_.max_depth = std::max(stats_.max_depth, depth);
}

template class ContactResponse<float>;
template class ContactResponse<double>;

}  // namespace clothlab
