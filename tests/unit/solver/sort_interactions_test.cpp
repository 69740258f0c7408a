// Detection's sort (solver/detection/sort_interactions.hpp): records end in key order, equal keys in
// their detection order, whether permuted in place or gathered through interaction_order.
#include "solver/detection/sort_interactions.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace lmgc::solver
