#include "core/base/stats.h"

#include <algorithm>
#include <cmath>

namespace shadelab {

double percentile(std::vector<double> samples, double p) {
  if (samples.empty()) return 0.0;
  std::sort(samples.begin(), samples.end());
  double rank = std::clamp(p, 0.0, 100.0) / 100.0 * double(samples.size() - 1);
  size_t below = size_t(std::floor(rank));
  size_t above = std::min(below + 1, samples.size() - 1);
  double t = rank - double(below);
  return samples[below] * (1.0 - t) + samples[above] * t;
}

double mean(const std::vector<double>& samples) {
  if (samples.empty()) return 0.0;
  double sum = 0.0;
  for (double sample : samples) sum += sample;
  return sum / double(samples.size());
}

size_t warmupFrames(size_t frames) {
  if (frames == 0) return 0;
  return std::min(frames / 10 + 1, frames - 1);
}

}  // namespace shadelab
