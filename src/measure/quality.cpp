#include "measure/quality.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <sstream>

#include "core/base/errors.h"
#include "core/scene/shadows.h"

namespace shadelab {

std::optional<size_t> cheapestMeeting(const std::vector<QualityCandidate>& candidates,
                                      const ErrorMetric& metric, double bound) {
  std::optional<size_t> best;
  for (size_t i = 0; i < candidates.size(); ++i) {
    const QualityCandidate& c = candidates[i];
    if (!metric.meets(c.error, bound)) continue;
    if (!best || c.costMs < candidates[*best].costMs ||
        (c.costMs == candidates[*best].costMs &&
         metric.badness(c.error) < metric.badness(candidates[*best].error)))
      best = i;
  }
  return best;
}

std::vector<QualityCandidate> quickQualitySweep(
    Renderer& renderer, const Scene& scene, const Reference& reference, const ErrorMetric& metric,
    uint32_t width, uint32_t height, uint32_t msaa,
    const std::function<void(const std::string&)>& progress) {
  BenchAxes axes{
      {ShadingModel::Flat, ShadingModel::Gouraud, ShadingModel::Phong, ShadingModel::BlinnPhong},
      {0.5f, 1.0f, 2.0f, 4.0f},
      {msaa},
      {std::nullopt},
      {ShadowMethod::Off, ShadowMethod::Hard, ShadowMethod::Pcf3},
      {kDefaultShadowMapSize},
      {{width, height}}};
  // Few frames: enough to rank settings whose costs differ by more than the
  // noise; `bench` measures properly.
  BenchOptions options{/* frames= */ 8, /* rounds= */ 1, reference, {metric}};
  std::vector<BenchPoint> points = benchPoints(axes);
  assert(points.size() == kQuickSweepSettings);
  std::vector<BenchResult> results = runBenchmark(renderer, scene, points, options, progress);
  std::vector<QualityCandidate> candidates;
  for (const BenchResult& r : results)
    candidates.push_back({r.point, r.triangles, r.deviceMedianMs, r.errors.at(0)});
  return candidates;
}

std::vector<QualityCandidate> candidatesFromBench(const BenchTable& table,
                                                  const std::string& source,
                                                  const std::string& sceneName,
                                                  const ErrorMetric& metric, uint32_t msaa) {
  size_t scene = table.column("scene", source), mode = table.column("mode", source);
  size_t tess = table.column("tessellation", source), samples = table.column("msaa", source);
  size_t triangles = table.column("triangles", source);
  size_t cost = table.column("device_median_ms", source);
  size_t error = table.column(metric.name, source);
  // Rows that override the texture filter measure the filter, not the model
  // and tessellation --quality chooses: only the materials' own samplers count.
  auto filterColumn = std::find(table.columns.begin(), table.columns.end(), "filter");
  auto ownFilter = [&](const std::vector<std::string>& row) {
    return filterColumn == table.columns.end() ||
           row[size_t(filterColumn - table.columns.begin())] == "material";
  };
  // Tables from before shadow maps have no shadow columns: shadows off.
  auto shadowsColumn = std::find(table.columns.begin(), table.columns.end(), "shadows");
  auto sizeColumn = std::find(table.columns.begin(), table.columns.end(), "shadow_size");
  auto shadowsOf = [&](const std::vector<std::string>& row) -> std::optional<ShadowMethod> {
    if (shadowsColumn == table.columns.end()) return ShadowMethod::Off;
    return valueOf(kShadowMethodNames, row[size_t(shadowsColumn - table.columns.begin())]);
  };
  std::vector<QualityCandidate> candidates;
  for (size_t r = 0; r < table.rows.size(); ++r) {
    const std::vector<std::string>& row = table.rows[r];
    // A value read as a number within [low, high], or InputError naming the
    // row, the column and the value (the file is anyone's to edit).
    auto number = [&](size_t column, double low, double high) {
      const std::string& text = row[column];
      double value = std::nan("");
      size_t used = 0;
      try {
        value = std::stod(text, &used);
      } catch (const std::logic_error&) {  // not a number, or beyond a double
      }
      if (used != text.size() || !std::isfinite(value) || value < low || value > high) {
        std::ostringstream expected;
        expected << "expected a number from " << low << " to " << high;
        throw InputError("'" + source + "' row " + std::to_string(r + 1) + ", " +
                         table.columns[column] + " '" + text + "': " + expected.str());
      }
      return value;
    };
    std::optional<ShadingModel> model = valueOf(kShadingModelNames, row[mode]);
    std::optional<ShadowMethod> shadows = shadowsOf(row);
    if (row[scene] != sceneName || !model || *model == ShadingModel::Unlit || !shadows ||
        number(samples, 1, 64) != msaa || row[error].empty() || !ownFilter(row))
      continue;
    uint32_t mapSize = kDefaultShadowMapSize;
    if (*shadows != ShadowMethod::Off && sizeColumn != table.columns.end())
      mapSize = uint32_t(number(size_t(sizeColumn - table.columns.begin()), 1, kMaxShadowMapSize));
    // The ranges bench measures (--tess, --shadow-sizes): a choice outside
    // them was not made by shadelab, and could cost any number of triangles.
    candidates.push_back(
        {{*model, float(number(tess, kMinTessellation, kMaxTessellation)), msaa, std::nullopt,
          *shadows, mapSize},
         uint64_t(number(triangles, 0, 1e15)),
         number(cost, 0, 1e9),
         // The metric's own range (FLIP 0..1, SSIM -1..1, ...).
         number(error, std::max(metric.lowest, -1e9), std::min(metric.highest, 1e9))});
  }
  if (candidates.empty())
    throw InputError("'" + source + "': no lit settings of scene '" + sceneName + "' at msaa " +
                     std::to_string(msaa) + " with a '" + metric.name + "' column");
  return candidates;
}

}  // namespace shadelab
