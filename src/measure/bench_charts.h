#pragma once
// The benchmark's charts: error against frame time with the Pareto front
// marked, and error against triangle count across the tessellation sweep.
#include <vector>

#include "core/base/image.h"
#include "core/metrics/error_metric.h"
#include "core/metrics/pareto.h"
#include "measure/benchmark.h"

namespace shadelab {

// The results a quality choice or chart considers: every lit model (unlit is
// the timing floor, not a way to render the scene) with an error measured.
std::vector<size_t> chartedResults(const std::vector<BenchResult>& results, size_t metricIndex);
// Pareto front (device median ms against the metric's badness) over `indices`;
// returns indices into `results`, cheapest first.
std::vector<size_t> benchParetoFront(const std::vector<BenchResult>& results,
                                     const std::vector<size_t>& indices, size_t metricIndex,
                                     const ErrorMetric& metric);

ImageU8 errorTimeChart(const std::vector<BenchResult>& results, size_t metricIndex,
                       const ErrorMetric& metric, const std::string& title);
ImageU8 errorTriangleChart(const std::vector<BenchResult>& results, size_t metricIndex,
                           const ErrorMetric& metric, const std::string& title);

// How the frame time grows: a log-log panel per axis that varies among the
// results (triangles through the tessellation sweep, pixels through the frame
// sizes, lights through the light counts), a line per shading model, the
// other axes held at their first value. Empty (0x0) when none varies.
ImageU8 scalingChart(const std::vector<BenchResult>& results, const std::string& title);

// Levels of detail (`bench --lod`): two panels over the error bound in
// pixels, a line per shading model (other axes at their first value): the
// frame time, with --lod off's as a flat line, and the mean FLIP against
// the same model at --lod off, with the 0.01 line. Empty (0x0) unless the
// results hold --lod off and at least one bound for some model.
ImageU8 levelOfDetailChart(const std::vector<BenchResult>& results, const std::string& title);

}  // namespace shadelab
