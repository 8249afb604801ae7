// Pushes against the colliders (sim/contact/collider_touches.hpp): a vertex a collider holds
// takes no share of a push that points into that collider, the pair's constraint is met all the
// same by the others, and a push along the collider's surface or away from it is shared as
// before. The scene-level check, cloth resting on the ball staying at rest under the sheet above
// it, is ClothContact.StackOnBallHasNoCrossingInAnyFrame.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>

#include "sim/contact/collider_touches.hpp"

namespace clothlab {
namespace {

using V3 = Eigen::Vector3d;

// A vertex (0) above a triangle (1, 2, 3) on a floor with normal +y, the vertex 0.3 of the way
// from vertex 1 to the others' midpoint: weights w = (1, -b1, -b2, -b3), each inverse mass 1.
struct FloorPair {
  ColliderTouches touches;
  std::array<std::int32_t, 4> v{0, 1, 2, 3};
  std::array<double, 4> w{1.0, -0.7, -0.15, -0.15};
  std::array<double, 4> inv{1.0, 1.0, 1.0, 1.0};
  double W = 1.0 + 0.49 + 0.0225 + 0.0225;
  FloorPair() {
    touches.resize(4);
    touches.now = 7;
    for (std::size_t i = 1; i < 4; ++i) touches.hold(i, V3(0, 1, 0));
  }
  // sum_k w_k (move of k) for the push c: the constraint's change.
  V3 achieved(const V3& c, double W_used) const {
    V3 sum = V3::Zero();
    for (std::size_t k = 0; k < 4; ++k) sum += w[k] * (w[k] * inv[k] * c / W_used);
    return sum;
  }
};

TEST(CollidersHold, PushIntoTheFloorMovesOnlyTheFreeVertex) {
  FloorPair p;
  const V3 c(0.0, 0.002, 0.0);  // the vertex goes up, the triangle would go down
  const double W = hold_against_colliders(p.touches, p.v, p.w, c, p.inv, p.W);
  EXPECT_DOUBLE_EQ(W, 1.0);
  EXPECT_EQ(p.inv, (std::array<double, 4>{1.0, 0.0, 0.0, 0.0}));
  // The constraint moves by the whole push, all of it the free vertex's.
  EXPECT_LT((p.achieved(c, W) - c).norm(), 1e-15);
}

TEST(CollidersHold, SidewaysOrOutwardPushesAreSharedAsBefore) {
  for (const V3& c : {V3(0.002, 0.0, 0.0), V3(0.0, -0.002, 0.0), V3(0.002, 0.0005, 0.0)}) {
    FloorPair p;
    const double before = p.W;
    EXPECT_EQ(hold_against_colliders(p.touches, p.v, p.w, c, p.inv, p.W), before);
    EXPECT_EQ(p.inv, (std::array<double, 4>{1.0, 1.0, 1.0, 1.0}));
  }
}

TEST(CollidersHold, OnlyTheLastResponseHolds) {
  FloorPair p;
  ++p.touches.now;  // a later response that held nothing
  const V3 c(0.0, 0.002, 0.0);
  EXPECT_EQ(hold_against_colliders(p.touches, p.v, p.w, c, p.inv, p.W), p.W);
  ColliderTouches none;
  none.resize(1);
  EXPECT_FALSE(none.held(0));  // stamps and `now` both 0: nothing held before a response
}

// An edge-edge pair pinched between a floor and a ceiling, each edge's heavy end held: the free
// ends weigh 0.01 each in the pair, and held alone they would move 100 times the push, so the
// pair keeps its ordinary split.
TEST(CollidersHold, TooLittleLeftKeepsTheSplit) {
  ColliderTouches touches;
  touches.resize(4);
  touches.now = 1;
  touches.hold(0, V3(0, 1, 0));   // on the floor
  touches.hold(2, V3(0, -1, 0));  // under the ceiling
  const std::array<std::int32_t, 4> v{0, 1, 2, 3};
  const std::array<double, 4> w{0.99, 0.01, -0.99, -0.01};
  std::array<double, 4> inv{1.0, 1.0, 1.0, 1.0};
  const double W = 2.0 * (0.99 * 0.99 + 0.0001);
  // c down: the first edge moves down into the floor, the second up into the ceiling.
  EXPECT_EQ(hold_against_colliders(touches, v, w, V3(0, -0.002, 0), inv, W), W);
  EXPECT_EQ(inv, (std::array<double, 4>{1.0, 1.0, 1.0, 1.0}));
  // With the ceiling gone, the second edge takes the push.
  touches.stamp[2] = 0;
  EXPECT_DOUBLE_EQ(hold_against_colliders(touches, v, w, V3(0, -0.002, 0), inv, W),
                   W - 0.99 * 0.99);
  EXPECT_EQ(inv, (std::array<double, 4>{0.0, 1.0, 1.0, 1.0}));
}

}  // namespace
}  // namespace clothlab
