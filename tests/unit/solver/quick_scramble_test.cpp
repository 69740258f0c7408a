// LMGC90's quick scramble of the NLGS sweep order (quick_scramble.hpp).
#include "solver/nlgs/quick_scramble.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace lmgc::solver {
namespace {

std::vector<int> identity(int n) {
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  return order;
}

TEST(QuickScramble, SwapsEntryIWithEntryOfTheRandomListInTurn) {
  QuickScramble scramble(7);
  scramble.prepare(10);
  const std::vector<std::size_t>& list = scramble.random_list();
  ASSERT_EQ(list.size(), 10u);
  std::vector<int> expected = identity(10);
  for (std::size_t i = 0; i < list.size(); ++i) {
    ASSERT_LT(list[i], 10u);
    std::swap(expected[i], expected[list[i]]);
  }
  std::vector<int> order = identity(10);
  scramble.scramble(order);
  EXPECT_EQ(order, expected);
}

TEST(QuickScramble, EveryBlockOfASolveGetsAnotherPermutationFromTheSameList) {
  QuickScramble scramble(3);
  scramble.prepare(40);
  std::vector<int> order = identity(40);
  scramble.scramble(order);
  const std::vector<int> first_block = order;
  scramble.scramble(order);
  EXPECT_NE(order, first_block);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, identity(40));  // still a permutation of the contacts
}

TEST(QuickScramble, ASeedRepeatsItsListsAndTheStreamContinuesFromSolveToSolve) {
  QuickScramble a(5), b(5), c(6);
  a.prepare(30);
  b.prepare(30);
  c.prepare(30);
  EXPECT_EQ(a.random_list(), b.random_list());
  EXPECT_NE(a.random_list(), c.random_list());
  const std::vector<std::size_t> first = a.random_list();
  a.prepare(30);
  EXPECT_NE(a.random_list(), first);
}

TEST(QuickScramble, AnOrderOfAnotherSizeThanThePreparedListThrows) {
  QuickScramble scramble;
  scramble.prepare(5);
  std::vector<int> shorter = identity(4), longer = identity(6);
  EXPECT_THROW(scramble.scramble(shorter), std::logic_error);
  EXPECT_THROW(scramble.scramble(longer), std::logic_error);
  EXPECT_EQ(shorter, identity(4));
}

TEST(QuickScramble, NoContactsAndOneContactAreHarmless) {
  QuickScramble scramble;
  scramble.prepare(0);
  std::vector<int> none;
  scramble.scramble(none);
  EXPECT_TRUE(none.empty());
  scramble.prepare(1);
  std::vector<int> one{0};
  scramble.scramble(one);
  EXPECT_EQ(one, std::vector<int>{0});
}

}  // namespace
}  // namespace lmgc::solver
