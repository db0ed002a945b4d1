#include "core/base/radix_sort.h"

#include <array>
#include <cstddef>
#include <utility>

namespace shadelab {

void radixSort(std::vector<uint64_t>& keys, std::vector<uint64_t>& scratch) {
  size_t count = keys.size();
  if (count < 2) return;
  // Every byte's histogram in one read of the keys.
  std::array<std::array<size_t, 256>, 8> histograms{};
  for (uint64_t key : keys)
    for (int byte = 0; byte < 8; ++byte) ++histograms[byte][(key >> (8 * byte)) & 0xffu];
  scratch.resize(count);
  std::vector<uint64_t>* from = &keys;
  std::vector<uint64_t>* to = &scratch;
  for (int byte = 0; byte < 8; ++byte) {
    std::array<size_t, 256>& histogram = histograms[byte];
    // A byte every key shares leaves the order as it is.
    if (histogram[((*from)[0] >> (8 * byte)) & 0xffu] == count) continue;
    size_t offset = 0;
    for (size_t& bucket : histogram) offset += std::exchange(bucket, offset);
    // Stable: keys with the same byte keep the previous passes' order.
    for (uint64_t key : *from) (*to)[histogram[(key >> (8 * byte)) & 0xffu]++] = key;
    std::swap(from, to);
  }
  if (from != &keys) keys.swap(scratch);
}

}  // namespace shadelab
