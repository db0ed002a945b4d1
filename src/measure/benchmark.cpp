#include "measure/benchmark.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

#include "core/base/errors.h"
#include "core/base/process_memory.h"
#include "core/base/stats.h"
#include "core/scene/texture.h"

namespace shadelab {

std::vector<BenchPoint> benchPoints(const BenchAxes& axes) {
  std::vector<BenchPoint> points;
  // Shadows off has no map size: one point, not one per size.
  std::vector<std::pair<ShadowMethod, uint32_t>> shadows;
  for (ShadowMethod method : axes.shadows) {
    if (method == ShadowMethod::Off)
      shadows.emplace_back(method, kDefaultShadowMapSize);
    else
      for (uint32_t size : axes.shadowMapSizes) shadows.emplace_back(method, size);
  }
  for (float tessellation : axes.tessellations)
    for (uint32_t samples : axes.msaa)
      for (const std::optional<TextureFilter>& filter : axes.filters)
        for (auto [method, size] : shadows)
          for (ShadingModel model : axes.models)
            points.push_back({model, tessellation, samples, filter, method, size});
  return points;
}

std::string benchFilterName(const std::optional<TextureFilter>& filter) {
  return filter ? textureFilterName(*filter) : "material";
}

std::string benchShadowName(const BenchPoint& point) {
  return point.shadows == ShadowMethod::Off
             ? "off"
             : std::string(nameOf(kShadowMethodNames, point.shadows)) + " " +
                   std::to_string(point.shadowMapSize);
}

std::string benchPointName(const BenchPoint& point) {
  char text[96];
  std::snprintf(text, sizeof text, "%s t%g %ux%s%s%s%s",
                std::string(shadingModelName(point.model)).c_str(), point.tessellation,
                point.msaaSamples, point.filter ? " " : "",
                point.filter ? textureFilterName(*point.filter) : "",
                point.shadows != ShadowMethod::Off ? " " : "",
                point.shadows != ShadowMethod::Off ? benchShadowName(point).c_str() : "");
  return text;
}

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
  ImageU8 reference;
  if (options.reference.render && !options.metrics.empty()) {
    progress("reference: " + options.reference.name + " (" + options.reference.description + ")");
    reference =
        encodeSrgb8(options.reference.render(renderer, scene, options.width, options.height));
  }

  std::vector<BenchResult> results(points.size());
  std::vector<std::vector<double>> device(points.size()), wall(points.size());
  for (uint32_t round = 0; round < options.rounds; ++round)
    for (size_t i = 0; i < points.size(); ++i) {
      const BenchPoint& point = points[i];
      BenchResult& result = results[i];
      RenderSettings settings{options.width, options.height, point.model};
      settings.frames = options.frames;
      settings.msaaSamples = point.msaaSamples;
      settings.textures.filterOverride = point.filter;
      settings.shadows = point.shadows;
      settings.shadowMapSize = point.shadowMapSize;
      resetPeakResident();
      RenderResult run = renderer.renderToImage(scenes.at(point.tessellation), settings);
      result.deviceMemoryBytes = std::max(result.deviceMemoryBytes, run.stats.deviceMemoryBytes);
      result.peakResidentBytes = std::max(result.peakResidentBytes, peakResidentBytes());
      const RenderStats& stats = run.stats;
      size_t warmup = warmupFrames(stats.deviceMs.size());
      device[i].insert(device[i].end(), stats.deviceMs.begin() + long(warmup),
                       stats.deviceMs.end());
      wall[i].insert(wall[i].end(), stats.wallMs.begin() + long(warmup), stats.wallMs.end());
      result.point = point;
      result.triangles = stats.triangles;
      std::string errors;
      // Output is deterministic, so the first round's image stands for all.
      if (round == 0 && reference.width > 0) {
        ImageU8 image = encodeSrgb8(run.image);
        for (const ErrorMetric& metric : options.metrics) {
          result.errors.push_back(metric.measure(reference, image));
          char text[48];
          std::snprintf(text, sizeof text, "  %s %.3f", metric.name.c_str(), result.errors.back());
          errors += text;
        }
      }
      char line[240];
      std::snprintf(
          line, sizeof line, "round %u/%u  %-11s tess %-5g msaa %u shadows %-9s median %.3f ms%s",
          round + 1, options.rounds, std::string(shadingModelName(point.model)).c_str(),
          point.tessellation, point.msaaSamples, benchShadowName(point).c_str(),
          median({stats.deviceMs.begin() + long(warmup), stats.deviceMs.end()}), errors.c_str());
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
  csv << "scene,width,height,mode,tessellation,msaa,filter,shadows,shadow_size,triangles,frames,"
         "device_median_ms,device_p95_ms,wall_median_ms,wall_p95_ms,"
         "device_memory_mb,peak_rss_mb,reference";
  for (const ErrorMetric& metric : options.metrics) csv << ',' << metric.name;
  csv << '\n';
  for (const BenchResult& r : results) {
    csv << sceneName << ',' << options.width << ',' << options.height << ','
        << shadingModelName(r.point.model) << ',' << r.point.tessellation << ','
        << r.point.msaaSamples << ',' << benchFilterName(r.point.filter) << ','
        << nameOf(kShadowMethodNames, r.point.shadows) << ','
        << (r.point.shadows == ShadowMethod::Off ? 0 : r.point.shadowMapSize) << ',' << r.triangles
        << ',' << r.frames << ',' << r.deviceMedianMs << ',' << r.deviceP95Ms << ','
        << r.wallMedianMs << ',' << r.wallP95Ms << ',' << double(r.deviceMemoryBytes) / (1 << 20)
        << ',' << double(r.peakResidentBytes) / (1 << 20) << ',' << options.reference.name;
    for (size_t m = 0; m < options.metrics.size(); ++m) {
      csv << ',';
      if (m < r.errors.size()) csv << r.errors[m];
    }
    csv << '\n';
  }
  return csv.str();
}

size_t BenchTable::column(const std::string& name, const std::string& source) const {
  auto found = std::find(columns.begin(), columns.end(), name);
  if (found == columns.end())
    throw InputError("'" + source + "': no column '" + name + "' in the bench results");
  return size_t(found - columns.begin());
}

BenchTable parseBenchCsv(const std::string& text, const std::string& source) {
  auto split = [](const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream stream(line);
    std::string cell;
    while (std::getline(stream, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    return cells;
  };
  BenchTable table;
  std::stringstream lines(text);
  std::string line;
  if (!std::getline(lines, line) || line.empty())
    throw InputError("'" + source + "': empty, expected bench results with a header line");
  table.columns = split(line);
  for (size_t number = 2; std::getline(lines, line); ++number) {
    if (line.empty()) continue;
    table.rows.push_back(split(line));
    if (table.rows.back().size() != table.columns.size())
      throw InputError("'" + source + "' line " + std::to_string(number) + ": " +
                       std::to_string(table.rows.back().size()) + " values, expected " +
                       std::to_string(table.columns.size()));
  }
  return table;
}

}  // namespace shadelab
