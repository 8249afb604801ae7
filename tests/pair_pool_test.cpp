// The pool the broad phase's pieces share (sim/contact/pair_pool.hpp): lists filled side by side
// give back their own pairs in the order pushed, whichever chunks they took; a full pool says so
// and, grown, holds them all.
#include <gtest/gtest.h>

#include <vector>

#include "sim/contact/pair_pool.hpp"

namespace clothlab {
namespace {

ContactPair numbered(int list, int k) {
  ContactPair p;
  p.v = {list, k, 0, 0};
  p.dist = float(k);
  return p;
}

// Pushes sizes[l] pairs into list l, interleaved one at a time; false when the pool ran out.
bool fill(PairPool& pool, std::vector<PairPool::List>& lists, const std::vector<int>& sizes) {
  pool.clear();
  for (auto& l : lists) l = {};
  for (int k = 0; k < 200; ++k)
    for (std::size_t l = 0; l < lists.size(); ++l)
      if (k < sizes[l] && !pool.push(lists[l], numbered(int(l), k))) return false;
  return true;
}

TEST(PairPool, ListsKeepTheirOwnPairsInOrderAndAFullPoolGrows) {
  PairPool pool;
  const std::vector<int> sizes = {150, 0, 1, 64, 65, 130};  // 410 pairs, 9 chunks of 64
  pool.reserve(100, sizes.size());                          // room for 2 + 6 chunks: too few
  std::vector<PairPool::List> lists(sizes.size());
  EXPECT_FALSE(fill(pool, lists, sizes));
  EXPECT_TRUE(pool.exhausted());
  pool.grow();
  EXPECT_TRUE(fill(pool, lists, sizes));
  EXPECT_FALSE(pool.exhausted());
  for (std::size_t l = 0; l < lists.size(); ++l) {
    std::vector<ContactPair> out = {numbered(99, 0)};  // appended after what is there
    pool.append_to(lists[l], out);
    ASSERT_EQ(out.size(), std::size_t(sizes[l]) + 1);
    for (int k = 0; k < sizes[l]; ++k) {
      EXPECT_EQ(out[std::size_t(k) + 1].v[0], int(l));
      EXPECT_EQ(out[std::size_t(k) + 1].v[1], k);
    }
  }
}

}  // namespace
}  // namespace clothlab
