#include "measure/benchmark.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/constants.hpp>
#include <map>
#include <sstream>
#include <tuple>

#include "core/base/errors.h"
#include "core/base/names.h"
#include "core/base/process_memory.h"
#include "core/base/stats.h"
#include "core/metrics/metrics.h"
#include "core/scene/frustum.h"
#include "core/scene/gltf_loader.h"
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
  for (glm::uvec2 frame : axes.sizes)
    for (uint32_t lights : axes.lights)
      for (float tessellation : axes.tessellations)
        for (uint32_t samples : axes.msaa)
          for (const std::optional<TextureFilter>& filter : axes.filters)
            for (auto [method, size] : shadows)
              for (float lod : axes.lodErrors)
                for (ShadingModel model : axes.models)
                  points.push_back({model, tessellation, samples, filter, method, size, frame.x,
                                    frame.y, lights, lod});
  return points;
}

Scene withLightRing(const Scene& scene, uint32_t count) {
  Scene lit = scene;
  Bounds bounds = sceneBounds(scene);
  glm::vec3 middle = centre(bounds);
  float radius = std::max(boundingRadius(bounds), 1e-3f);
  lit.lights.clear();
  for (uint32_t i = 0; i < count; ++i) {
    float angle = 2.0f * glm::pi<float>() * (float(i) + 0.5f) / float(count);
    Light light;
    light.type = LightType::Point;
    light.position = middle + radius * glm::vec3(std::cos(angle), 1.0f, std::sin(angle));
    light.intensity = glm::vec3(1.0f / float(count));
    lit.lights.push_back(light);
  }
  return lit;
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
  char text[128];
  std::snprintf(text, sizeof text, "%s t%g %ux%s%s%s%s",
                std::string(shadingModelName(point.model)).c_str(), point.tessellation,
                point.msaaSamples, point.filter ? " " : "",
                point.filter ? textureFilterName(*point.filter) : "",
                point.shadows != ShadowMethod::Off ? " " : "",
                point.shadows != ShadowMethod::Off ? benchShadowName(point).c_str() : "");
  std::string name = text;
  char more[48];
  if (point.lights > 0) {
    std::snprintf(more, sizeof more, " %u lights", point.lights);
    name += more;
  }
  if (point.lodError > 0.0f) {
    std::snprintf(more, sizeof more, " lod %g px", point.lodError);
    name += more;
  }
  return name;
}

std::vector<BenchResult> runBenchmark(Renderer& renderer, const Scene& scene,
                                      const std::vector<BenchPoint>& points,
                                      const BenchOptions& options,
                                      const std::function<void(const std::string&)>& progress) {
  // Each tessellation and light count is built once, not once per round;
  // each frame size and light count has its reference image.
  std::map<std::pair<float, uint32_t>, Scene> scenes;
  std::map<std::tuple<uint32_t, uint32_t, uint32_t>, ImageU8> references;
  bool measured = options.reference.render && !options.metrics.empty();
  for (const BenchPoint& point : points) {
    std::pair<float, uint32_t> key{point.tessellation, point.lights};
    if (!scenes.count(key)) {
      Scene built = point.lights > 0 ? withLightRing(scene, point.lights) : scene;
      if (point.tessellation != 1.0f) built.retessellate(point.tessellation);
      scenes.emplace(key, std::move(built));
    }
    std::tuple<uint32_t, uint32_t, uint32_t> frame{point.width, point.height, point.lights};
    if (measured && !references.count(frame)) {
      progress("reference: " + options.reference.name + " (" + options.reference.description +
               ") at " + std::to_string(point.width) + "x" + std::to_string(point.height) +
               (point.lights > 0 ? ", " + std::to_string(point.lights) + " lights" : ""));
      Scene lit = point.lights > 0 ? withLightRing(scene, point.lights) : scene;
      references.emplace(
          frame, encodeSrgb8(options.reference.render(renderer, lit, point.width, point.height)));
    }
  }

  std::vector<BenchResult> results(points.size());
  std::vector<std::vector<double>> device(points.size()), wall(points.size());
  // With a level-of-detail axis, the first image of each point that has a
  // twin at the other side (a bound and its setting at --lod off), to
  // measure the levels against the same setting drawn in full.
  std::vector<bool> keep(points.size(), false);
  for (size_t i = 0; i < points.size(); ++i) {
    if (points[i].lodError == 0.0f) continue;
    BenchPoint full = points[i];
    full.lodError = 0.0f;
    auto found = std::find(points.begin(), points.end(), full);
    if (found != points.end()) keep[i] = keep[size_t(found - points.begin())] = true;
  }
  bool levels = std::find(keep.begin(), keep.end(), true) != keep.end();
  std::vector<ImageU8> images(levels ? points.size() : 0);
  for (uint32_t round = 0; round < options.rounds; ++round)
    for (size_t i = 0; i < points.size(); ++i) {
      const BenchPoint& point = points[i];
      BenchResult& result = results[i];
      RenderSettings settings{point.width, point.height, point.model};
      settings.frames = options.frames;
      // One camera per run; built at the first frame, so not for a single one.
      settings.lightConstants = options.frames > 1;
      settings.msaaSamples = point.msaaSamples;
      settings.textures.filterOverride = point.filter;
      settings.shadows = point.shadows;
      settings.shadowMapSize = point.shadowMapSize;
      settings.lod = point.lodError > 0.0f;
      if (settings.lod) settings.lodErrorPixels = point.lodError;
      resetPeakResident();
      RenderResult run =
          renderer.renderToImage(scenes.at({point.tessellation, point.lights}), settings);
      result.deviceMemoryBytes = std::max(result.deviceMemoryBytes, run.stats.deviceMemoryBytes);
      result.peakResidentBytes = std::max(result.peakResidentBytes, peakResidentBytes());
      const RenderStats& stats = run.stats;
      size_t warmup = warmupFrames(stats.deviceMs.size());
      device[i].insert(device[i].end(), stats.deviceMs.begin() + long(warmup),
                       stats.deviceMs.end());
      wall[i].insert(wall[i].end(), stats.wallMs.begin() + long(warmup), stats.wallMs.end());
      result.point = point;
      result.triangles = stats.triangles;
      result.lights = uint32_t(scenes.at({point.tessellation, point.lights}).lights.size());
      result.coarserDraws = stats.coarserDraws;
      if (round == 0 && keep[i]) images[i] = encodeSrgb8(run.image);
      std::string errors;
      // Output is deterministic, so the first round's image stands for all.
      if (round == 0 && measured) {
        const ImageU8& reference = references.at({point.width, point.height, point.lights});
        ImageU8 image = encodeSrgb8(run.image);
        for (const ErrorMetric& metric : options.metrics) {
          result.errors.push_back(metric.measure(reference, image));
          char text[48];
          std::snprintf(text, sizeof text, "  %s %.3f", metric.name.c_str(), result.errors.back());
          errors += text;
        }
      }
      char lod[24] = "";
      if (point.lodError > 0.0f) std::snprintf(lod, sizeof lod, " lod %g px", point.lodError);
      char line[300];
      std::snprintf(line, sizeof line,
                    "round %u/%u  %-11s %ux%u lights %-5s tess %-5g msaa %u shadows %-9s%s median "
                    "%.3f ms%s",
                    round + 1, options.rounds, std::string(shadingModelName(point.model)).c_str(),
                    point.width, point.height,
                    point.lights > 0 ? std::to_string(point.lights).c_str() : "scene",
                    point.tessellation, point.msaaSamples, benchShadowName(point).c_str(), lod,
                    median({stats.deviceMs.begin() + long(warmup), stats.deviceMs.end()}),
                    errors.c_str());
      progress(line);
    }
  for (size_t i = 0; i < points.size(); ++i) {
    results[i].frames = device[i].size();
    results[i].deviceMedianMs = median(device[i]);
    results[i].deviceP95Ms = percentile(device[i], 95.0);
    results[i].wallMedianMs = median(wall[i]);
    results[i].wallP95Ms = percentile(wall[i], 95.0);
  }
  for (size_t i = 0; levels && i < points.size(); ++i) {
    BenchPoint full = points[i];
    full.lodError = 0.0f;
    auto found = std::find(points.begin(), points.end(), full);
    if (points[i].lodError > 0.0f && found != points.end() && keep[i])
      results[i].flipAgainstFull =
          flipError(images[size_t(found - points.begin())], images[i]).mean;
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
  // Columns added later go last, so that older readers' positions hold.
  csv << ",lights,lod_error_px,coarser_draws,flip_vs_lod_off\n";
  for (const BenchResult& r : results) {
    csv << sceneName << ',' << r.point.width << ',' << r.point.height << ','
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
    csv << ',' << r.lights << ',' << r.point.lodError << ',' << r.coarserDraws << ',';
    if (r.flipAgainstFull >= 0.0) csv << r.flipAgainstFull;
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
  // As a spreadsheet saves the file: a UTF-8 byte order mark, CRLF line
  // ends and fields in double quotes ("" inside one is a quote) are read as
  // the plain file would be. A quoted field may not hold a comma.
  auto fields = [](std::string line) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::vector<std::string> cells = splitFields(line);
    for (std::string& cell : cells)
      if (cell.size() >= 2 && cell.front() == '"' && cell.back() == '"') {
        const std::string inner = cell.substr(1, cell.size() - 2);
        std::string unquoted;
        for (size_t i = 0; i < inner.size(); ++i) {
          unquoted += inner[i];
          if (inner[i] == '"' && i + 1 < inner.size() && inner[i + 1] == '"') ++i;
        }
        cell = unquoted;
      }
    return cells;
  };
  BenchTable table;
  std::stringstream lines(text.starts_with("\xEF\xBB\xBF") ? text.substr(3) : text);
  std::string line;
  if (!std::getline(lines, line) || line.empty() || line == "\r")
    throw InputError("'" + source + "': empty, expected bench results with a header line");
  table.columns = fields(line);
  for (size_t i = 0; i < table.columns.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (table.columns[i] == table.columns[j])
        throw InputError("'" + source + "': column '" + table.columns[i] +
                         "' twice in the header; expected each once");
  for (size_t number = 2; std::getline(lines, line); ++number) {
    if (line.empty() || line == "\r") continue;
    table.rows.push_back(fields(line));
    if (table.rows.back().size() != table.columns.size())
      throw InputError("'" + source + "' line " + std::to_string(number) + ": " +
                       std::to_string(table.rows.back().size()) + " values, expected " +
                       std::to_string(table.columns.size()));
  }
  return table;
}

}  // namespace shadelab
