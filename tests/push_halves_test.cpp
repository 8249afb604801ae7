// The halves triangle contact's pushes run on (sim/contact/push_halves.hpp): the cut lies across
// the widest axis at the median, a pair belongs to a half only when all four of its vertices do,
// and a NaN coordinate neither breaks the median nor lands a pair in both halves. Whether the
// two halves pushed at once give what one thread gives is
// ClothContact.OneAndTwoThreadsGiveTheSameBytes (the landing pile pushes about a thousand pairs a
// pass, above the two-thread threshold).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "sim/contact/push_halves.hpp"

namespace clothlab {
namespace {

TEST(PushHalves, CutLiesAcrossTheWidestAxisAtTheMedian) {
  Vec3Array<float> x;
  x.resize(5);
  const float xs[] = {0.0f, 0.1f, 0.2f, 0.3f, 0.4f}, ys[] = {0.0f, 0.9f, 0.1f, 0.5f, 0.2f},
              zs[] = {0.0f, 0.05f, 0.1f, 0.0f, 0.0f};
  for (std::size_t i = 0; i < 5; ++i) x.set(i, xs[i], ys[i], zs[i]);
  EXPECT_EQ(widest_axis(x), 1);  // y spreads 0.9, x 0.4, z 0.1
  std::vector<float> values(x.y.begin(), x.y.end());
  EXPECT_FLOAT_EQ(median_of(values), 0.2f);  // of 0, 0.1, 0.2, 0.5, 0.9
}

TEST(PushHalves, NaNSortsLastAndEndsNoMedian) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<float> values = {3.0f, nan, 1.0f, nan, 2.0f};
  // Sorted: 1, 2, 3, inf, inf.
  EXPECT_FLOAT_EQ(median_of(values), 3.0f);
  std::vector<float> none;
  EXPECT_EQ(median_of(none), 0.0f);
}

TEST(PushHalves, APairIsInAHalfOnlyWithAllFourVertices) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> c = {0.0f, 0.1f, 0.5f, 0.6f, 0.5f, nan};
  const float cut = 0.5f;
  EXPECT_EQ(pair_half({0, 1, 0, 1}, c, cut), 0);
  EXPECT_EQ(pair_half({2, 3, 4, 2}, c, cut), 1);  // on the cut counts as above it
  EXPECT_EQ(pair_half({0, 2, 3, 4}, c, cut), 2);
  EXPECT_EQ(pair_half({1, 0, 0, 2}, c, cut), 2);  // the last vertex alone across
  EXPECT_EQ(pair_half({2, 3, 5, 4}, c, cut), 1);  // NaN is not below the cut
  EXPECT_EQ(pair_half({0, 1, 5, 0}, c, cut), 2);
}

}  // namespace
}  // namespace clothlab
