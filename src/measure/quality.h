#pragma once
// `render --quality X`: the cheapest shading model, tessellation and shadow
// method whose
// error against the reference meets X, from a quick sweep or from the
// results a `bench` run wrote. X is a bound in the chosen metric's units: a
// ceiling for RMSE, a floor for PSNR (FLIP, a ceiling, once it lands).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/metrics/error_metric.h"
#include "measure/benchmark.h"
#include "measure/reference.h"

namespace shadelab {

struct QualityCandidate {
  BenchPoint point;
  uint64_t triangles = 0;
  double costMs = 0.0;  // device median frame time
  double error = 0.0;   // the metric's value against the reference
};

// The cheapest candidate whose error meets `bound` (the smaller error among
// equal costs); none when no candidate does.
std::optional<size_t> cheapestMeeting(const std::vector<QualityCandidate>& candidates,
                                      const ErrorMetric& metric, double bound);

// Every lit model x tessellation 0.5, 1, 2, 4 x shadows off, hard, pcf3
// (default map size) at `msaa`, a few frames each: kQuickSweepSettings runs.
inline constexpr size_t kQuickSweepSettings = 4 * 4 * 3;
std::vector<QualityCandidate> quickQualitySweep(
    Renderer& renderer, const Scene& scene, const Reference& reference, const ErrorMetric& metric,
    uint32_t width, uint32_t height, uint32_t msaa,
    const std::function<void(const std::string&)>& progress);

// The rows of a bench results table for `sceneName` at `msaa` that hold the
// metric's column. Throws InputError naming `source` when none fit.
std::vector<QualityCandidate> candidatesFromBench(const BenchTable& table,
                                                  const std::string& source,
                                                  const std::string& sceneName,
                                                  const ErrorMetric& metric, uint32_t msaa);

}  // namespace shadelab
