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
// The levels are formed within windows of consecutive updates of the sweep order, run one window
// after the other. Over a whole scene the chains of a packing in detection order run across its
// width, so a level's few updates spread over the whole packing and each level would walk the whole
// body array, beyond L2 on a large scene; within a window the bodies a level touches stay in L2.
#include <algorithm>
#include <cstdint>
#include <vector>

namespace lmgc::solver {

class SweepWavefront {
 public:
  // Updates per window. A list of up to 4096 is one window (every RIGID_2D example: 1024DK_BoxJC
  // has about 2000 contacts), so that a level holds as many independent updates as it can; a longer
  // one is cut every 1024. Windows of 1024 to 4096 sweep a large box equally fast (much larger ones
  // do not), but the set-up, the checks and the end of the step read the sweep arrays in contact
  // order, at each contact's place in its window: a smaller window's levels spread over fewer rows
  // of disks, which keeps those places closer together.
  static constexpr std::size_t single_window_limit = 4096, long_list_window = 1024;
  static std::size_t window_for(std::size_t updates) {
    return updates <= single_window_limit ? single_window_limit : long_list_window;
  }

  // `order`: the sweep order (contact indices). `bodies_of(k)` gives contact k's two body indices,
  // `movable(i)` whether body i can move, `body_count` the number of bodies. `execution` receives
  // the same indices in the order to run them.
  template <typename Index, typename BodiesOf, typename Movable>
  void reorder(const std::vector<Index>& order, BodiesOf&& bodies_of, Movable&& movable,
               std::size_t body_count, std::vector<Index>& execution) {
    reorder(order, bodies_of, movable, body_count, execution, window_for(order.size()));
  }
  // The same with a window of `window` updates (at least 1).
  template <typename Index, typename BodiesOf, typename Movable>
  void reorder(const std::vector<Index>& order, BodiesOf&& bodies_of, Movable&& movable,
               std::size_t body_count, std::vector<Index>& execution, std::size_t window) {
    const std::size_t n = order.size();
    window = std::max<std::size_t>(window, 1);
    body_level_.assign(body_count, 0u);
    level_.resize(n);
    execution.resize(n);
    std::uint32_t base = 0, depth = 0;
    for (std::size_t w0 = 0; w0 < n; w0 += window) {
      const std::size_t w1 = std::min(n, w0 + window);
      std::uint32_t top = base;
      for (std::size_t p = w0; p < w1; ++p) {
        const auto [i, j] = bodies_of(order[p]);
        const bool moves_i = movable(i), moves_j = movable(j);
        // Levels of earlier windows are at most `base`: a window starts again from level 1.
        std::uint32_t level = base;
        if (moves_i) level = std::max(level, body_level_[static_cast<std::size_t>(i)]);
        if (moves_j) level = std::max(level, body_level_[static_cast<std::size_t>(j)]);
        ++level;
        if (moves_i) body_level_[static_cast<std::size_t>(i)] = level;
        if (moves_j) body_level_[static_cast<std::size_t>(j)] = level;
        level_[p] = level - base;
        top = std::max(top, level);
      }
      const std::uint32_t local_depth = top - base;
      depth = std::max(depth, local_depth);
      // Counting sort by level, stable: sweep order within a level.
      start_.assign(static_cast<std::size_t>(local_depth) + 2, 0u);
      for (std::size_t p = w0; p < w1; ++p) ++start_[level_[p] + 1];
      for (std::size_t l = 1; l < start_.size(); ++l) start_[l] += start_[l - 1];
      for (std::size_t p = w0; p < w1; ++p) execution[w0 + start_[level_[p]]++] = order[p];
      base = top;
    }
    depth_ = depth;
  }

  // Levels of the last reorder (the longest chain of updates that share bodies within a window).
  std::uint32_t depth() const { return depth_; }

 private:
  std::vector<std::uint32_t> body_level_, level_, start_;
  std::uint32_t depth_ = 0;
};

}  // namespace lmgc::solver
