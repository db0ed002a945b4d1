#pragma once
// Sorting 64-bit keys in linear time, for the per-frame orders of many
// copies (the billboard pass sorts 10,000 depth keys a frame, where
// std::sort took ~0.5 ms of the host's frame on this machine).
#include <cstdint>
#include <vector>

namespace shadelab {

// Sorts `keys` ascending, the same result as std::sort: a least significant
// byte first radix sort, one pass per byte in which the keys differ.
// `scratch` is working space, kept by the caller so that a frame allocates
// nothing; its contents afterwards are unspecified.
void radixSort(std::vector<uint64_t>& keys, std::vector<uint64_t>& scratch);

}  // namespace shadelab
