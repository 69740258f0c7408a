#pragma once
// Detection's interactions in LMGC90's order (numerics.md §4 step 2: family by family, then by
// candidate), 2D and 3D. Sorted through 24-byte keys: an interaction is 256 (2D) or 504 (3D) bytes,
// and a sort that compares or moves whole records streams them from memory over and over. Equal
// keys keep their detection order.
#include <algorithm>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

namespace lmgc::solver {

// A sort key: (high, low) halves of the 128-bit key, then the detection position, so that every
// key is distinct and any sort gives the one order where equal keys keep their detection order.
struct InteractionSortKey {
  std::uint64_t high, low;
  std::uint32_t index;
  bool operator<(const InteractionSortKey& o) const {
    return std::tie(high, low, index) < std::tie(o.high, o.low, o.index);
  }
};

// Sorts keys that come nearly in order, as detection gives them: the grid reports each candidate's
// pairs together and candidates in increasing order, but the families (the top of `high`) of a
// candidate's pairs interleave, and its antagonists come in cell order. So: a counting pass by family,
// then an insertion sort of each family, which is linear for such a list; a family that needs more
// than kMovesPerKey moves per key falls back to std::sort, as does a list with larger family values.
inline void sort_nearly_ordered(std::vector<InteractionSortKey>& keys) {
  constexpr std::uint64_t kFamilies = 64;
  constexpr std::size_t kMovesPerKey = 16;
  std::vector<std::size_t> start(kFamilies + 1, 0);
  for (const InteractionSortKey& k : keys) {
    const std::uint64_t family = k.high >> 32;
    if (family >= kFamilies) {
      std::sort(keys.begin(), keys.end());
      return;
    }
    ++start[family + 1];
  }
  for (std::size_t f = 0; f < kFamilies; ++f) start[f + 1] += start[f];
  std::vector<InteractionSortKey> by_family(keys.size());
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (const InteractionSortKey& k : keys) by_family[next[k.high >> 32]++] = k;
  for (std::size_t f = 0; f < kFamilies; ++f) {
    const auto first = by_family.begin() + static_cast<std::ptrdiff_t>(start[f]);
    const auto last = by_family.begin() + static_cast<std::ptrdiff_t>(start[f + 1]);
    std::size_t budget = kMovesPerKey * static_cast<std::size_t>(last - first);
    bool sorted = true;
    for (auto it = first; it != last && sorted; ++it) {
      const InteractionSortKey moving = *it;
      auto hole = it;
      for (; hole != first && moving < *(hole - 1); --hole) {
        *hole = *(hole - 1);
        if (budget-- == 0) {
          sorted = false;
          break;
        }
      }
      *hole = moving;
    }
    if (!sorted) std::sort(first, last);  // every key is still there, in some order
  }
  keys.swap(by_family);
}

// The positions of `list` in the order of their keys; empty when `list` is already in that order.
// `key_of(interaction)` returns the (high, low) halves of its 128-bit sort key.
template <class List, class KeyOf>
std::vector<std::uint32_t> interaction_order(const List& list, KeyOf&& key_of) {
  std::vector<InteractionSortKey> keys(list.size());
  for (std::size_t k = 0; k < list.size(); ++k) {
    const auto [high, low] = key_of(list[k]);
    keys[k] = {high, low, static_cast<std::uint32_t>(k)};
  }
  std::vector<std::uint32_t> order;
  if (std::is_sorted(keys.begin(), keys.end())) return order;
  sort_nearly_ordered(keys);
  order.reserve(keys.size());
  for (const InteractionSortKey& k : keys) order.push_back(k.index);
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
