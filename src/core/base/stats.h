#pragma once
#include <cstddef>
#include <vector>

namespace shadelab {

// Percentile by linear interpolation between closest ranks; p in [0, 100].
// Returns 0 for an empty sample.
double percentile(std::vector<double> samples, double p);
inline double median(const std::vector<double>& samples) {
  return percentile(samples, 50.0);
}
// The arithmetic mean; 0 for an empty sample.
double mean(const std::vector<double>& samples);

// Frames to leave out of steady-state statistics for a run of `frames`: the
// first ones include lavapipe's lazy pipeline compile. A tenth plus one,
// always leaving at least one frame.
size_t warmupFrames(size_t frames);

}  // namespace shadelab
