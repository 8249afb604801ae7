#include "sim/contact/push_test_batch.hpp"

// The helpers below take and return vectors by value; they are internal to this file, so GCC's
// note that such calls changed their ABI without AVX (a build without -march=native) is moot.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace clothlab {
namespace {

// Relative tolerances of the batch's answers (push_test_batch.hpp). Its sums differ from the
// scalar test's by a few units in the last place of the coordinates (about 1e-16 m a metre from
// the origin); a pair answered here is at least 1e-7 of the thickness squared, or of its
// squared separations, from either bound.
constexpr double kBoundSlack = 1e-7;
// Closest points that rounding could move far: a sliver triangle (twice its squared area under
// this share of |ab|^2 |ac|^2), nearly parallel edges (sine squared of their angle under it), or
// a side shorter than kShortest (squared, m^2).
constexpr double kIllConditioned = 1e-6;
constexpr double kShortest = 1e-16;

// One value per lane, in GCC's vector extension: the compiler emits the lanes' arithmetic and
// selects as vector instructions (a loop of scalar code with selects kept its divisions in
// branches, since a division may trap).
constexpr int kLanes = PushTestBatch::kLanes;
using Lanes = double __attribute__((vector_size(kLanes * sizeof(double))));
using Mask = long long __attribute__((vector_size(kLanes * sizeof(long long))));

struct Lanes3 {
  Lanes x, y, z;
};

Lanes load(const double* row) {
  Lanes v;
  __builtin_memcpy(&v, row, sizeof v);
  return v;
}
Lanes3 at(const double (&x)[12][kLanes], int k) {
  return {load(x[3 * k]), load(x[3 * k + 1]), load(x[3 * k + 2])};
}
Lanes3 sub(const Lanes3& a, const Lanes3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
Lanes dot(const Lanes3& a, const Lanes3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
Lanes splat(double v) {
  return Lanes{} + v;
}
Lanes pick(const Mask& m, const Lanes& a, const Lanes& b) {
  return m ? a : b;
}
Lanes lane_min(const Lanes& a, const Lanes& b) {
  return b < a ? b : a;
}
Lanes lane_max(const Lanes& a, const Lanes& b) {
  return a < b ? b : a;
}
Lanes clamp01(const Lanes& v) {
  return v < 0.0 ? splat(0.0) : (1.0 < v ? splat(1.0) : v);
}
// w0 x0 + w1 x1 + w2 x2 + w3 x3.
Lanes3 combine4(const double (&x)[12][kLanes], const Lanes& w0, const Lanes& w1, const Lanes& w2,
                const Lanes& w3) {
  const Lanes3 a = at(x, 0), b = at(x, 1), c = at(x, 2), d = at(x, 3);
  return {w0 * a.x + w1 * b.x + w2 * c.x + w3 * d.x, w0 * a.y + w1 * b.y + w2 * c.y + w3 * d.y,
          w0 * a.z + w1 * b.z + w2 * c.z + w3 * d.z};
}

// Whether the sides' boxes come within d along every axis: points_within (pair_spans.hpp), with
// the first side's vertices 0 .. split - 1. Exact: minima, maxima and one sum, as there.
template <int split>
Mask within(const double (&x)[12][kLanes], double d) {
  Mask inside = Mask{} - 1;
  for (int a = 0; a < 3; ++a) {
    const Lanes v1 = load(x[3 + a]), v2 = load(x[6 + a]);
    Lanes lo_p = load(x[a]), hi_p = lo_p, lo_q = load(x[9 + a]), hi_q = lo_q;
    if constexpr (split == 1) {
      lo_q = lane_min(lane_min(lo_q, v1), v2);
      hi_q = lane_max(lane_max(hi_q, v1), v2);
    } else {
      lo_p = lane_min(lo_p, v1);
      hi_p = lane_max(hi_p, v1);
      lo_q = lane_min(lo_q, v2);
      hi_q = lane_max(hi_q, v2);
    }
    inside &= (lo_p <= hi_q + d) & (lo_q <= hi_p + d);
  }
  return inside;
}

// The answer from the separations at both ends: a push when closer than the thickness now or
// on the other side than at the start (r1 . r0 <= 0), apart when neither, with the slack.
void verdicts(const Mask& inside, const Mask& ill, const Lanes3& r1, const Lanes3& r0, double th2,
              int count, PushVerdict* verdict) {
  const Lanes n1 = dot(r1, r1), side = dot(r1, r0);
  const Lanes slack_n = splat(kBoundSlack * th2);
  const Lanes slack_side = kBoundSlack * (n1 + dot(r0, r0)) + 1e-300;
  const Mask push = (n1 < th2 - slack_n) | (side < -slack_side);
  const Mask apart = (n1 > th2 + slack_n) & (side > slack_side);
  for (int i = 0; i < count; ++i)
    verdict[i] = !inside[i] ? PushVerdict::apart
                 : ill[i]   ? PushVerdict::unsure
                 : push[i]  ? PushVerdict::push
                 : apart[i] ? PushVerdict::apart
                            : PushVerdict::unsure;
}

}  // namespace

// Ericson 2005, section 5.1.5, every region's weights computed and the first region that holds
// (in his order) selected.
void point_triangle_push_tests(const PushTestBatch& batch, double thickness, PushVerdict* verdict) {
  const Lanes3 p = at(batch.x1, 0), a = at(batch.x1, 1), b = at(batch.x1, 2), c = at(batch.x1, 3);
  const Lanes3 ab = sub(b, a), ac = sub(c, a), ap = sub(p, a), bp = sub(p, b), cp = sub(p, c);
  const Lanes d1 = dot(ab, ap), d2 = dot(ac, ap), d3 = dot(ab, bp), d4 = dot(ac, bp),
              d5 = dot(ab, cp), d6 = dot(ac, cp);
  const Lanes vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
  const Lanes sum = va + vb + vc;
  // The face, then each region before it in the order the scalar test tries them, so that the
  // first that holds is selected last.
  Lanes v = vb / sum, w = vc / sum, u = 1.0 - v - w;
  Mask face = Mask{} - 1;
  const auto region = [&](const Mask& holds, const Lanes& nu, const Lanes& nv, const Lanes& nw) {
    u = pick(holds, nu, u);
    v = pick(holds, nv, v);
    w = pick(holds, nw, w);
    face &= ~holds;
  };
  const Lanes zero = splat(0.0), one = splat(1.0);
  const Lanes t_bc = (d4 - d3) / ((d4 - d3) + (d5 - d6)), t_ac = d2 / (d2 - d6),
              t_ab = d1 / (d1 - d3);
  region((va <= 0.0) & (d4 - d3 >= 0.0) & (d5 - d6 >= 0.0) & ((d4 - d3) + (d5 - d6) > 0.0), zero,
         1.0 - t_bc, t_bc);
  region((vb <= 0.0) & (d2 >= 0.0) & (d6 <= 0.0) & (d2 - d6 > 0.0), 1.0 - t_ac, zero, t_ac);
  region((d6 >= 0.0) & (d5 <= d6), zero, zero, one);
  region((vc <= 0.0) & (d1 >= 0.0) & (d3 <= 0.0) & (d1 - d3 > 0.0), 1.0 - t_ab, t_ab, zero);
  region((d3 >= 0.0) & (d4 <= d3), zero, one, zero);
  region((d1 <= 0.0) & (d2 <= 0.0), one, zero, zero);
  const Lanes ab2 = dot(ab, ab), ac2 = dot(ac, ac), bc2 = dot(sub(c, b), sub(c, b));
  const Mask ill = (face & ~(sum > kIllConditioned * ab2 * ac2)) | (ab2 < kShortest) |
                   (ac2 < kShortest) | (bc2 < kShortest);
  const Lanes3 r1 = combine4(batch.x1, one, -u, -v, -w);
  const Lanes3 r0 = combine4(batch.x0, one, -u, -v, -w);
  verdicts(within<1>(batch.x1, thickness), ill, r1, r0, thickness * thickness, batch.count,
           verdict);
}

// Ericson 2005, section 5.1.9: the lines' closest parameters clamped one after the other; the
// ends' parameters for s computed both and one selected, as the scalar test does.
void edge_edge_push_tests(const PushTestBatch& batch, double thickness, PushVerdict* verdict) {
  const Lanes3 p0 = at(batch.x1, 0), p1 = at(batch.x1, 1), q0 = at(batch.x1, 2),
               q1 = at(batch.x1, 3);
  const Lanes3 d1 = sub(p1, p0), d2 = sub(q1, q0), r = sub(p0, q0);
  const Lanes a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r), c = dot(d1, r), b = dot(d1, d2);
  const Lanes denom = a * e - b * b;
  const Mask ill = (a < kShortest) | (e < kShortest) | ~(denom > kIllConditioned * a * e);
  const Lanes s_free = clamp01((b * f - c * e) / denom);
  const Lanes free_t = (b * s_free + f) / e;
  const Lanes s_at0 = clamp01(-c / a), s_at1 = clamp01((b - c) / a);
  const Lanes s = free_t < 0.0 ? s_at0 : (free_t > 1.0 ? s_at1 : s_free);
  const Lanes t = free_t < 0.0 ? splat(0.0) : (free_t > 1.0 ? splat(1.0) : free_t);
  const Lanes3 r1 = combine4(batch.x1, 1.0 - s, s, -(1.0 - t), -t);
  const Lanes3 r0 = combine4(batch.x0, 1.0 - s, s, -(1.0 - t), -t);
  verdicts(within<2>(batch.x1, thickness), ill, r1, r0, thickness * thickness, batch.count,
           verdict);
}

}  // namespace clothlab
