#pragma once
#include <vector>

namespace shadelab {

// Percentile by linear interpolation between closest ranks; p in [0, 100].
// Returns 0 for an empty sample.
double percentile(std::vector<double> samples, double p);
inline double median(const std::vector<double>& samples) { return percentile(samples, 50.0); }

}  // namespace shadelab
