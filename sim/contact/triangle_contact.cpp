#include "sim/contact/triangle_contact.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <type_traits>

#include "sim/contact/ccd.hpp"
#include "sim/contact/intersections.hpp"
#include "sim/contact/pair_spans.hpp"
#include "sim/contact/primitive_distance.hpp"
#include "sim/contact/push_test_batch.hpp"
#include "sim/contact/rigid_fit.hpp"
#include "sim/core/parallel.hpp"
#include "sim/core/vec3_eigen.hpp"

namespace clothlab {
namespace {

// Gauss-Seidel sweeps over the pairs per substep of a pass (a second cost 1.1x the frame,
// docs/contact.md). A pass of several substeps sweeps as many times: with one sweep, passes of up
// to four substeps left the landed pile's layers 0.79 of the thickness apart, with four 0.93.
constexpr int kProximityIterations = 1;
// Pairs to push from which the two halves push on two threads (push_sweeps): a try costs about
// 0.1 us, a thread's wake-up tens.
constexpr std::size_t kParallelMinPushes = 512;
constexpr double kFriction = 0.3;  // cloth on cloth (cotton on cotton 0.3 to 0.5)
// Candidate pairs reserved per triangle when built: the pair list grows past it only in a
// tangle denser than that, once.
constexpr std::size_t kPairsPerTriangle = 16;
// Broad-phase leaf pairs and candidate pairs per triangle, and in all, beyond which the skins
// shrink to the least that covers the substep, and beyond which again the substep is undone.
// The twist (tests/stress_scenes/twist.toml) wrung into a rope holds 170 pairs a triangle at 2 s;
// the cap keeps an exploding large cloth's list under 100 MB.
constexpr std::size_t kMaxPairsPerTriangle = 256;
constexpr std::size_t kMaxPairs = std::size_t(1) << 22;
// A pass may span several substeps while no vertex moves, relative to the mean velocity of all,
// more than kPassReach thicknesses over it, and for at most kMaxPassTime (docs/contact.md section
// 7, "Passes"): cloth at rest or moving as one needs contact far less often than the integrator
// needs its substeps.
constexpr double kPassReach = 0.5;
constexpr double kMaxPassTime = 1.0 / 150.0;  // s
// Rounds of the fail-safe before every free vertex returns.
constexpr int kMaxRounds = 16;
// Leaf pairs a broad-phase piece visits between adding its counts to the shared totals.
constexpr std::size_t kFlush = 256;
// Levels of the tree unrolled into pieces for threads (2^kTaskDepth nodes against themselves).
constexpr int kTaskDepth = 5;
// Triangles in a pair of nodes below which the pair is not cut into smaller pieces: the stack on
// the ball's two cloths (6400 triangles) against each other in 64 pieces, the 32 x 32 default
// sheet's two halves in 4.
constexpr int kMinPairPiece = 1024;
// The least a vertex may stray before the pairs are collected again, in thicknesses.
constexpr double kSkin = 1.0;
// At least this many times the vertex's stray in the substep that needed the pairs again, so
// that a cloth deforming fast keeps its pairs for several substeps (each vertex its own: only
// the fast ones gather more pairs), but no more than kSkinExtra thicknesses beyond that stray.
// Measured (docs/contact.md section 7): the pile and the stack on the ball cost about 0.7x of
// kSkin 0.5 and growth 2; without the cap the swinging large sheet gathers 2.9x the pairs.
constexpr double kSkinGrowth = 8.0;
constexpr double kSkinExtra = 1.0;
// m: added to every box's pad for the rounding of its float coordinates.
constexpr double kBoxSlack = 1e-5;
// Collections of the pairs after a fail-safe whose returns bent a flat patch, before every
// free vertex returns.
constexpr int kMaxFlatRetries = 4;
// A collection keeps the flat patches that are still flat, but chooses them afresh at least
// once in this many collections. Measured (one run, 2 threads, ms a frame): the swinging
// large_sheet 157 choosing at every collection, 105 at 2 and at 4, 127 at 16 (patches kept too
// long stay small); the stack on the ball 22.9, 18.4, 20.8, 19.9.
constexpr int kChooseEvery = 4;
// The proximity pass tests every pair again once 2 growth > kMarginRefresh thickness, the growth
// of the vertices' strays since it last did (PairMargins). On the stack on the ball 0.25 skipped
// 17 500 of its 42 000 pairs a substep, 1.0 skipped 19 500 and 3.0 14 600 (6 700 were near).
constexpr double kMarginRefresh = 1.0;
// Partial sums per block of vertices for the rigid fit (or the largest stray and excess).
constexpr std::size_t kBlockSums = 15;

using V3 = Eigen::Vector3d;

template <class T>
std::array<V3, 4> gather(const Vec3Array<T>& a, const std::array<std::int32_t, 4>& v) {
  return {load3(a, std::size_t(v[0])), load3(a, std::size_t(v[1])), load3(a, std::size_t(v[2])),
          load3(a, std::size_t(v[3]))};
}

// The pair's closest points at x as weights on its four vertices: the relative position
// sum_k w_k x_k points from the triangle (or edge q) to the point (or edge p).
std::array<double, 4> closest_weights(bool edge_edge, const std::array<V3, 4>& x) {
  if (edge_edge) {
    const EdgeEdgeClosest c = closest_edge_edge(x[0], x[1], x[2], x[3]);
    return {1.0 - c.s, c.s, -(1.0 - c.t), -c.t};
  }
  const PointTriangleClosest c = closest_point_triangle(x[0], x[1], x[2], x[3]);
  return {1.0, -c.w[0], -c.w[1], -c.w[2]};
}

// Lane batch.count of the batch: the pair's four vertices at x1 and at x0.
template <class T>
void add_lane(PushTestBatch& batch, const std::array<std::int32_t, 4>& v, const Vec3Array<T>& x1,
              const Vec3Array<T>& x0, std::uint32_t pair) {
  const int lane = batch.count++;
  batch.pair[lane] = pair;
  for (std::size_t k = 0; k < 4; ++k) {
    const auto i = std::size_t(v[k]);
    for (int a = 0; a < 3; ++a) {
      batch.x1[3 * k + std::size_t(a)][lane] = double(x1.axis(a)[i]);
      batch.x0[3 * k + std::size_t(a)][lane] = double(x0.axis(a)[i]);
    }
  }
}

void copy_lane(PushTestBatch& batch, int from, int to) {
  for (std::size_t r = 0; r < 12; ++r) {
    batch.x1[r][to] = batch.x1[r][from];
    batch.x0[r][to] = batch.x0[r][from];
  }
}

[[gnu::always_inline]] inline V3 combine(const std::array<double, 4>& w,
                                         const std::array<V3, 4>& x) {
  return w[0] * x[0] + w[1] * x[1] + w[2] * x[2] + w[3] * x[3];
}

// Whether two boxes meet.
template <class Box>
bool near(const Box& a, const Box& b) {
  for (std::size_t k = 0; k < 3; ++k)
    if (a.lo[k] > b.hi[k] || b.lo[k] > a.hi[k]) return false;
  return true;
}

// Whether the box around the pair's first side (the point, or edge p) comes within d of the box
// around its other side (the triangle, or edge q) along every axis, each vertex k spanning
// lo[k] .. hi[k].
bool sides_within(bool edge_edge, const std::array<V3, 4>& lo, const std::array<V3, 4>& hi,
                  double d) {
  const std::size_t split = edge_edge ? 2 : 1;
  V3 lo_p = lo[0], hi_p = hi[0], lo_q = lo[3], hi_q = hi[3];
  for (std::size_t k = 1; k < split; ++k) {
    lo_p = lo_p.cwiseMin(lo[k]);
    hi_p = hi_p.cwiseMax(hi[k]);
  }
  for (std::size_t k = split; k < 3; ++k) {
    lo_q = lo_q.cwiseMin(lo[k]);
    hi_q = hi_q.cwiseMax(hi[k]);
  }
  return (lo_p.array() <= hi_q.array() + d).all() && (lo_q.array() <= hi_p.array() + d).all();
}

// The cloth of each vertex and of each triangle (the tree keeps the cloths in their own subtrees,
// so each can be one flat patch) and the triangles' centroids at rest.
template <class T>
typename TriangleContact<T>::RestLayout rest_layout(const Model<T>& m) {
  typename TriangleContact<T>::RestLayout out;
  out.vertex_cloth = vertex_cloths(m.cloths, m.n);
  out.triangle_cloth.resize(m.triangles.size());
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    out.triangle_cloth[t] = out.vertex_cloth[std::size_t(m.triangles[t][0])];
  out.centroids = triangle_centroids(m.triangles, points_of(m.rest_positions));
  return out;
}

// Each cloth's centroids moved a third of its extent along every axis, those past the far side
// wrapped round to the near one: a tree cut from them by median splits has its cuts where the
// first tree's are not (the first tree's at dyadic fractions of the extent, these a third off).
std::vector<V3> shifted_round(std::vector<V3> c, const std::vector<int>& cloth) {
  const int cloths = c.empty() ? 0 : *std::max_element(cloth.begin(), cloth.end()) + 1;
  std::vector<V3> lo(std::size_t(cloths), V3::Constant(INFINITY));
  std::vector<V3> hi(std::size_t(cloths), V3::Constant(-INFINITY));
  for (std::size_t t = 0; t < c.size(); ++t) {
    lo[std::size_t(cloth[t])] = lo[std::size_t(cloth[t])].cwiseMin(c[t]);
    hi[std::size_t(cloth[t])] = hi[std::size_t(cloth[t])].cwiseMax(c[t]);
  }
  for (std::size_t t = 0; t < c.size(); ++t) {
    const V3 extent = hi[std::size_t(cloth[t])] - lo[std::size_t(cloth[t])];
    for (long a = 0; a < 3; ++a) {
      if (!(extent[a] > 0.0)) continue;
      const double u = c[t][a] - lo[std::size_t(cloth[t])][a] + extent[a] / 3.0;
      c[t][a] = lo[std::size_t(cloth[t])][a] + (u > extent[a] ? u - extent[a] : u);
    }
  }
  return c;
}

}  // namespace

template <class T>
TriangleContact<T>::TriangleContact(const Model<T>& m, const SolverSpec& spec)
    : TriangleContact(m, spec, rest_layout(m)) {}

template <class T>
TriangleContact<T>::TriangleContact(const Model<T>& m, const SolverSpec& spec,
                                    const RestLayout& rest)
    : thickness_(spec.self_thickness),
      eta_(0.01 * spec.self_thickness),
      features_(surface_features(m.triangles, m.n)),
      bvh_(rest.centroids, rest.triangle_cloth),
      flat_(bvh_, features_, m.rest_positions, eta_),
      shifted_bvh_(shifted_round(rest.centroids, rest.triangle_cloth), rest.triangle_cloth),
      shifted_flat_(shifted_bvh_, features_, m.rest_positions, eta_),
      cloth_of_(rest.vertex_cloth) {
  x0_.resize(m.n);
  x_step_.resize(m.n);
  xc_.resize(m.n);
  triangle_box_.assign(features_.triangles.size(), FloatBox{});
  edge_box_.assign(features_.edges.size(), FloatBox{});
  pairs_.reserve(kPairsPerTriangle * m.triangles.size());
  flag_.reserve(pairs_.capacity());
  margins_.slack.reserve(pairs_.capacity());
  margins_.moved.assign(m.n, 0.0f);
  tasks_ = bvh_.tasks(kTaskDepth, kMinPairPiece);
  task_lists_.resize(tasks_.size());
  pool_.reserve(pairs_.capacity(), tasks_.size());
  returned_round_.assign(m.n, 0);
  returned_.reserve(m.n);
  block_sums_.assign(kBlockSums * block_count(m.n), 0.0);
  strays_.allow.assign(m.n, 0.0f);
  strays_.dev0.assign(m.n, 0.0f);
  seam_patch_.assign(bvh_.node_count(), -1);
  strays_.dev1.assign(m.n, 0.0f);
  push_.pushed_at.assign(m.n, 0);
  for (auto& list : push_.moved) list.reserve(m.n);
  push_.hits.reserve(pairs_.capacity());
  push_.half.reserve(pairs_.capacity());
  push_.block_start.reserve(block_count(pairs_.capacity()));
  push_.cut_values.reserve(m.n);
}

template <class T>
int TriangleContact<T>::pass_span(const State<T>& s, double h, int most, int threads) {
  const std::size_t n = s.vel.size(), blocks = block_count(n);
  // The time allows at most `cap` substeps; with one, no need to look at the velocities.
  const double cap = std::min(double(most), std::floor(kMaxPassTime / h * (1.0 + 1e-9)));
  if (cap <= 1.0 || n == 0) return span_ = 1;
  for_each_block_indexed(n, contact_threads(n, threads),
                         [&](std::size_t b, std::size_t lo, std::size_t hi) {
                           V3 sum = V3::Zero();
                           for (std::size_t i = lo; i < hi; ++i) sum += load3(s.vel, i);
                           for (long a = 0; a < 3; ++a)
                             block_sums_[3 * b + std::size_t(a)] = sum[a];
                         });
  V3 mean = V3::Zero();
  for (std::size_t b = 0; b < blocks; ++b)
    mean += V3(block_sums_[3 * b], block_sums_[3 * b + 1], block_sums_[3 * b + 2]);
  mean /= double(n);
  for_each_block_indexed(n, contact_threads(n, threads),
                         [&](std::size_t b, std::size_t lo, std::size_t hi) {
                           double fastest = 0.0;
                           for (std::size_t i = lo; i < hi; ++i)
                             fastest = std::max(fastest, (load3(s.vel, i) - mean).squaredNorm());
                           block_sums_[b] = fastest;
                         });
  const double fastest =
      std::sqrt(*std::max_element(block_sums_.begin(), block_sums_.begin() + long(blocks)));
  const double by_speed = kPassReach * thickness_ / std::max(fastest * h, 1e-300);
  span_ = int(std::clamp(std::floor(by_speed), 1.0, cap));
  return span_;
}

template <class T>
void TriangleContact<T>::begin(const State<T>& s, int threads) {
  x0_ = s.pos;  // same size: copies without allocating
  // Something moved the cloth between substeps (a reset, a state set from outside). With one
  // flat patch over everything there are no pairs to keep; the patch's own test covers x0.
  if (stale_ || all_flat()) return;
  const RigidFit fit = fit_rigid(x0_, threads);
  strays_.rotation0 = fit.rotation;
  strays_.shrink = 1.0;
  const Stray stray = deviations(x0_, fit, strays_.dev0, nullptr, threads);
  strays_.stray0 = stray.most;
  if (stray.excess > 0.0) stale_ = true;
}

// The best rigid motion of all vertices from xc to x (sim/contact/rigid_fit.hpp). A rigid motion
// changes no distance, so a falling or swinging cloth keeps its pairs. In double, by blocks
// summed in block order (the same answer for any thread count).
template <class T>
RigidFit TriangleContact<T>::fit_rigid(const Vec3Array<T>& x, int threads) {
  const std::size_t n = xc_.size(), blocks = block_count(n);
  for_each_block_indexed(n, contact_threads(n, threads),
                         [&](std::size_t b, std::size_t lo, std::size_t hi) {
                           V3 sum_c = V3::Zero(), sum_x = V3::Zero();
                           Eigen::Matrix3d cross = Eigen::Matrix3d::Zero();
                           for (std::size_t i = lo; i < hi; ++i) {
                             const V3 c = load3(xc_, i), p = load3(x, i);
                             sum_c += c;
                             sum_x += p;
                             cross.noalias() += c * p.transpose();
                           }
                           double* out = &block_sums_[kBlockSums * b];
                           for (long a = 0; a < 3; ++a) out[a] = sum_c[a], out[3 + a] = sum_x[a];
                           for (long a = 0; a < 9; ++a) out[6 + a] = cross.data()[a];
                         });
  RigidFit fit;
  Eigen::Matrix3d cross = Eigen::Matrix3d::Zero();
  for (std::size_t b = 0; b < blocks; ++b) {
    const double* in = &block_sums_[kBlockSums * b];
    fit.from += V3(in[0], in[1], in[2]);
    fit.to += V3(in[3], in[4], in[5]);
    cross += Eigen::Map<const Eigen::Matrix3d>(in + 6);
  }
  const double count = double(std::max<std::size_t>(n, 1));
  fit.from /= count;
  fit.to /= count;
  fit.rotation = kabsch_rotation(cross - count * fit.from * fit.to.transpose());
  return fit;
}

// Each vertex's stray from the fit, |x_i - to - R (xc_i - from)| rounded up, into dev; the
// largest, and the largest excess of max(dev_i, also_i) over what vertex i may stray (its
// allowance less the shrink's share, see strays_.allow).
template <class T>
StraySummary TriangleContact<T>::deviations(const Vec3Array<T>& x, const RigidFit& fit,
                                            std::vector<float>& dev, const std::vector<float>* also,
                                            int threads) {
  const std::size_t n = xc_.size(), blocks = block_count(n);
  const double slack = (1.0 - strays_.shrink) * 0.5 * thickness_;
  const Eigen::Matrix3d& r = fit.rotation;
  const double shrink = strays_.shrink;
  for_each_block_indexed(
      n, contact_threads(n, threads), [&](std::size_t b, std::size_t lo, std::size_t hi) {
        // One vector lane a vertex: the fit's terms as scalars, the arrays as plain pointers.
        const T* __restrict px = x.x.data(), * __restrict py = x.y.data(), * __restrict pz = x.z.data();
        const T *__restrict cx = xc_.x.data(), *__restrict cy = xc_.y.data(),
                *__restrict cz = xc_.z.data();
        float* __restrict out = dev.data();
        const float* __restrict before = also ? also->data() : nullptr;
        const float* __restrict allow = strays_.allow.data();
        const double f0 = fit.from.x(), f1 = fit.from.y(), f2 = fit.from.z();
        const double t0 = fit.to.x(), t1 = fit.to.y(), t2 = fit.to.z();
        const double r00 = r(0, 0), r01 = r(0, 1), r02 = r(0, 2), r10 = r(1, 0), r11 = r(1, 1),
                     r12 = r(1, 2), r20 = r(2, 0), r21 = r(2, 1), r22 = r(2, 2);
        double most = 0.0, excess = -INFINITY;
        const auto sweep = [&](auto with_before) {
#pragma omp simd reduction(max : most, excess)
          for (std::size_t i = lo; i < hi; ++i) {
            const double v0 = double(cx[i]) - f0, v1 = double(cy[i]) - f1, v2 = double(cz[i]) - f2;
            const double e0 = (double(px[i]) - t0) - (r00 * v0 + r01 * v1 + r02 * v2);
            const double e1 = (double(py[i]) - t1) - (r10 * v0 + r11 * v1 + r12 * v2);
            const double e2 = (double(pz[i]) - t2) - (r20 * v0 + r21 * v1 + r22 * v2);
            const double d = std::sqrt(e0 * e0 + e1 * e1 + e2 * e2);
            const float up = float(d * (1.0 + 1e-6) + 1e-12);  // rounded up
            out[i] = up;
            most = most < d ? d : most;  // std::max's choice within a lane
            float moved = up;
            if constexpr (decltype(with_before)::value)
              moved = moved < before[i] ? before[i] : moved;
            const double over = double(moved) + slack - shrink * double(allow[i]);
            excess = excess < over ? over : excess;
          }
        };
        if (before) {
          sweep(std::true_type{});
        } else {
          sweep(std::false_type{});
        }
        block_sums_[2 * b] = most;
        block_sums_[2 * b + 1] = excess;
      });
  Stray out{0.0, -INFINITY};
  for (std::size_t b = 0; b < blocks; ++b) {
    out.most = std::max(out.most, block_sums_[2 * b]);
    out.excess = std::max(out.excess, block_sums_[2 * b + 1]);
  }
  return out;
}

// What each vertex may stray from xc before a pair left out could come within the thickness:
// kSkin thicknesses, or `growth` times its stray in the substep that needed the pairs but no more
// than kSkinExtra thicknesses beyond that stray (a cloth deforming fast keeps its pairs for a
// few substeps, without gathering pairs from afar), and at least what covers that substep itself
// (its stray, and the shrink's share, below the allowance less that share).
template <class T>
void TriangleContact<T>::set_allowances(double growth, int threads) {
  const double base = kSkin * thickness_, extra = kSkinExtra * thickness_;
  const double slack = (1.0 - strays_.shrink) * 0.5 * thickness_;
  for_each_block(strays_.allow.size(), contact_threads(strays_.allow.size(), threads),
                 [&](std::size_t begin, std::size_t end) {
                   for (std::size_t i = begin; i < end; ++i) {
                     const double d = double(strays_.dev0[i]);
                     strays_.allow[i] = float(std::max({base, std::min(growth * d, d + extra),
                                                        (d + slack) / strays_.shrink}) *
                                              (1.0 + 1e-6));
                   }
                 });
}

// Each triangle's and edge's box around its vertices where the pairs are collected (xc), padded
// by half the thickness and the largest allowance of its vertices (and kBoxSlack for the floats'
// rounding): two features within the thickness and their allowances have boxes that meet.
template <class T>
void TriangleContact<T>::feature_boxes(int threads) {
  const auto box_of = [&](const auto& vertices) {
    float allow = 0.0f;
    for (int v : vertices) allow = std::max(allow, strays_.allow[std::size_t(v)]);
    const float pad = float(0.5 * thickness_ + kBoxSlack) + allow;
    FloatBox b;
    for (std::size_t a = 0; a < 3; ++a) {
      const AlignedVector<T>& axis = xc_.axis(int(a));
      b.lo[a] = b.hi[a] = float(axis[std::size_t(vertices[0])]);
      for (std::size_t k = 1; k < vertices.size(); ++k) {
        b.lo[a] = std::min(b.lo[a], float(axis[std::size_t(vertices[k])]));
        b.hi[a] = std::max(b.hi[a], float(axis[std::size_t(vertices[k])]));
      }
      b.lo[a] -= pad;
      b.hi[a] += pad;
    }
    return b;
  };
  for_each_block(triangle_box_.size(), contact_threads(triangle_box_.size(), threads),
                 [&](std::size_t begin, std::size_t end) {
                   for (std::size_t t = begin; t < end; ++t)
                     triangle_box_[t] = box_of(features_.triangles[t]);
                 });
  for_each_block(edge_box_.size(), contact_threads(edge_box_.size(), threads),
                 [&](std::size_t begin, std::size_t end) {
                   for (std::size_t e = begin; e < end; ++e)
                     edge_box_[e] = box_of(features_.edges[e]);
                 });
}

// The pairs are collected at the positions now (xc). A pair is kept when it is within the
// thickness plus the allowances of its two sides there (strays_.allow, each side's largest): while
// no vertex strays beyond its allowance from xc (after the best rigid motion, less the shrink's
// share), no other pair can come within the thickness.
template <class T>
bool TriangleContact<T>::collect_pairs(const State<T>& s, int threads) {
  xc_ = s.pos;
  tangled_ = false;
  const RigidFit fit = fit_rigid(x0_, threads);
  strays_.rotation0 = fit.rotation;
  strays_.rotation1.setIdentity();
  strays_.shrink = interpolated_rotation_shrink(strays_.rotation0, strays_.rotation1);
  strays_.stray0 = deviations(x0_, fit, strays_.dev0, nullptr, threads).most;
  strays_.stray1 = 0.0;
  std::fill(strays_.dev1.begin(), strays_.dev1.end(), 0.0f);
  stale_ = false;
  // The patches that cannot touch themselves over the substep under way, skipped below: those
  // chosen before while they stay flat over it (a collection for strayed vertices alone), but
  // chosen afresh at least every kChooseEvery collections, so that they grow as cloth flattens.
  const bool keep = ++kept_choices_ < kChooseEvery &&
                    flat_.patch_count() + shifted_flat_.patch_count() > 0 &&
                    still_flat(s.pos, threads);
  if (!keep) {
    kept_choices_ = 0;
    flat_.choose(bvh_, features_, x0_, s.pos, threads);
    shifted_flat_.choose(shifted_bvh_, features_, x0_, s.pos, threads);
    seam_patches();
  }
  pairs_.clear();
  flag_.clear();
  margins_.valid = false;
  if (all_flat()) return true;
  // Grown skins first; when they gather more pairs than the bound (a sudden fast motion), the
  // least skins that cover the substep under way, before the substep is undone.
  for (const double growth : {kSkinGrowth, 1.0}) {
    set_allowances(growth, threads);
    if (gather_pairs(threads)) return true;
    // No vertex strayed enough for the growth to matter: the least skins are these.
    if (kSkinGrowth * strays_.stray0 <= kSkin * thickness_) break;
  }
  stale_ = true;
  tangled_ = true;  // at xc
  return false;
}

// After a tangle: whether the cloth is still where it was (within kSkin thicknesses of xc after
// the rigid fit), so that a new collection would find the same tangle. The undo returns every
// free vertex, so a tangle that stays is undone again without walking the tree each substep.
template <class T>
bool TriangleContact<T>::still_tangled(const State<T>& s, int threads) {
  if (!tangled_) return false;
  // strays_.dev1 as scratch: after a tangle the pairs are stale and a collection resets it.
  const double most =
      deviations(s.pos, fit_rigid(s.pos, threads), strays_.dev1, nullptr, threads).most;
  tangled_ = most <= kSkin * thickness_;
  return tangled_;
}

// The pairs of triangles whose padded boxes meet give their owned features' pairs; the tree's
// pieces run in parallel, each into its own list, joined in order. False beyond the bound.
template <class T>
bool TriangleContact<T>::gather_pairs(int threads) {
  feature_boxes(threads);
  std::vector<Box3>& boxes = bvh_.leaf_boxes();
  for (std::size_t t = 0; t < boxes.size(); ++t) {
    const FloatBox& b = triangle_box_[t];
    boxes[t] = {V3(b.lo[0], b.lo[1], b.lo[2]), V3(b.hi[0], b.hi[1], b.hi[2])};
  }
  bvh_.refit();
  const std::size_t bound = std::min(kMaxPairsPerTriangle * boxes.size(), kMaxPairs);
  // What the first tree's traversal skips: its own flat patches within themselves, and pairs of
  // nodes inside one flat patch of the second tree.
  struct Cull {
    const FlatPatches<T>& flat;
    const std::vector<std::int32_t>& seam_patch;
    bool self(int n) const { return flat.skipped(n); }
    bool pair(int a, int b) const {
      const std::int32_t p = seam_patch[std::size_t(a)];
      return p >= 0 && p == seam_patch[std::size_t(b)];
    }
  };
  const Cull cull{flat_, seam_patch_};
  for (;;) {
    const Gathered g = run_pieces(threads, bound, cull);
    if (g == Gathered::tangle) return false;
    if (g == Gathered::all) break;
    pool_.grow();  // the pool ran out before the bound: once, when the list outgrows it
  }
  for (const PairPool::List& list : task_lists_) pool_.append_to(list, pairs_);
  flag_.resize(pairs_.size());
  push_.hits.reserve(pairs_.capacity());
  push_.block_start.reserve(block_count(pairs_.capacity()));
  // The pushes' halves hold until the next collection: each pair's, once.
  const auto& along = xc_.axis(widest_axis(xc_));
  push_.cut_values.assign(along.begin(), along.end());
  const T cut = median_of(push_.cut_values);
  push_.half.resize(pairs_.size());
  for_each_block(pairs_.size(), contact_threads(pairs_.size(), threads),
                 [&](std::size_t b, std::size_t e) {
                   for (std::size_t k = b; k < e; ++k)
                     push_.half[k] = std::uint8_t(pair_half(pairs_[k].v, along, cut));
                 });
  margins_.slack.resize(pairs_.size());
  margins_.max_dist = 0.0;
  for (const Pair& p : pairs_) margins_.max_dist = std::max(margins_.max_dist, double(p.dist));
  return true;
}

// The broad phase's pieces on the threads, each into its own list of the pool.
template <class T>
template <class Cull>
typename TriangleContact<T>::Gathered TriangleContact<T>::run_pieces(int threads, std::size_t bound,
                                                                     const Cull& cull) {
  pool_.clear();
  const long count = long(tasks_.size());
  // The pieces add their leaf pairs and pairs to shared totals every kFlush leaves; once a total
  // passes the bound every piece stops. The true totals alone decide whether they pass it, so
  // the outcome (a tangle or the full list) is the same for any thread count, and a tangle is
  // found after about the bound's worth of work.
  std::atomic<std::size_t> all_leaves{0}, all_pairs{0};
  std::atomic<bool> tangle{false};
  run_team(threads, [&] {
#pragma omp for schedule(dynamic, 1)
    for (long k = 0; k < count; ++k) {
      PairPool::List& list = task_lists_[std::size_t(k)];
      list = {};
      std::size_t leaves = 0, flushed = 0;
      const auto flush = [&] {
        const bool past = all_leaves.fetch_add(leaves) + leaves > bound ||
                          all_pairs.fetch_add(list.size - flushed) + (list.size - flushed) > bound;
        leaves = 0;
        flushed = list.size;
        if (past) tangle.store(true, std::memory_order_relaxed);
        return !past && !tangle.load(std::memory_order_relaxed);
      };
      bvh_.run(tasks_[std::size_t(k)], cull, [&](int ta, int tb) {
        return add_pairs(ta, tb, list) && (++leaves < kFlush || flush());
      });
      flush();
    }
  });
  if (tangle.load()) return Gathered::tangle;
  return pool_.exhausted() ? Gathered::out_of_room : Gathered::all;
}

// For each node of the first tree, the second tree's flat patch that holds all its triangles, or
// -1 (bottom-up: children come after their parents).
template <class T>
void TriangleContact<T>::seam_patches() {
  for (std::size_t n = bvh_.node_count(); n-- > 0;) {
    const int l = bvh_.left(int(n)), r = bvh_.right(int(n));
    if (l < 0) {
      seam_patch_[n] = shifted_flat_.patch_of(*bvh_.triangles_begin(int(n)));
    } else {
      const std::int32_t a = seam_patch_[std::size_t(l)];
      seam_patch_[n] = a == seam_patch_[std::size_t(r)] ? a : -1;
    }
  }
}

template <class T>
bool TriangleContact<T>::add_pairs(int ta, int tb, PairPool::List& out) {
  const auto& A = features_.triangles[std::size_t(ta)];
  const auto& B = features_.triangles[std::size_t(tb)];
  const auto points_on = [&](int owner, const std::array<int, 3>& P, int face) {
    const std::uint8_t mask = features_.owned_vertices[std::size_t(owner)];
    const auto& F = features_.triangles[std::size_t(face)];
    for (int k = 0; k < 3; ++k) {
      const int v = P[std::size_t(k)];
      if ((mask & (1u << k)) && !shares_vertex(F, v) &&
          near(point_box(v), triangle_box_[std::size_t(face)]) &&
          !keep_if_close({{v, F[0], F[1], F[2]}, false}, out))
        return false;
    }
    return true;
  };
  if (!points_on(ta, A, tb) || !points_on(tb, B, ta)) return false;
  const std::uint8_t ma = features_.owned_edges[std::size_t(ta)];
  const std::uint8_t mb = features_.owned_edges[std::size_t(tb)];
  if (!ma || !mb) return true;
  for (int i = 0; i < 3; ++i) {
    if (!(ma & (1u << i))) continue;
    const auto ei = std::size_t(features_.triangle_edges[std::size_t(ta)][std::size_t(i)]);
    const auto& e = features_.edges[ei];
    for (int j = 0; j < 3; ++j) {
      if (!(mb & (1u << j))) continue;
      const auto fj = std::size_t(features_.triangle_edges[std::size_t(tb)][std::size_t(j)]);
      const auto& f = features_.edges[fj];
      if (!shares_vertex(e, f) && near(edge_box_[ei], edge_box_[fj]) &&
          !keep_if_close({{e[0], e[1], f[0], f[1]}, true}, out))
        return false;
    }
  }
  return true;
}

// A pair is kept when its distance at xc is within the thickness and the allowances of its two
// sides (a point of a triangle or an edge strays no farther than its farthest vertex).
template <class T>
bool TriangleContact<T>::keep_if_close(Pair p, PairPool::List& out) {
  const auto a = [&](int k) { return strays_.allow[std::size_t(p.v[std::size_t(k)])]; };
  const float first = p.edge_edge ? std::max(a(0), a(1)) : a(0);
  const float other = std::max({a(2), a(3), p.edge_edge ? a(2) : a(1)});
  const double d = thickness_ + double(first) + double(other);
  const std::array<V3, 4> x = gather(xc_, p.v);
  // The gap between the boxes around the two sides bounds their distance from below: of the
  // pairs the exact test would drop, four in five on large_sheet go without it, an eighth on the
  // stack on the ball (docs/contact.md section 7, "The exact tests").
  if (box_gap2(p.edge_edge, x) > d * d) return true;
  const double dist2 =
      pair_dist2(p.edge_edge ? PrimitivePair::edge_edge : PrimitivePair::point_triangle, x);
  if (dist2 > d * d) return true;
  p.dist = float(std::sqrt(dist2) * (1.0 - 1e-6));
  return pool_.push(out, p);
}

template <class T>
typename TriangleContact<T>::FloatBox TriangleContact<T>::point_box(int v) const {
  const float pad = float(0.5 * thickness_ + kBoxSlack) + strays_.allow[std::size_t(v)];
  FloatBox b;
  for (std::size_t a = 0; a < 3; ++a) {
    const float c = float(xc_.axis(int(a))[std::size_t(v)]);
    b.lo[a] = c - pad;
    b.hi[a] = c + pad;
  }
  return b;
}

// Whether a pair needs its proximity constraint now: within the thickness along every axis,
// and then closer than it or on the other side than at x0.
template <class T>
bool TriangleContact<T>::needs_push(const Pair& p, const Vec3Array<T>& x) const {
  const std::array<V3, 4> x1 = gather(x, p.v);
  if (!points_within(p.edge_edge, x1, thickness_)) return false;
  const std::array<double, 4> w = closest_weights(p.edge_edge, x1);
  const V3 r1 = combine(w, x1);
  return r1.squaredNorm() < thickness_ * thickness_ || r1.dot(combine(w, gather(x0_, p.v))) <= 0.0;
}

// One pair's proximity constraint: (sum_k w_k x_k) . n >= thickness, where n is the direction
// between the closest points now, or at x0 when the pair has passed through since (the two
// disagree), so a pair that crossed in the substep is pushed back to the side it came from.
template <class T>
bool TriangleContact<T>::push_apart(const Model<T>& m, State<T>& s, const Pair& p,
                                    std::uint64_t stamp, std::vector<std::int32_t>& moved) {
  const std::array<V3, 4> x = gather(s.pos, p.v);
  // Farther apart than the thickness along some axis: nothing to do (most candidates). A pair
  // that passed through each other by more than that is the fail-safe's.
  if (!points_within(p.edge_edge, x, thickness_)) return false;
  const std::array<double, 4> w = closest_weights(p.edge_edge, x);
  const V3 r1 = combine(w, x);
  const double th = thickness_;
  const V3 r0 = combine(w, gather(x0_, p.v));
  // A pair that stayed more than the thickness apart and on its side needs nothing.
  if (r1.squaredNorm() >= th * th && r1.dot(r0) > 0.0) return false;
  V3 n;
  if (r1.dot(r0) > 0.0 && r1.squaredNorm() > 1e-24)
    n = r1.normalized();
  else if (r0.squaredNorm() > 1e-24)
    n = r0.normalized();
  else
    return false;
  const double depth = th - r1.dot(n);
  if (depth <= 0.0) return false;
  // Features of one cloth that close at rest are its springs' business.
  if (cloth_of_[std::size_t(p.v[0])] == cloth_of_[std::size_t(p.v[3])] &&
      combine(w, gather(m.rest_positions, p.v)).squaredNorm() < th * th)
    return false;
  std::array<double, 4> inv;
  double W = 0.0;
  for (std::size_t k = 0; k < 4; ++k) {
    inv[k] = double(m.inv_mass[std::size_t(p.v[k])]);
    W += w[k] * w[k] * inv[k];
  }
  if (!(W > 0.0)) return false;
  // Coulomb friction on the relative tangential motion of the substep, bounded by mu depth.
  const V3 slide = (r1 - r0) - (r1 - r0).dot(n) * n;
  const double len = slide.norm();
  const V3 stop = len <= kFriction * depth ? V3(-slide) : V3(-(kFriction * depth / len) * slide);
  // Not into a collider that holds a vertex (sim/contact/collider_touches.hpp).
  if (touches_) W = hold_against_colliders(*touches_, p.v, w, depth * n + stop, inv, W);
  const V3 correction = (depth * n + stop) / W;
  for (std::size_t k = 0; k < 4; ++k) {
    const auto i = std::size_t(p.v[k]);
    if (push_.pushed_at[i] == 0) {  // where the integrator left it, for the velocity
      moved.push_back(p.v[k]);
      x_step_.x[i] = s.pos.x[i];
      x_step_.y[i] = s.pos.y[i];
      x_step_.z[i] = s.pos.z[i];
    }
    push_.pushed_at[i] = stamp;
    store3(s.pos, i, V3(x[k] + w[k] * inv[k] * correction));
  }
  return true;
}

// kProximityIterations sweeps per substep of the pass over the pairs flagged hit, Gauss-Seidel
// in pair order within each half of the vertices (sim/contact/push_halves.hpp): the two halves at
// once on two threads, then the pairs across the cut, each sweep. A pair is tried again only
// once a push since its last try moved one of its vertices: push_apart reads nothing else that
// changes within the pass, so the try skipped would have found nothing to do.
template <class T>
int TriangleContact<T>::push_sweeps(const Model<T>& m, State<T>& s, int threads) {
  list_hits(threads);
  const int sweeps = kProximityIterations * span_;
  std::array<int, 3> pushes{};
  run_team(threads_for(push_.hits.size(), threads, kParallelMinPushes) > 1 ? 2 : 1, [&] {
    for (int it = 0; it < sweeps; ++it) {
#pragma omp for schedule(static)
      for (int half = 0; half < 2; ++half) pushes[std::size_t(half)] += push_sweep(m, s, it, half);
#pragma omp single
      pushes[2] += push_sweep(m, s, it, 2);
    }
  });
  return pushes[0] + pushes[1] + pushes[2];
}

// The pairs flagged hit, by half and in pair order within each: counted per block of pairs and
// listed from each block's offset, both in parallel (a serial pass over the list was 2 % of the
// stack on the ball's samples on two threads, the other thread waiting meanwhile).
template <class T>
void TriangleContact<T>::count_hits(std::size_t block, std::size_t lo, std::size_t hi) {
  std::array<std::size_t, 3> c{};
  for (std::size_t k = lo; k < hi; ++k)
    if (flag_[k] == PairFlag::hit) ++c[push_.half[k]];
  push_.block_start[block] = c;
}

// After flag_proximity, which counted each block's hits (count_hits) while they were in cache.
template <class T>
void TriangleContact<T>::list_hits(int threads) {
  const std::size_t n = pairs_.size();
  const int team = contact_threads(n, threads);
  std::array<std::size_t, 3> count{};
  for (std::array<std::size_t, 3>& start : push_.block_start)
    for (std::size_t h = 0; h < 3; ++h) {
      const std::size_t here = start[h];
      start[h] = count[h];
      count[h] += here;
    }
  push_.hits.resize(count[0] + count[1] + count[2]);
  push_.begin = {0, count[0], count[0] + count[1], push_.hits.size()};
  for_each_block_indexed(n, team, [&](std::size_t b, std::size_t lo, std::size_t hi) {
    std::array<std::size_t, 3> next = push_.block_start[b];
    for (std::size_t h = 0; h < 3; ++h) next[h] += push_.begin[h];
    for (std::size_t k = lo; k < hi; ++k)
      if (flag_[k] == PairFlag::hit) push_.hits[next[push_.half[k]]++] = {std::uint32_t(k), 0};
  });
}

// Stamps grow along the serial order: sweep after sweep, in each the first half, the second and
// the pairs across the cut, each taking room for one push per hit.
template <class T>
int TriangleContact<T>::push_sweep(const Model<T>& m, State<T>& s, int sweep, int half) {
  const std::uint64_t room = push_.hits.size() + 1;
  std::uint64_t last = (std::uint64_t(sweep) * 3 + std::uint64_t(half)) * room;
  int pushes = 0;
  for (std::size_t h = push_.begin[std::size_t(half)]; h < push_.begin[std::size_t(half) + 1];
       ++h) {
    auto& hit = push_.hits[h];
    const Pair& p = pairs_[hit.pair];
    if (sweep > 0 && std::none_of(p.v.begin(), p.v.end(), [&](std::int32_t v) {
          return push_.pushed_at[std::size_t(v)] > hit.tried;
        }))
      continue;
    hit.tried = last;
    if (push_apart(m, s, p, last + 1, push_.moved[std::size_t(half)])) {
      ++last;
      ++pushes;
    }
  }
  return pushes;
}

template <class T>
bool TriangleContact<T>::meets(const Pair& p, const Vec3Array<T>& x) const {
  const std::array<V3, 4> x0 = gather(x0_, p.v), x1 = gather(x, p.v);
  // Swept boxes that stay apart by more than eta cannot meet.
  std::array<V3, 4> lo, hi;
  for (std::size_t k = 0; k < 4; ++k) {
    lo[k] = x0[k].cwiseMin(x1[k]);
    hi[k] = x0[k].cwiseMax(x1[k]);
  }
  if (!sides_within(p.edge_edge, lo, hi, eta_)) return false;
  CcdOptions o;
  o.eta = eta_;
  o.tolerance = eta_;
  return additive_ccd(p.edge_edge ? PrimitivePair::edge_edge : PrimitivePair::point_triangle, x0,
                      x1, o) >= 0.0;
}

// flag_[k] = test(k, pairs_[k]) for every pair, in parallel (each pair its own byte: the same
// flags for any thread count).
template <class T>
template <class Test>
void TriangleContact<T>::flag_pairs(int threads, Test&& test) {
  for_each_block(pairs_.size(), contact_threads(pairs_.size(), threads),
                 [&](std::size_t b, std::size_t e) {
                   for (std::size_t k = b; k < e; ++k) flag_[k] = test(k, pairs_[k]);
                 });
}

// Vertex i back where the substep started, at rest.
template <class T>
void TriangleContact<T>::return_vertex(State<T>& s, std::size_t i) const {
  s.pos.x[i] = x0_.x[i];
  s.pos.y[i] = x0_.y[i];
  s.pos.z[i] = x0_.z[i];
  s.vel.x[i] = s.vel.y[i] = s.vel.z[i] = T(0);
}

// Returns the pair's vertices that may move to x0 with zero velocity; whether it returned any.
template <class T>
bool TriangleContact<T>::return_vertices(const Model<T>& m, State<T>& s, const Pair& p, int round) {
  bool any = false;
  for (std::int32_t v : p.v) {
    const auto i = std::size_t(v);
    if (returned_round_[i] != 0 || m.inv_mass[i] == T(0)) continue;
    returned_round_[i] = round;
    returned_.push_back(v);
    return_vertex(s, i);
    any = true;
  }
  return any;
}

// Rounds of the fail-safe; returns the vertices returned to x0. The first round tests every pair
// (in parallel), later ones only the pairs of vertices the last round returned.
template <class T>
int TriangleContact<T>::fail_safe(const Model<T>& m, State<T>& s, int threads, bool near_only) {
  returned_.clear();
  int unresolved = 0;
  // Every vertex is at x1 (this round only): the distance bound holds over the substep.
  flag_pairs(threads, [&](std::size_t k, const Pair& p) {
    if (near_only && flag_[k] == PairFlag::clear) return PairFlag::clear;
    return !strays_.clear_by(p, 2.0 * eta_) && meets(p, s.pos) ? PairFlag::hit : PairFlag::clear;
  });
  for (int round = 1;; ++round) {
    if (round > kMaxRounds) {
      for (std::int32_t v : returned_) returned_round_[std::size_t(v)] = 0;
      stats_.unresolved = 0;
      return return_all(m, s);
    }
    const std::size_t before = returned_.size();
    unresolved = 0;
    for (std::size_t k = 0; k < pairs_.size(); ++k) {
      const Pair& p = pairs_[k];
      const bool met = round == 1
                           ? flag_[k] == PairFlag::hit
                           : std::any_of(p.v.begin(), p.v.end(),
                                         [&](std::int32_t v) {
                                           return returned_round_[std::size_t(v)] == round - 1;
                                         }) &&
                                 meets(p, s.pos);
      if (met && !return_vertices(m, s, p, round)) ++unresolved;
    }
    if (returned_.size() == before) break;
  }
  for (std::int32_t v : returned_) returned_round_[std::size_t(v)] = 0;
  stats_.unresolved = unresolved;
  return int(returned_.size());
}

// Which pairs need a push. A full pass tests every pair and keeps its margins; until the strays
// have grown by half a thickness since, a pass takes a pair whose margin exceeds that growth
// (PairMargins) as clear without testing it. Both give the same flags: the margin is a lower bound
// on the full test's own quantity.
template <class T>
void TriangleContact<T>::flag_proximity(const State<T>& s, int threads) {
  const double growth = margins_.valid ? growth_since_margins(threads) : INFINITY;
  const bool full = 2.0 * growth > kMarginRefresh * thickness_;
  // The skip reads one float a pair: the shrink's fall is taken at the longest pair.
  const double limit =
      2.0 * growth + std::max(0.0, margins_.shrink - strays_.shrink) * margins_.max_dist;
  if (full) {
    for (std::size_t v = 0; v < margins_.moved.size(); ++v)
      margins_.moved[v] = strays_.moved_by(std::int32_t(v));
    margins_.shrink = strays_.shrink;
    margins_.valid = true;
  }
  // The pairs the margins do not clear are tested in batches of one kind, one vector lane a pair
  // (sim/contact/push_test_batch.hpp), and those it is unsure of one by one.
  const auto run = [&](PushTestBatch& batch, bool edge_edge) {
    if (batch.count == 0) return;
    for (int i = batch.count; i < PushTestBatch::kLanes; ++i) copy_lane(batch, 0, i);
    std::array<PushVerdict, PushTestBatch::kLanes> verdict;
    if (edge_edge)
      edge_edge_push_tests(batch, thickness_, verdict.data());
    else
      point_triangle_push_tests(batch, thickness_, verdict.data());
    for (int i = 0; i < batch.count; ++i) {
      const std::size_t k = batch.pair[i];
      const bool hit = verdict[std::size_t(i)] == PushVerdict::unsure
                           ? needs_push(pairs_[k], s.pos)
                           : verdict[std::size_t(i)] == PushVerdict::push;
      flag_[k] = hit ? PairFlag::hit : PairFlag::near;
    }
    batch.count = 0;
  };
  push_.block_start.resize(block_count(pairs_.size()));
  for_each_block_indexed(pairs_.size(), contact_threads(pairs_.size(), threads),
                         [&](std::size_t block, std::size_t b, std::size_t e) {
                           std::array<PushTestBatch, 2> batches;  // point-triangle, edge-edge
                           for (std::size_t k = b; k < e; ++k) {
                             const Pair& p = pairs_[k];
                             flag_[k] = PairFlag::clear;
                             if (!full && double(margins_.slack[k]) > limit) continue;
                             const double margin = strays_.margin(p) - thickness_;
                             if (full) margins_.slack[k] = std::nextafter(float(margin), -INFINITY);
                             if (margin > 0.0) continue;
                             PushTestBatch& batch = batches[p.edge_edge ? 1 : 0];
                             add_lane(batch, p.v, s.pos, x0_, std::uint32_t(k));
                             if (batch.count == PushTestBatch::kLanes) run(batch, p.edge_edge);
                           }
                           run(batches[0], false);
                           run(batches[1], true);
                           count_hits(block, b, e);
                         });
}

template <class T>
double TriangleContact<T>::growth_since_margins(int threads) {
  const std::size_t n = margins_.moved.size(), blocks = block_count(n);
  for_each_block_indexed(
      n, contact_threads(n, threads), [&](std::size_t b, std::size_t lo, std::size_t hi) {
        double most = 0.0;  // in double: the exact difference
        for (std::size_t v = lo; v < hi; ++v)
          most =
              std::max(most, double(strays_.moved_by(std::int32_t(v))) - double(margins_.moved[v]));
        block_sums_[b] = most;
      });
  return *std::max_element(block_sums_.begin(), block_sums_.begin() + long(blocks));
}

// A tangle beyond the bound: the substep is undone.
template <class T>
bool TriangleContact<T>::undo(const Model<T>& m, State<T>& s) {
  stats_.overflow = true;
  stats_.candidates = 0;
  stats_.rolled_back = return_all(m, s);
  return true;
}

template <class T>
int TriangleContact<T>::return_all(const Model<T>& m, State<T>& s) {
  int count = 0;
  for (std::size_t i = 0; i < m.n; ++i) {
    if (m.inv_mass[i] == T(0)) continue;
    return_vertex(s, i);
    ++count;
  }
  return count;
}

// Velocities take the position change of the pushes over h, the pass's duration (only the
// vertices they moved): a pair that closed over the pass has its closing speed taken away, not
// reversed, also when the pass spans several substeps (over the last substep alone, the push of a
// pass of k substeps would send it apart at up to k times that speed).
// Returns the longest of those changes.
template <class T>
double TriangleContact<T>::update_velocities(State<T>& s, double h) {
  const double inv_h = 1.0 / h;
  double most = 0.0;
  for (std::vector<std::int32_t>& moved : push_.moved) {
    for (std::int32_t v : moved) {
      const auto i = std::size_t(v);
      const V3 change = load3(s.pos, i) - load3(x_step_, i);
      most = std::max(most, change.norm());
      store3(s.vel, i, V3(load3(s.vel, i) + inv_h * change));
      push_.pushed_at[i] = 0;
    }
    moved.clear();
  }
  return most;
}

template <class T>
bool TriangleContact<T>::still_flat(const Vec3Array<T>& x, int threads) {
  return flat_.still_flat(features_, x0_, x, threads) &&
         shifted_flat_.still_flat(features_, x0_, x, threads);
}

// The substep's end x1 against xc, and the shrink factor of the straight motion from x0.
template <class T>
void TriangleContact<T>::measure_stray1(const State<T>& s, int threads) {
  if (stale_ || all_flat()) {
    strays_.stray1 = 0.0;
    strays_.excess1 = -INFINITY;
    return;
  }
  const RigidFit fit = fit_rigid(s.pos, threads);
  strays_.rotation1 = fit.rotation;
  strays_.shrink = interpolated_rotation_shrink(strays_.rotation0, strays_.rotation1);
  const Stray stray = deviations(s.pos, fit, strays_.dev1, &strays_.dev0, threads);
  strays_.stray1 = stray.most;
  strays_.excess1 = stray.excess;
}

template <class T>
bool TriangleContact<T>::recollect_if_needed(const State<T>& s, int threads, bool& flag) {
  measure_stray1(s, threads);
  const bool needed = stale_ || strays_.excess1 > 0.0 || !still_flat(s.pos, threads);
  if (!needed) return true;
  flag = true;
  return collect_pairs(s, threads);
}

// The fail-safe returns vertices to x0, which changes the motion of the flat patches' triangles
// too: while that bends one, the pairs are collected again (without it) and the fail-safe runs
// on them; a bounded number of times, then every free vertex returns.
template <class T>
bool TriangleContact<T>::guarantee(const Model<T>& m, State<T>& s, int threads, bool near_only) {
  for (int retry = 0;; ++retry) {
    stats_.rolled_back += fail_safe(m, s, threads, near_only && retry == 0);
    if (stats_.rolled_back == 0 || still_flat(s.pos, threads)) return true;
    if (retry == kMaxFlatRetries) {
      stats_.rolled_back = return_all(m, s);
      return true;
    }
    stats_.recollected = true;
    if (!collect_pairs(s, threads)) return false;
  }
}

template <class T>
bool TriangleContact<T>::respond(const Model<T>& m, State<T>& s, double h, int threads,
                                 const ColliderTouches* touches) {
  stats_ = {};
  touches_ = touches;
  // The pairs again when a vertex has strayed past its skin since they were collected.
  if (still_tangled(s, threads)) return undo(m, s);
  measure_stray1(s, threads);
  if (stale_ || strays_.excess1 > 0.0) {
    stats_.collected = true;
    if (!collect_pairs(s, threads)) return undo(m, s);
  }
  // Which pairs need a push, in parallel; then sweeps of pushes over those, serially in pair
  // order, kProximityIterations per substep of the pass (a pair that a neighbour's push brings
  // within the thickness waits for the next pass; the fail-safe holds meanwhile).
  flag_proximity(s, threads);
  const int contacts = push_sweeps(m, s, threads);
  stats_.contacts = contacts;
  const double pushed = update_velocities(s, h);
  // The fail-safe needs every pair whose swept boxes meet: new ones if a push left a box, or if
  // a flat patch bent in the substep.
  if (!recollect_if_needed(s, threads, stats_.recollected)) return undo(m, s);
  // A pair flagged clear stayed more than the thickness apart on the straight motion to the end the
  // integrator made; the pushes moved each end by at most `pushed`, each point of the motion
  // by no more, so while 2 pushed < thickness - 2 eta it still cannot come within 2 eta (the
  // fail-safe's own bound) and its test is skipped.
  const bool near_only = !stats_.recollected && 2.0 * pushed < thickness_ - 2.0 * eta_;
  if (!guarantee(m, s, threads, near_only)) return undo(m, s);
  stats_.candidates = int(pairs_.size());
  stats_.flat_patches = int(flat_.patch_count());
  stats_.flat_triangles = int(flat_.triangles_covered());
  return contacts > 0 || stats_.rolled_back > 0;
}

template class TriangleContact<float>;
template class TriangleContact<double>;

}  // namespace clothlab
