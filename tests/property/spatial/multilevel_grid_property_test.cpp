// The shared spatial grid finds every pair of items whose spheres, grown by the margin, overlap
// (compared with the all-pairs search) and gives each candidate pair exactly once, whether its
// levels use the dense cell table (x-major or y-major) or the sorted cell list.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "spatial/multilevel_grid.hpp"

namespace lmgc::spatial {
namespace {

struct Items {
  std::vector<Eigen::Vector3d> centres;
  std::vector<double> radii;
};

// A flat lattice of touching items, numbered row by row or column by column: the dense table's
// y-major and x-major orders.
Items lattice_items() {
  const int columns = *rc::gen::inRange(1, 16), rows = *rc::gen::inRange(1, 16);
  const bool row_by_row = *rc::gen::arbitrary<bool>();
  const double spacing = *rc::gen::element(0.5, 1.0), radius = 0.5 * spacing;
  Items items;
  for (int a = 0; a < (row_by_row ? rows : columns); ++a)
    for (int b = 0; b < (row_by_row ? columns : rows); ++b) {
      const int column = row_by_row ? b : a, row = row_by_row ? a : b;
      items.centres.emplace_back(spacing * column, spacing * row, 0.0);
      items.radii.push_back(radius * *rc::gen::element(1.0, 0.9, 1.1));
    }
  return items;
}

Items random_items() {
  if (*rc::gen::inRange(0, 4) == 0) return lattice_items();
  const int count = *rc::gen::inRange(0, 120);
  const bool flat = *rc::gen::arbitrary<bool>();  // 2D scenes pass z = 0
  // Packed items take the grid's dense cell table, spread ones its sorted cell list.
  const double spread = *rc::gen::element(0.2, 1.0, 100.0);
  Items items;
  for (int i = 0; i < count; ++i) {
    auto coordinate = [&] { return spread * *rc::gen::inRange(-1000, 1000) / 100.0; };
    items.centres.emplace_back(coordinate(), coordinate(), flat ? 0.0 : coordinate());
    // Mostly small items, a few very large ones (walls), some points.
    const int kind = *rc::gen::inRange(0, 10);
    items.radii.push_back(kind == 0   ? 0.0
                          : kind == 1 ? *rc::gen::inRange(100, 800) / 100.0
                                      : *rc::gen::inRange(1, 60) / 100.0);
  }
  return items;
}

std::vector<std::pair<std::size_t, std::size_t>> candidate_pairs(const MultilevelGrid& grid,
                                                                 const Items& items, double margin) {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  grid.for_each_candidate_pair(items.centres, items.radii, margin,
                               [&](std::size_t i, std::size_t j) { pairs.emplace_back(i, j); });
  return pairs;
}

RC_GTEST_PROP(MultilevelGrid, FindsEveryOverlappingPairExactlyOnce, ()) {
  const Items items = random_items();
  const std::vector<Eigen::Vector3d>& centres = items.centres;
  const std::vector<double>& radii = items.radii;
  const double margin = *rc::gen::inRange(0, 30) / 100.0;
  MultilevelGrid grid;
  grid.build(centres, radii, {}, margin);
  RC_CLASSIFY(grid.level_count() > 0 && grid.dense_table_is_y_major(0), "y-major dense table");
  std::set<std::pair<std::size_t, std::size_t>> found;
  std::size_t calls = 0;
  grid.for_each_candidate_pair(centres, radii, margin, [&](std::size_t i, std::size_t j) {
    ++calls;
    found.insert({std::min(i, j), std::max(i, j)});
    RC_ASSERT(i != j);
  });
  RC_ASSERT(calls == found.size());  // no pair twice
  for (std::size_t i = 0; i < centres.size(); ++i)
    for (std::size_t j = i + 1; j < centres.size(); ++j) {
      const double reach = radii[i] + radii[j] + margin;
      if ((centres[i] - centres[j]).norm() <= reach) RC_ASSERT(found.count({i, j}) == 1u);
    }
}

// Detection keeps its grid from step to step, and a build reuses the levels' storage: what a build
// gives must not depend on the builds before it.
RC_GTEST_PROP(MultilevelGrid, ARebuiltGridGivesTheSamePairsInTheSameOrderAsAFreshOne, ()) {
  const Items before = random_items(), after = random_items();
  const double margin = *rc::gen::inRange(0, 30) / 100.0;
  MultilevelGrid reused, fresh;
  reused.build(before.centres, before.radii, {}, margin);
  reused.build(after.centres, after.radii, {}, margin);
  fresh.build(after.centres, after.radii, {}, margin);
  RC_ASSERT(reused.level_count() == fresh.level_count());
  RC_ASSERT(candidate_pairs(reused, after, margin) == candidate_pairs(fresh, after, margin));
}

RC_GTEST_PROP(MultilevelGrid, CellIndexIsTheFloorOfTheQuotientWithinTheClamp, ()) {
  // Integers and their neighbours (exact multiples of the cell are the edge cases), and arbitrary values.
  const double whole = *rc::gen::inRange(-100000, 100000);
  const double x = *rc::gen::element(whole, std::nextafter(whole, -1e9), std::nextafter(whole, 1e9),
                                     whole / 7.0, *rc::gen::arbitrary<double>());
  const double cell = *rc::gen::element(1.0, 0.25, 3e-3, 1e5);
  const double q = std::floor(x / cell);
  const std::int64_t index = grid_index(x, cell);
  if (std::isnan(q)) {
    RC_ASSERT(index == 0);
  } else if (std::fabs(q) <= 1099511627776.0) {
    RC_ASSERT(static_cast<double>(index) == q);
  } else {
    RC_ASSERT(std::llabs(index) == 1099511627776LL);  // clamped at 2^40
  }
}

TEST(MultilevelGrid, AFlatLatticeNumberedRowByRowGetsAYMajorTableAndColumnByColumnAnXMajorOne) {
  std::vector<Eigen::Vector3d> by_rows, by_columns, stacked;
  for (int a = 0; a < 20; ++a)
    for (int b = 0; b < 5; ++b) {
      by_rows.emplace_back(b, a, 0.0);
      by_columns.emplace_back(a, b, 0.0);
      stacked.emplace_back(b, 0.0, a);  // 3D: the table stays x-major
    }
  const std::vector<double> radii(100, 0.5);
  MultilevelGrid grid;
  grid.build(by_rows, radii, {}, 0.0);
  EXPECT_TRUE(grid.dense_table_is_y_major(0));
  grid.build(by_columns, radii, {}, 0.0);
  ASSERT_TRUE(grid.has_dense_table(0));
  EXPECT_FALSE(grid.dense_table_is_y_major(0));
  grid.build(stacked, radii, {}, 0.0);
  ASSERT_TRUE(grid.has_dense_table(0));
  EXPECT_FALSE(grid.dense_table_is_y_major(0));
}

TEST(MultilevelGrid, PackedItemsGetTheDenseCellTableAndFarApartOnesTheSortedList) {
  std::vector<Eigen::Vector3d> packed, spread;
  for (int i = 0; i < 100; ++i) {
    packed.emplace_back(i % 10, i / 10, 0.0);
    spread.emplace_back(1e4 * (i % 10), 1e4 * (i / 10), 1e4 * i);
  }
  const std::vector<double> radii(100, 0.5);
  MultilevelGrid grid;
  grid.build(packed, radii, {}, 0.0);
  EXPECT_TRUE(grid.has_dense_table(0));
  grid.build(spread, radii, {}, 0.0);
  EXPECT_FALSE(grid.has_dense_table(0));
}

}  // namespace
}  // namespace lmgc::spatial
