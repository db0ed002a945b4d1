#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/base/radix_sort.h"

namespace shadelab {
namespace {

// The billboard pass's keys: a depth's ordered bits above, the copy's index
// below, indices ascending in input order.
TEST(RadixSort, SortsLikeStdSort) {
  std::mt19937_64 random(7);
  for (size_t count : {0u, 1u, 2u, 3u, 255u, 256u, 257u, 10000u}) {
    std::vector<uint64_t> keys(count), scratch;
    for (size_t i = 0; i < count; ++i) keys[i] = (random() & 0xffffffff00000000ull) | i;
    std::vector<uint64_t> expected = keys;
    std::sort(expected.begin(), expected.end());
    radixSort(keys, scratch);
    EXPECT_EQ(keys, expected) << count << " keys";
  }
}

TEST(RadixSort, KeysThatShareBytesAndRepeat) {
  std::mt19937_64 random(11);
  std::vector<uint64_t> keys(5000), scratch(3, 42u);
  // Only bytes 2 and 7 vary, with repeats; the others are shared (skipped passes).
  for (uint64_t& key : keys)
    key = 0x0011223344556677ull ^ ((random() % 7) << 16) ^ ((random() % 3) << 56);
  std::vector<uint64_t> expected = keys;
  std::sort(expected.begin(), expected.end());
  radixSort(keys, scratch);
  EXPECT_EQ(keys, expected);
  std::vector<uint64_t> same(100, 0x8000000000000001ull);
  radixSort(same, scratch);
  EXPECT_EQ(same, std::vector<uint64_t>(100, 0x8000000000000001ull));
  std::vector<uint64_t> descending = {~0ull, 1ull << 63, 1ull << 32, 1ull, 0ull};
  radixSort(descending, scratch);
  EXPECT_EQ(descending, (std::vector<uint64_t>{0ull, 1ull, 1ull << 32, 1ull << 63, ~0ull}));
}

}  // namespace
}  // namespace shadelab
