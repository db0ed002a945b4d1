#include "measure/quality.h"

#include <algorithm>
#include <cassert>

#include "core/base/errors.h"

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
  try {
    for (const std::vector<std::string>& row : table.rows) {
      std::optional<ShadingModel> model = valueOf(kShadingModelNames, row[mode]);
      std::optional<ShadowMethod> shadows = shadowsOf(row);
      if (row[scene] != sceneName || !model || *model == ShadingModel::Unlit || !shadows ||
          std::stoul(row[samples]) != msaa || row[error].empty() || !ownFilter(row))
        continue;
      uint32_t mapSize = kDefaultShadowMapSize;
      if (*shadows != ShadowMethod::Off && sizeColumn != table.columns.end())
        mapSize = uint32_t(std::stoul(row[size_t(sizeColumn - table.columns.begin())]));
      candidates.push_back({{*model, std::stof(row[tess]), msaa, std::nullopt, *shadows, mapSize},
                            std::stoull(row[triangles]),
                            std::stod(row[cost]),
                            std::stod(row[error])});
    }
  } catch (const std::logic_error&) {  // stoul and friends: not a number
    throw InputError("'" + source + "': a value is not a number where one was expected");
  }
  if (candidates.empty())
    throw InputError("'" + source + "': no lit settings of scene '" + sceneName + "' at msaa " +
                     std::to_string(msaa) + " with a '" + metric.name + "' column");
  return candidates;
}

}  // namespace shadelab
