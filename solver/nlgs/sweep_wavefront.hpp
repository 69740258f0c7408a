#pragma once
// The order in which a Gauss–Seidel sweep executes its contact updates, with the sweep's result
// unchanged bit for bit. An update reads and writes the velocities of its two bodies and nothing
// else, so two updates that share no movable body commute exactly; only the relative order of
// updates that share one matters. Each update gets the level 1 + the highest level of the earlier
// updates on its bodies, and the updates run level by level, in sweep order within a level: every
// pair that shares a body keeps its order, and consecutive updates of one level are independent,
// so the processor overlaps them instead of waiting for each one's velocities (in detection order
// a candidate's contacts follow one another, each on the velocities the previous one wrote).
// A body that no update moves (every inverse mass 0: walls, driven bodies) orders nothing.
#include <algorithm>
#include <cstdint>
#include <vector>

namespace lmgc::solver {

class SweepWavefront {
 public:
  // `order`: the sweep order (contact indices). `bodies_of(k)` gives contact k's two body indices,
  // `movable(i)` whether body i can move, `body_count` the number of bodies. `execution` receives
  // the same indices in the order to run them.
  template <typename Index, typename BodiesOf, typename Movable>
  void reorder(const std::vector<Index>& order, BodiesOf&& bodies_of, Movable&& movable,
               std::size_t body_count, std::vector<Index>& execution) {
    const std::size_t n = order.size();
    body_level_.assign(body_count, 0u);
    level_.resize(n);
    std::uint32_t depth = 0;
    for (std::size_t p = 0; p < n; ++p) {
      const auto [i, j] = bodies_of(order[p]);
      const bool moves_i = movable(i), moves_j = movable(j);
      std::uint32_t level = 0;
      if (moves_i) level = body_level_[static_cast<std::size_t>(i)];
      if (moves_j) level = std::max(level, body_level_[static_cast<std::size_t>(j)]);
      ++level;
      if (moves_i) body_level_[static_cast<std::size_t>(i)] = level;
      if (moves_j) body_level_[static_cast<std::size_t>(j)] = level;
      level_[p] = level;
      depth = std::max(depth, level);
    }
    // Counting sort by level, stable: sweep order within a level.
    start_.assign(static_cast<std::size_t>(depth) + 2, 0u);
    for (std::size_t p = 0; p < n; ++p) ++start_[level_[p] + 1];
    for (std::size_t l = 1; l < start_.size(); ++l) start_[l] += start_[l - 1];
    execution.resize(n);
    for (std::size_t p = 0; p < n; ++p) execution[start_[level_[p]]++] = order[p];
    depth_ = depth;
  }

  // Levels of the last reorder (the longest chain of updates that share bodies).
  std::uint32_t depth() const { return depth_; }

 private:
  std::vector<std::uint32_t> body_level_, level_, start_;
  std::uint32_t depth_ = 0;
};

}  // namespace lmgc::solver
