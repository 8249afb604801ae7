// The batched proximity test (sim/contact/push_test_batch.hpp) against its scalar definition
// (triangle_contact.cpp, needs_push: the sides' boxes within the thickness, then the closest
// points now closer than the thickness, or on the other side than at the start): wherever the
// batch answers, it answers as the scalar test does, it answers nearly every well-conditioned
// pair itself, and it leaves the ill-conditioned ones (parallel edges, slivers, degenerate sides)
// to the scalar test.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <random>

#include "sim/contact/pair_spans.hpp"
#include "sim/contact/primitive_distance.hpp"
#include "sim/contact/push_test_batch.hpp"

namespace clothlab {
namespace {

using V3 = Eigen::Vector3d;
using Quad = std::array<V3, 4>;
constexpr double kPairThickness = 0.004;

// The scalar definition the batch must agree with.
bool needs_push(bool edge_edge, const Quad& x1, const Quad& x0, double th) {
  if (!points_within(edge_edge, x1, th)) return false;
  std::array<double, 4> w;
  if (edge_edge) {
    const EdgeEdgeClosest c = closest_edge_edge(x1[0], x1[1], x1[2], x1[3]);
    w = {1.0 - c.s, c.s, -(1.0 - c.t), -c.t};
  } else {
    const PointTriangleClosest c = closest_point_triangle(x1[0], x1[1], x1[2], x1[3]);
    w = {1.0, -c.w[0], -c.w[1], -c.w[2]};
  }
  const auto combine = [&](const Quad& x) {
    return V3(w[0] * x[0] + w[1] * x[1] + w[2] * x[2] + w[3] * x[3]);
  };
  const V3 r1 = combine(x1);
  return r1.squaredNorm() < th * th || r1.dot(combine(x0)) <= 0.0;
}

struct Tally {
  int push = 0, apart = 0, unsure = 0, wrong = 0;
};

// Runs the cases through the batch, lane by lane as triangle contact fills it, and counts its
// answers and those that contradict the scalar test.
Tally run_batch(bool edge_edge, const std::vector<std::pair<Quad, Quad>>& cases) {
  Tally tally;
  PushTestBatch batch;
  const auto flush = [&](std::size_t first) {
    for (int i = batch.count; i < PushTestBatch::kLanes; ++i)
      for (int r = 0; r < 12; ++r) batch.x1[r][i] = batch.x0[r][i] = batch.x1[r][0];
    std::array<PushVerdict, PushTestBatch::kLanes> verdict{};
    if (edge_edge)
      edge_edge_push_tests(batch, kPairThickness, verdict.data());
    else
      point_triangle_push_tests(batch, kPairThickness, verdict.data());
    for (int i = 0; i < batch.count; ++i) {
      const auto& [x1, x0] = cases[first + std::size_t(i)];
      const bool scalar = needs_push(edge_edge, x1, x0, kPairThickness);
      switch (verdict[std::size_t(i)]) {
        case PushVerdict::push:
          ++tally.push;
          tally.wrong += !scalar;
          break;
        case PushVerdict::apart:
          ++tally.apart;
          tally.wrong += scalar;
          break;
        case PushVerdict::unsure:
          ++tally.unsure;
          break;
      }
    }
    batch.count = 0;
  };
  std::size_t first = 0;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const int lane = batch.count++;
    for (int v = 0; v < 4; ++v)
      for (int a = 0; a < 3; ++a) {
        batch.x1[3 * v + a][lane] = cases[k].first[std::size_t(v)][a];
        batch.x0[3 * v + a][lane] = cases[k].second[std::size_t(v)][a];
      }
    if (batch.count == PushTestBatch::kLanes) {
      flush(first);
      first = k + 1;
    }
  }
  if (batch.count > 0) flush(first);
  return tally;
}

// Pairs as cloth makes them: sides a grid edge (2.5 cm) across, a thickness or so apart, moved a
// few millimetres over the pass, some of them through each other; a metre from the origin.
std::vector<std::pair<Quad, Quad>> cloth_like_pairs(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto near = [&](double scale) {
    const double a = u(rng), b = u(rng), c = u(rng);
    return V3(a * scale, b * scale, c * scale);
  };
  std::vector<std::pair<Quad, Quad>> out;
  for (int k = 0; k < 4000; ++k) {
    const V3 origin = V3(0.3, 1.0, -0.2) + near(0.5);
    Quad x1;
    for (V3& v : x1) v = origin + near(0.0125);
    // The first side lifted off the other by about the thickness, either way.
    const V3 lift = V3(0, 1, 0) * (u(rng) * 3.0 * kPairThickness);
    x1[0] += lift;
    if (k % 2) x1[1] += lift;
    Quad x0 = x1;
    for (V3& v : x0) v += near(0.003);
    out.emplace_back(x1, x0);
  }
  return out;
}

TEST(PushTestBatch, AnswersAsTheScalarTestWhereverItAnswers) {
  for (const bool edge_edge : {false, true}) {
    std::vector<std::pair<Quad, Quad>> cases = cloth_like_pairs(edge_edge ? 7 : 3);
    // For edge-edge pairs only the odd cases lift both ends of the first edge.
    const Tally t = run_batch(edge_edge, cases);
    EXPECT_EQ(t.wrong, 0) << (edge_edge ? "edge-edge" : "point-triangle");
    // It does the work itself: both answers plenty, and few left to the scalar test.
    EXPECT_GT(t.push, 400);
    EXPECT_GT(t.apart, 400);
    EXPECT_LT(t.unsure, int(cases.size()) / 50);
  }
}

// Pairs on their bounds and the ill-conditioned ones: exactly the thickness apart, parallel and
// collinear edges, a zero-length edge, a sliver and a collapsed triangle, a NaN coordinate.
TEST(PushTestBatch, LeavesTheIllConditionedToTheScalarTest) {
  const V3 o(1.0, 0.5, 0.0), x(0.025, 0, 0), z(0, 0, 0.025), up(0, kPairThickness, 0);
  std::vector<std::pair<Quad, Quad>> edges = {
      {{o + up, o + up + x, o, o + x}, {o + up, o + up + x, o, o + x}},  // parallel, at th
      {{o + up, o + up + x, o + 0.5 * x, o + 1.5 * x}, {o + up, o + up + x, o, o + x}},
      {{o + 0.5 * up, o + 0.5 * up + x, o, o + x}, {o + up, o + up + x, o, o + x}},
      {{o + 0.5 * x, o + 1.5 * x, o, o + x}, {o + up, o + up + x, o, o + x}},  // collinear
      {{o + up, o + up, o, o + z}, {o + up, o + up, o, o + z}},                // zero-length edge
  };
  const Tally e = run_batch(true, edges);
  EXPECT_EQ(e.wrong, 0);
  EXPECT_EQ(e.unsure, 5);  // all of them ill-conditioned: the scalar test answers
  std::vector<std::pair<Quad, Quad>> triangles = {
      {{o + up, o, o + x, o + z}, {o + up, o, o + x, o + z}},  // exactly the thickness above
      {{o + 0.5 * up + 0.3 * x, o, o + x, o + 1e-9 * z}, {o + up, o, o + x, o + z}},  // sliver
      {{o + up, o, o + x, o + 2.0 * x}, {o + up, o, o + x, o + 2.0 * x}},             // collapsed
      {{o + 0.5 * up + 0.3 * x + 0.3 * z, o, o + x, o + z},
       {o + up + 0.3 * x + 0.3 * z, o, o + x, o + z}},  // half the thickness above: a push
      {{o - up + 0.3 * x + 0.3 * z, o, o + x, o + z},
       {o + up + 0.3 * x + 0.3 * z, o, o + x, o + z}},  // through the triangle: a push
  };
  triangles.push_back(triangles.back());
  triangles.back().first[0].x() = NAN;  // apart, as the scalar box test answers
  const Tally t = run_batch(false, triangles);
  EXPECT_EQ(t.wrong, 0);
  EXPECT_EQ(t.unsure, 3);
  EXPECT_EQ(t.push, 2);
  EXPECT_EQ(t.apart, 1);
}

}  // namespace
}  // namespace clothlab
