// LargeArray (solver/model/large_array.hpp): a std::vector whose buffers from 2 MB up start on a
// 2 MB boundary, where the kernel can back them with transparent huge pages.
#include "solver/model/large_array.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <vector>

namespace lmgc::solver {
namespace {

std::uintptr_t address(const void* p) {
  return reinterpret_cast<std::uintptr_t>(p);
}

TEST(LargeArray, BuffersFromTwoMegabytesUpStartOnAHugePageBoundary) {
  LargeArray<double> large(kHugePageBytes / sizeof(double) + 1);
  EXPECT_EQ(address(large.data()) % kHugePageBytes, 0u);
  large.reserve(3 * kHugePageBytes / sizeof(double));  // a larger buffer, on a boundary too
  EXPECT_EQ(address(large.data()) % kHugePageBytes, 0u);
}

TEST(LargeArray, KeepsItsElementsAcrossGrowthLikeAVector) {
  LargeArray<std::int64_t> a;
  for (std::int64_t k = 0; k < 400000; ++k) a.push_back(k);  // grows from bytes to 3.2 MB
  std::int64_t expected = 0;
  for (std::int64_t value : a) EXPECT_EQ(value, expected++);
  EXPECT_EQ(std::accumulate(a.begin(), a.end(), std::int64_t{0}), 399999LL * 400000 / 2);
  LargeArray<std::int64_t> small(3, 7);
  EXPECT_EQ(small[2], 7);
}

TEST(LargeArray, OverAlignedElementsKeepTheirAlignmentInSmallBuffers) {
  struct alignas(64) Line {
    double value = 0.0;
  };
  for (std::size_t count : {1u, 3u, 100u}) {
    LargeArray<Line> lines(count);
    EXPECT_EQ(address(lines.data()) % 64, 0u) << count;
  }
}

// The passes that read an array through an index ask for the element kPrefetchAhead steps on: near the
// end of the index there is none, and the index itself must not be read past its end (the sanitizer
// configuration catches such a read: the index's buffer holds exactly its elements).
TEST(LargeArray, PrefetchGatheredReadsNoIndexPastTheEnd) {
  LargeArray<double> values(64, 1.0);
  for (std::size_t n :
       {std::size_t{0}, std::size_t{1}, kPrefetchAhead, kPrefetchAhead + 1, std::size_t{40}}) {
    std::vector<std::uint32_t> index_of(n);
    std::iota(index_of.begin(), index_of.end(), 0u);
    index_of.shrink_to_fit();
    for (std::size_t i = 0; i < n; ++i) {
      prefetch_gathered<false>(values, index_of, i);
      prefetch_gathered<true>(values, index_of, i);
    }
    EXPECT_EQ(index_of.size(), n);
  }
  EXPECT_EQ(std::accumulate(values.begin(), values.end(), 0.0), 64.0);  // prefetches change nothing
}

}  // namespace
}  // namespace lmgc::solver
