// CLOTHLAB_CHECK: a broken invariant prints the expression, the values compared and the C++ file
// and line, and aborts; a true one does nothing.
#include <gtest/gtest.h>

#include "sim/core/check.hpp"

namespace clothlab {
namespace {

int two() {
  return 2;
}

TEST(CheckDeathTest, FailedComparisonNamesExpressionValuesAndPlace) {
  EXPECT_DEATH(CLOTHLAB_CHECK_EQ(two() + 1, 4),
               "check_test\\.cpp:[0-9]+: CLOTHLAB_CHECK\\(two\\(\\) \\+ 1 == 4\\) failed: 3 vs 4");
  EXPECT_DEATH(CLOTHLAB_CHECK(two() > 5), "CLOTHLAB_CHECK\\(two\\(\\) > 5\\) failed\n");
}

TEST(Check, TrueConditionsPassAndEvaluateOnce) {
  int calls = 0;
  auto counted = [&] { return ++calls; };
  CLOTHLAB_CHECK_EQ(counted(), 1);
  CLOTHLAB_CHECK_LT(two(), 3);
  CLOTHLAB_CHECK(two() == 2);
  EXPECT_EQ(calls, 1);
}

}  // namespace
}  // namespace clothlab
