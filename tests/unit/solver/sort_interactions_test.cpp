// Detection's sort (solver/detection/sort_interactions.hpp): records end in key order, equal keys in
// their detection order, whether permuted in place or gathered through interaction_order.
#include "solver/detection/sort_interactions.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace lmgc::solver {
namespace {

struct Record {
  std::uint64_t high = 0, low = 0;
  int detected = 0;  // position at detection
};

std::pair<std::uint64_t, std::uint64_t> key_of(const Record& r) {
  return {r.high, r.low};
}

std::vector<Record> detected() {
  // Two records share the key (1, 5): they must keep their order (positions 1 and 4).
  return {{2, 0, 0}, {1, 5, 1}, {1, 2, 2}, {0, 9, 3}, {1, 5, 4}, {2, 0, 5}};
}

TEST(SortInteractions, InPlaceSortOrdersByKeyAndKeepsEqualKeysInDetectionOrder) {
  std::vector<Record> list = detected();
  sort_interactions(list, key_of);
  std::vector<int> order;
  for (const Record& r : list) order.push_back(r.detected);
  EXPECT_EQ(order, (std::vector<int>{3, 2, 1, 4, 0, 5}));
}

TEST(SortInteractions, OrderIsEmptyForASortedListAndOtherwiseThePositionsByKey) {
  std::vector<Record> list = detected();
  EXPECT_EQ(interaction_order(list, key_of), (std::vector<std::uint32_t>{3, 2, 1, 4, 0, 5}));
  sort_interactions(list, key_of);
  EXPECT_TRUE(interaction_order(list, key_of).empty());
}

// Detection's shape of list (candidates increasing, families interleaved, antagonists in any order
// within a candidate, repeated keys), a list far from it (reversed) and family values beyond the
// counting pass's range: the nearly-ordered sort gives std::sort's order in every case.
TEST(SortInteractions, NearlyOrderedSortGivesTheSameOrderAsAFullSort) {
  std::uint32_t seed = 12345;
  const auto next = [&](std::uint32_t range) {
    seed = seed * 1664525u + 1013904223u;
    return (seed >> 8) % range;
  };
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<InteractionSortKey> keys;
    const std::uint64_t families = trial % 10 == 9 ? 200 : 3;
    for (std::uint64_t candidate = 0; candidate < 300; ++candidate)
      for (std::uint32_t k = next(8); k > 0; --k) {
        const std::uint64_t family = next(static_cast<std::uint32_t>(families));
        keys.push_back({(family << 32) | candidate, std::uint64_t(next(40)) << 32, 0});
      }
    if (trial % 10 == 5) std::reverse(keys.begin(), keys.end());
    for (std::size_t k = 0; k < keys.size(); ++k) keys[k].index = static_cast<std::uint32_t>(k);
    std::vector<InteractionSortKey> expected = keys;
    std::sort(expected.begin(), expected.end());
    sort_nearly_ordered(keys);
    ASSERT_EQ(keys.size(), expected.size());
    for (std::size_t k = 0; k < keys.size(); ++k) ASSERT_EQ(keys[k].index, expected[k].index) << trial;
  }
}

}  // namespace
}  // namespace lmgc::solver
