#pragma once
// The spatial grid of lmgc: uniform grids, one per power-of-two level of bounding radius, so that
// a few large contactors among many small ones (walls, hoppers, big disks) do not make every cell
// large. Used by the solver's rough detection and by lmgc-check's initial-overlap check, so that
// both find the same candidate pairs; linear in the number of items. Points are 3D (2D scenes
// pass z = 0).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <compare>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace lmgc::spatial {

// The cell index of coordinate x, clamped so that absurd coordinates cannot overflow. Floor by
// truncation: std::floor is a library call on the baseline x86-64 target, and this runs in the
// candidate-pair loop.
inline std::int64_t grid_index(double x, double cell) {
  constexpr double kLimit = 1099511627776.0;  // 2^40
  const double q = x / cell;
  if (!(q == q)) return 0;
  const double clamped = std::max(-kLimit, std::min(kLimit, q));
  const auto truncated = static_cast<std::int64_t>(clamped);
  return static_cast<double>(truncated) > clamped ? truncated - 1 : truncated;
}

class MultilevelGrid {
 public:
  // Items with a finite centre and a finite radius >= 0 are placed (`placed[i]` false skips one);
  // radius r goes to level floor(log2(r / smallest positive radius)) (level 0 for points).
  // Cells are twice the largest radius of their level, and at least `min_cell`.
  void build(std::span<const Eigen::Vector3d> centres, std::span<const double> radii,
             std::span<const std::uint8_t> placed, double min_cell) {
    // The levels keep their storage from the last build: a grid kept from step to step allocates
    // nothing once it has seen its largest scene.
    for (Level& l : levels_) {
      l.entries.clear();
      l.largest_radius = 0.0;
    }
    std::size_t level_count = 0;
    level_of_.assign(centres.size(), -1);
    double smallest = 0.0;
    for (std::size_t i = 0; i < centres.size(); ++i)
      if (usable(centres, radii, placed, i) && radii[i] > 0.0)
        smallest = smallest == 0.0 ? radii[i] : std::min(smallest, radii[i]);
    for (std::size_t i = 0; i < centres.size(); ++i) {
      if (!usable(centres, radii, placed, i)) continue;
      const int level = smallest > 0.0 && radii[i] > smallest
                            ? static_cast<int>(std::min(60.0, std::floor(std::log2(radii[i] / smallest))))
                            : 0;
      level_of_[i] = level;
      if (static_cast<int>(levels_.size()) <= level) levels_.resize(static_cast<std::size_t>(level) + 1);
      level_count = std::max(level_count, static_cast<std::size_t>(level) + 1);
      Level& l = levels_[static_cast<std::size_t>(level)];
      l.largest_radius = std::max(l.largest_radius, radii[i]);
    }
    levels_.resize(level_count);
    for (Level& l : levels_) l.cell = std::max({2.0 * l.largest_radius, min_cell, 1e-300});
    for (std::size_t i = 0; i < centres.size(); ++i)
      if (level_of_[i] >= 0) {
        Level& l = levels_[static_cast<std::size_t>(level_of_[i])];
        l.entries.push_back({l.cell_of(centres[i]), i});
      }
    for (Level& l : levels_) l.sort_entries();
    // Levels are powers of two of the radius: a scene with a few long walls has many empty ones
    // between its grains' and its walls', so each item looks only into the occupied ones above
    // its own.
    occupied_.clear();
    for (std::size_t l = 0; l < levels_.size(); ++l)
      if (!levels_[l].entries.empty()) occupied_.push_back(l);
    occupied_from_.resize(levels_.size() + 1);
    for (std::size_t l = 0, k = 0; l <= levels_.size(); ++l) {
      while (k < occupied_.size() && occupied_[k] < l) ++k;
      occupied_from_[l] = k;
    }
  }

  int level_of(std::size_t i) const { return level_of_[i]; }
  std::size_t level_count() const { return levels_.size(); }
  bool has_dense_table(std::size_t level) const { return !levels_[level].first_entry.empty(); }
  bool dense_table_is_y_major(std::size_t level) const {
    return has_dense_table(level) && levels_[level].y_major;
  }

  // Calls f(j) for every item j of `level` whose cell meets the box [lo, hi] grown by the level's
  // largest radius (a superset of the items whose sphere meets the box). Walks the whole level
  // instead when the box covers more cells than the level has items.
  template <class F>
  void for_each_near(std::size_t level, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, F&& f) const {
    const Level& l = levels_[level];
    const Eigen::Vector3d grow = Eigen::Vector3d::Constant(l.largest_radius);
    const Cell a = l.cell_of(lo - grow), b = l.cell_of(hi + grow);
    const double span = double(b.x - a.x + 1) * double(b.y - a.y + 1) * double(b.z - a.z + 1);
    if (span > double(l.entries.size())) {
      for (const Entry& e : l.entries)
        if (e.cell.x >= a.x && e.cell.x <= b.x && e.cell.y >= a.y && e.cell.y <= b.y && e.cell.z >= a.z &&
            e.cell.z <= b.z)
          f(e.item);
      return;
    }
    if (!l.first_entry.empty()) {
      // Dense table: the entries of cells (x, y, a.z … b.z) are one run, found in O(1); with every
      // z of the level (a 2D scene), so are those of a whole row of the box along the table's
      // faster axis of x and y.
      const std::int64_t x0 = std::max(a.x, l.low.x), x1 = std::min(b.x, l.high.x);
      const std::int64_t y0 = std::max(a.y, l.low.y), y1 = std::min(b.y, l.high.y);
      const std::int64_t z0 = std::max(a.z, l.low.z), z1 = std::min(b.z, l.high.z);
      if (z0 > z1 || x0 > x1 || y0 > y1) return;
      const bool whole_z = z0 == l.low.z && z1 == l.high.z;
      const auto visit = [&](const Cell& from, const Cell& to) {
        const std::size_t first = l.first_entry[l.dense_index(from)];
        const std::size_t last = l.first_entry[l.dense_index(to) + 1];
        for (std::size_t k = first; k < last; ++k) f(l.entries[k].item);
      };
      if (l.y_major) {
        for (std::int64_t y = y0; y <= y1; ++y) {
          if (whole_z) {
            visit({x0, y, z0}, {x1, y, z1});
            continue;
          }
          for (std::int64_t x = x0; x <= x1; ++x) visit({x, y, z0}, {x, y, z1});
        }
      } else {
        for (std::int64_t x = x0; x <= x1; ++x) {
          if (whole_z) {
            visit({x, y0, z0}, {x, y1, z1});
            continue;
          }
          for (std::int64_t y = y0; y <= y1; ++y) visit({x, y, z0}, {x, y, z1});
        }
      }
      return;
    }
    // Entries are sorted by (x, y, z): one binary search per (x, y) column of the box.
    for (std::int64_t x = a.x; x <= b.x; ++x)
      for (std::int64_t y = a.y; y <= b.y; ++y) {
        auto it = std::lower_bound(l.entries.begin(), l.entries.end(), Cell{x, y, a.z},
                                   [](const Entry& e, const Cell& c) { return e.cell < c; });
        for (; it != l.entries.end() && it->cell.x == x && it->cell.y == y && it->cell.z <= b.z; ++it)
          f(it->item);
      }
  }

  // Calls f(i, j) once for every pair of placed items whose spheres, grown by `margin`, may meet:
  // each item against its own level (j > i) and the larger levels.
  template <class F>
  void for_each_candidate_pair(std::span<const Eigen::Vector3d> centres, std::span<const double> radii,
                               double margin, F&& f) const {
    for (std::size_t i = 0; i < level_of_.size(); ++i) {
      const int li = level_of_[i];
      if (li < 0) continue;
      const Eigen::Vector3d reach = Eigen::Vector3d::Constant(radii[i] + margin);
      // The occupied levels from li up (an empty one has nothing near).
      for (std::size_t k = occupied_from_[static_cast<std::size_t>(li)]; k < occupied_.size(); ++k)
        for_each_near(occupied_[k], centres[i] - reach, centres[i] + reach, [&](std::size_t j) {
          if (level_of_[j] > li || j > i) f(i, j);
        });
    }
  }

 private:
  struct Cell {
    std::int64_t x, y, z;
    friend auto operator<=>(const Cell&, const Cell&) = default;
  };
  // A cell list sorted by cell then item: deterministic, and no allocation per cell.
  struct Entry {
    Cell cell;
    std::size_t item;
  };
  struct Level {
    double largest_radius = 0.0;
    double cell = 0.0;
    std::vector<Entry> entries;
    // When the occupied cells' bounding box is small against the entries (a packing, not a few
    // items far apart), first_entry[k] is the first entry of dense cell k (x-major, then y, z; or
    // y-major, then x, z): a lookup is one read instead of a binary search, at every query of the
    // candidate-pair loop.
    Cell low{}, high{};
    std::int64_t nx = 0, ny = 0, nz = 0;
    // The table's order follows the items': y-major when, in a plane, the cell's x changes from
    // item to item more often than its y (bodies numbered row by row), so that the table is filled
    // in sequence and the queries of items in order walk it in sequence. In the x-major order, a
    // layer numbered row by row would scatter its entries over the table and walk the whole table
    // once per row.
    bool y_major = false;
    std::vector<std::uint32_t> first_entry;
    std::vector<Entry> sorted;  // sort_entries' scratch, kept with the level
    std::vector<std::uint32_t> next;

    Cell cell_of(const Eigen::Vector3d& p) const {
      return {grid_index(p.x(), cell), grid_index(p.y(), cell), grid_index(p.z(), cell)};
    }
    std::size_t dense_index(const Cell& c) const {
      const std::int64_t plane =
          y_major ? (c.y - low.y) * nx + (c.x - low.x) : (c.x - low.x) * ny + (c.y - low.y);
      return static_cast<std::size_t>(plane * nz + (c.z - low.z));
    }

    // Entries in (cell, item) order; a counting sort over the dense table when there is one.
    void sort_entries() {
      first_entry.clear();
      y_major = false;  // set below with the dense table, which alone reads it
      if (entries.empty()) return;
      low = high = entries.front().cell;
      std::size_t x_changes = 0, y_changes = 0;
      const Cell* previous = &entries.front().cell;
      for (const Entry& e : entries) {
        low = {std::min(low.x, e.cell.x), std::min(low.y, e.cell.y), std::min(low.z, e.cell.z)};
        high = {std::max(high.x, e.cell.x), std::max(high.y, e.cell.y), std::max(high.z, e.cell.z)};
        x_changes += e.cell.x != previous->x;
        y_changes += e.cell.y != previous->y;
        previous = &e.cell;
      }
      const double cells =
          double(high.x - low.x + 1) * double(high.y - low.y + 1) * double(high.z - low.z + 1);
      const double limit = 8.0 * double(entries.size()) + 1024.0;
      if (cells > limit || entries.size() >= std::numeric_limits<std::uint32_t>::max()) {
        std::sort(entries.begin(), entries.end(), [](const Entry& p, const Entry& q) {
          return p.cell < q.cell || (p.cell == q.cell && p.item < q.item);
        });
        return;
      }
      nx = high.x - low.x + 1;
      ny = high.y - low.y + 1;
      nz = high.z - low.z + 1;
      // Only in a plane (2D scenes, whose detection sorts its pairs whatever the order the grid
      // gives them in); a 3D step keeps the order of a pair's periodic images as the grid gives them.
      y_major = nz == 1 && x_changes > y_changes;
      // Entries were appended in item order, so the counting sort keeps items ascending per cell.
      first_entry.assign(static_cast<std::size_t>(cells) + 1, 0u);
      for (const Entry& e : entries) ++first_entry[dense_index(e.cell) + 1];
      for (std::size_t k = 1; k < first_entry.size(); ++k) first_entry[k] += first_entry[k - 1];
      sorted.resize(entries.size());
      next.assign(first_entry.begin(), first_entry.end() - 1);
      for (const Entry& e : entries) sorted[next[dense_index(e.cell)]++] = e;
      entries.swap(sorted);
    }
  };

  static bool usable(std::span<const Eigen::Vector3d> centres, std::span<const double> radii,
                     std::span<const std::uint8_t> placed, std::size_t i) {
    return (placed.empty() || placed[i]) && centres[i].allFinite() && std::isfinite(radii[i]) &&
           radii[i] >= 0.0;
  }

  std::vector<Level> levels_;
  std::vector<int> level_of_;
  std::vector<std::size_t> occupied_;       // the levels with entries, increasing
  std::vector<std::size_t> occupied_from_;  // [l]: the index in occupied_ of the first one >= l
};

}  // namespace lmgc::spatial
