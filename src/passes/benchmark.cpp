#include "passes/benchmark.h"

#include <cstdio>
#include <map>
#include <sstream>

#include "core/stats.h"

namespace shadelab {

std::vector<BenchResult> runBenchmark(Renderer& renderer, const Scene& scene,
                                      const std::vector<BenchPoint>& points,
                                      const BenchOptions& options,
                                      const std::function<void(const std::string&)>& progress) {
  // Each tessellation is built once, not once per round.
  std::map<float, Scene> scenes;
  for (const BenchPoint& point : points)
    if (!scenes.count(point.tessellation)) {
      Scene tessellated = scene;
      if (point.tessellation != 1.0f) tessellated.retessellate(point.tessellation);
      scenes.emplace(point.tessellation, std::move(tessellated));
    }

  std::vector<BenchResult> results(points.size());
  std::vector<std::vector<double>> device(points.size()), wall(points.size());
  for (uint32_t round = 0; round < options.rounds; ++round)
    for (size_t i = 0; i < points.size(); ++i) {
      const BenchPoint& point = points[i];
      RenderSettings settings{options.width, options.height, point.model, options.frames};
      settings.msaaSamples = point.msaaSamples;
      RenderStats stats = renderer.renderToImage(scenes.at(point.tessellation), settings).stats;
      size_t warmup = warmupFrames(stats.deviceMs.size());
      device[i].insert(device[i].end(), stats.deviceMs.begin() + long(warmup), stats.deviceMs.end());
      wall[i].insert(wall[i].end(), stats.wallMs.begin() + long(warmup), stats.wallMs.end());
      results[i].point = point;
      results[i].triangles = stats.triangles;
      char line[200];
      std::snprintf(line, sizeof line, "round %u/%u  %-11s tess %-5g msaa %u  median %.3f ms",
                    round + 1, options.rounds, std::string(shadingModelName(point.model)).c_str(),
                    point.tessellation, point.msaaSamples,
                    median({stats.deviceMs.begin() + long(warmup), stats.deviceMs.end()}));
      progress(line);
    }
  for (size_t i = 0; i < points.size(); ++i) {
    results[i].frames = device[i].size();
    results[i].deviceMedianMs = median(device[i]);
    results[i].deviceP95Ms = percentile(device[i], 95.0);
    results[i].wallMedianMs = median(wall[i]);
    results[i].wallP95Ms = percentile(wall[i], 95.0);
  }
  return results;
}

std::string benchCsv(const std::vector<BenchResult>& results, const BenchOptions& options,
                     const std::string& sceneName) {
  std::ostringstream csv;
  csv << "scene,width,height,mode,tessellation,msaa,triangles,frames,"
         "device_median_ms,device_p95_ms,wall_median_ms,wall_p95_ms\n";
  for (const BenchResult& r : results) {
    csv << sceneName << ',' << options.width << ',' << options.height << ','
        << shadingModelName(r.point.model) << ',' << r.point.tessellation << ','
        << r.point.msaaSamples << ',' << r.triangles << ',' << r.frames << ','
        << r.deviceMedianMs << ',' << r.deviceP95Ms << ',' << r.wallMedianMs << ','
        << r.wallP95Ms << '\n';
  }
  return csv.str();
}

}  // namespace shadelab
