#pragma once
// Flat arrays that a large scene's step streams through (interactions, detection's points, the
// stored verlet list, the 2D sweep arrays): from 2 MB up, each is allocated on 2 MB boundaries and the
// kernel is asked to back it with transparent huge pages (madvise, the mode Debian's kernels default
// to). With 4 KB pages, every pass over a large list of interactions and every body lookup of a
// sweep walks the page tables. The advice is only a hint: where the kernel has no huge page to
// give, or THP is off, the pages are ordinary.
#include <sys/mman.h>

#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

namespace lmgc::solver {

inline constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;

template <class T>
struct HugePageAllocator {
  using value_type = T;

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > std::size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    void* p = nullptr;
    if (bytes < kHugePageBytes) {
      // Over-aligned records (Interaction2D keeps to whole cache lines) take their own alignment.
      constexpr std::size_t align = alignof(T);
      p = align > alignof(std::max_align_t) ? std::aligned_alloc(align, (bytes + align - 1) / align * align)
                                            : std::malloc(bytes);
    } else {
      const std::size_t whole_pages = (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
      p = std::aligned_alloc(kHugePageBytes, whole_pages);
      if (p) madvise(p, whole_pages, MADV_HUGEPAGE);  // a refusal leaves ordinary pages
    }
    if (!p) throw std::bad_alloc();
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t) noexcept { std::free(p); }

  template <class U>
  bool operator==(const HugePageAllocator<U>&) const noexcept {
    return true;
  }
};

template <class T>
using LargeArray = std::vector<T, HugePageAllocator<T>>;

// A pass that goes through a large array in order asks for the element kPrefetchAhead places on (for
// writing when `write`), nothing past the end: on a large scene the passes over the interactions
// would otherwise wait on each record from memory.
inline constexpr std::size_t kPrefetchAhead = 16;
template <bool write, class T>
[[gnu::always_inline]] inline void prefetch_ahead(const LargeArray<T>& array, std::size_t index) {
  if (index + kPrefetchAhead < array.size()) __builtin_prefetch(array.data() + index + kPrefetchAhead, write);
}

// The same for a pass that reads `array` through an index (`index_of[i]` for the i-th element of the
// pass): the element kPrefetchAhead steps on, both ends of it.
template <bool write, class T, class Index>
[[gnu::always_inline]] inline void prefetch_gathered(const LargeArray<T>& array,
                                                     const std::vector<Index>& index_of, std::size_t i) {
  if (i + kPrefetchAhead >= index_of.size()) return;
  const char* element = reinterpret_cast<const char*>(array.data() + index_of[i + kPrefetchAhead]);
  __builtin_prefetch(element, write);
  __builtin_prefetch(element + sizeof(T) - 1, write);
}

}  // namespace lmgc::solver
