#pragma once
// Detection's interactions in LMGC90's order (numerics.md §4 step 2: family by family, then by
// candidate), 2D and 3D. Sorted through 24-byte keys: an interaction is 384 (2D) or 624 (3D) bytes,
// and comparing or moving whole records in a sort was an eighth of a 64k-disk step and more than
// the fine detection of a 64k-sphere one. Equal keys keep their detection order.
#include <algorithm>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

namespace lmgc::solver {

// The positions of `list` in the order of their keys; empty when `list` is already in that order.
// `key_of(interaction)` returns the (high, low) halves of its 128-bit sort key.
template <class List, class KeyOf>
std::vector<std::uint32_t> interaction_order(const List& list, KeyOf&& key_of) {
  struct SortKey {
    std::uint64_t high, low;
    std::uint32_t index;
    bool operator<(const SortKey& o) const {
      return std::tie(high, low, index) < std::tie(o.high, o.low, o.index);
    }
  };
  std::vector<SortKey> keys(list.size());
  for (std::size_t k = 0; k < list.size(); ++k) {
    const auto [high, low] = key_of(list[k]);
    keys[k] = {high, low, static_cast<std::uint32_t>(k)};
  }
  std::vector<std::uint32_t> order;
  if (std::is_sorted(keys.begin(), keys.end())) return order;
  std::sort(keys.begin(), keys.end());
  order.reserve(keys.size());
  for (const SortKey& k : keys) order.push_back(k.index);
  return order;
}

// Sorts `list` in place, cycle by cycle, so that it keeps its buffer from step to step (a new one
// each step took fresh pages from the system on large scenes).
template <class List, class KeyOf>
void sort_interactions(List& list, KeyOf&& key_of) {
  std::vector<std::uint32_t> order = interaction_order(list, key_of);
  for (std::size_t start = 0; start < order.size(); ++start) {
    if (order[start] == start) continue;
    typename List::value_type moving = std::move(list[start]);
    std::size_t hole = start;
    while (order[hole] != start) {
      const std::size_t from = order[hole];
      list[hole] = std::move(list[from]);
      order[hole] = static_cast<std::uint32_t>(hole);
      hole = from;
    }
    list[hole] = std::move(moving);
    order[hole] = static_cast<std::uint32_t>(hole);
  }
}

}  // namespace lmgc::solver
