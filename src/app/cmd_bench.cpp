// shadelab bench: frame times of a scene under each combination of shading
// model, tessellation and MSAA, measured in interleaved rounds, with each
// setting's memory and error against a reference; printed as a table with
// each mode's cost against the constant-colour floor (unlit), written to
// DIR/results.csv and charted (error against time with the Pareto front,
// error against triangles).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/json_output.h"
#include "app/progress.h"
#include "core/base/errors.h"
#include "core/base/files.h"
#include "core/scene/scene_loader.h"
#include "core/scene/texture.h"
#include "interface.h"
#include "measure/bench_charts.h"
#include "measure/benchmark.h"

namespace shadelab {
namespace {
namespace fs = std::filesystem;

struct BenchCommandOptions {
  std::string scene;
  std::string output;
  std::string size = "1280x720";
  std::string modes = "unlit,flat,gouraud,phong,blinn-phong";
  std::string tessellations = "0.5,1,2";
  std::string msaa = "1,4";
  std::string reference = "trace";
  std::string metric = "flip";
  std::string filters = "material";
  std::string shadows{nameOf(kShadowMethodNames, kDefaultShadowMethod)};  // as render draws
  std::string lights = "scene";
  std::string lod = "off";
  std::string shadowSizes = std::to_string(kDefaultShadowMapSize);
  uint32_t frames = 60;
  uint32_t rounds = 2;
  JsonOutput json;
};

// "material,nearest" -> {none, Nearest}; throws InputError naming a bad entry.
std::vector<std::optional<TextureFilter>> parseFilterList(const std::string& text) {
  std::vector<std::optional<TextureFilter>> filters;
  for (const std::string& item : splitList(text, "--filters")) {
    if (item == "material") {
      filters.push_back(std::nullopt);
    } else if (std::optional<TextureFilter> filter = valueOf(kTextureFilterNames, item)) {
      filters.push_back(filter);
    } else {
      throw InputError("--filters '" + item + "': expected material or one of " +
                       joinNames(namesOf(kTextureFilterNames)));
    }
  }
  return filters;
}

// "off,hard" -> {Off, Hard}; throws InputError naming a bad entry.
std::vector<ShadowMethod> parseShadowList(const std::string& text) {
  std::vector<ShadowMethod> methods;
  for (const std::string& item : splitList(text, "--shadows"))
    methods.push_back(parseNamed(kShadowMethodNames, item, "--shadows"));
  return methods;
}

// "1,4" -> {1, 4}; throws InputError naming a bad entry.
std::vector<uint32_t> parseMsaaList(const std::string& text) {
  std::vector<uint32_t> counts;
  for (double count : parseNumberList(text, "--msaa", 1, 4, true, "1 or 4 samples")) {
    if (count != 1 && count != 4)
      throw InputError("--msaa '" + text + "': " + std::to_string(int(count)) +
                       " samples; expected 1 or 4");
    counts.push_back(uint32_t(count));
  }
  return counts;
}

std::vector<float> parseTessellationList(const std::string& text) {
  std::vector<float> factors;
  for (double factor : parseNumberList(text, "--tess", kMinTessellation, kMaxTessellation, false,
                                       "tessellation factors from " +
                                           std::to_string(kMinTessellation).substr(0, 5) + " to " +
                                           std::to_string(int(kMaxTessellation))))
    factors.push_back(float(factor));
  return factors;
}

std::vector<uint32_t> parseShadowSizeList(const std::string& text) {
  std::vector<uint32_t> sizes;
  for (double size :
       parseNumberList(text, "--shadow-sizes", 1, kMaxShadowMapSize, true,
                       "map sizes from 1 to " + std::to_string(kMaxShadowMapSize) + " texels"))
    sizes.push_back(uint32_t(size));
  return sizes;
}

// "320x180,1280x720" -> frame sizes; throws InputError naming a bad entry.
std::vector<glm::uvec2> parseSizeList(const std::string& text) {
  std::vector<glm::uvec2> sizes;
  for (const std::string& item : splitList(text, "--size")) {
    Size size = parseSize(item, "--size");
    sizes.emplace_back(size.width, size.height);
  }
  requireDistinct(sizes, "--size");
  return sizes;
}

// "scene,1,4" -> {0, 1, 4} (0: the scene's own lights); throws InputError.
std::vector<uint32_t> parseLightList(const std::string& text) {
  std::vector<uint32_t> counts;
  for (const std::string& item : splitList(text, "--lights")) {
    if (item == "scene") {
      counts.push_back(0);
      continue;
    }
    char* end = nullptr;
    long count = std::strtol(item.c_str(), &end, 10);
    if (*end != '\0' || count < 1 || count > MAX_LIGHTS)
      throw InputError("--lights '" + item + "': expected scene or a count from 1 to " +
                       std::to_string(MAX_LIGHTS));
    counts.push_back(uint32_t(count));
  }
  requireDistinct(counts, "--lights");
  return counts;
}

// "off,0.5,2" -> {0, 0.5, 2} (0: --lod off); throws InputError naming a bad entry.
std::vector<float> parseLodList(const std::string& text) {
  std::vector<float> bounds;
  for (const std::string& item : splitList(text, "--lod")) {
    if (item == "off") {
      bounds.push_back(0.0f);
      continue;
    }
    char* end = nullptr;
    float bound = std::strtof(item.c_str(), &end);
    if (*end != '\0' || !(bound >= 0.01f && bound <= 100.0f))
      throw InputError("--lod '" + item +
                       "': expected off or an error bound from 0.01 to 100 pixels");
    bounds.push_back(bound);
  }
  requireDistinct(bounds, "--lod");
  return bounds;
}

// One line per setting: cost (with the multiple of the unlit floor), memory,
// error; settings on the Pareto front are starred.
void printResults(const std::vector<BenchResult>& results, const ErrorMetric& metric,
                  size_t metricIndex, bool showFrame, bool showLod, FILE* out) {
  std::vector<size_t> front =
      benchParetoFront(results, chartedResults(results, metricIndex), metricIndex, metric);
  if (showFrame) std::fprintf(out, "%-10s %6s ", "size", "lights");
  if (showLod) std::fprintf(out, "%-6s %7s %8s ", "lod px", "coarser", "FLIP/off");
  std::fprintf(out, "%-12s %5s %5s %-9s %-10s %10s %10s %8s %8s %8s %8s %9s\n", "mode", "tess",
               "msaa", "filter", "shadows", "triangles", "median ms", "p95 ms", "x floor", "dev MB",
               "rss MB", metric.name.c_str());
  for (size_t i = 0; i < results.size(); ++i) {
    const BenchResult& r = results[i];
    const BenchResult* floor = nullptr;
    for (const BenchResult& f : results)
      if (f.point.model == ShadingModel::Unlit && f.point.tessellation == r.point.tessellation &&
          f.point.msaaSamples == r.point.msaaSamples && f.point.filter == r.point.filter &&
          f.point.shadows == r.point.shadows && f.point.shadowMapSize == r.point.shadowMapSize &&
          f.point.width == r.point.width && f.point.height == r.point.height &&
          f.point.lights == r.point.lights && f.point.lodError == r.point.lodError)
        floor = &f;
    char ratio[16] = "-";
    if (floor) std::snprintf(ratio, sizeof ratio, "%.2f", r.deviceMedianMs / floor->deviceMedianMs);
    bool onFront = std::find(front.begin(), front.end(), i) != front.end();
    if (showFrame) {
      std::string frame = std::to_string(r.point.width) + "x" + std::to_string(r.point.height);
      std::fprintf(out, "%-10s %6u ", frame.c_str(), r.lights);
    }
    if (showLod) {
      char bound[16] = "off", flip[16] = "-";
      if (r.point.lodError > 0.0f) std::snprintf(bound, sizeof bound, "%g", r.point.lodError);
      if (r.flipAgainstFull >= 0.0) std::snprintf(flip, sizeof flip, "%.4f", r.flipAgainstFull);
      std::fprintf(out, "%-6s %7u %8s ", bound, r.coarserDraws, flip);
    }
    char error[16] = "-";
    if (metricIndex < r.errors.size())
      std::snprintf(error, sizeof error, "%.3f", r.errors[metricIndex]);
    std::fprintf(out, "%-12s %5g %5u %-9s %-10s %10llu %10.3f %8.3f %8s %8.1f %8.1f %9s%s\n",
                 std::string(shadingModelName(r.point.model)).c_str(), r.point.tessellation,
                 r.point.msaaSamples, benchFilterName(r.point.filter).c_str(),
                 benchShadowName(r.point).c_str(), static_cast<unsigned long long>(r.triangles),
                 r.deviceMedianMs, r.deviceP95Ms, ratio, double(r.deviceMemoryBytes) / (1 << 20),
                 double(r.peakResidentBytes) / (1 << 20), error, onFront ? " *" : "");
  }
  std::fprintf(out,
               "* on the Pareto front of device time against %s; dev MB: device memory "
               "shadelab allocated, rss MB: process peak resident set (VmHWM)\n",
               metric.name.c_str());
}

int runBench(const BenchCommandOptions& options, const GlobalOptions& global) {
  BenchAxes axes{parseShadingModelList(options.modes, "--modes"),
                 parseTessellationList(options.tessellations),
                 parseMsaaList(options.msaa),
                 parseFilterList(options.filters),
                 parseShadowList(options.shadows),
                 parseShadowSizeList(options.shadowSizes),
                 parseSizeList(options.size),
                 parseLightList(options.lights),
                 parseLodList(options.lod)};
  glm::uvec2 size = axes.sizes.front();
  // none: time only (a scaling sweep need not trace each size and light count).
  BenchOptions bench{options.frames, options.rounds,
                     options.reference == "none"
                         ? Reference{"none", "no error measured", {}}
                         : findReference(options.reference, "--reference", "none"),
                     errorMetrics()};
  const ErrorMetric& charted = findErrorMetric(options.metric, "--metric");
  size_t chartedIndex = size_t(&charted - errorMetrics().data());
  Scene scene = loadScene(options.scene, {global.maxTriangles});
  checkOutputFolder(options.output, "results.csv");  // made only with the results
  std::vector<BenchPoint> points = benchPoints(axes);
  // The raster reference is 4x; the sweep's finest point may be finer.
  float finest = options.reference == "raster" ? 4.0f : 0.125f;
  for (const BenchPoint& point : points) finest = std::max(finest, point.tessellation);
  checkTriangleBudget(scene, finest, global.maxTriangles, "the sweep's finest tessellation",
                      "--max-triangles");

  std::unique_ptr<Context> context = openContext(global);
  std::vector<BenchResult> results;
  {
    Renderer renderer(*context);
    std::fprintf(stderr, "bench: scene %s at %s, %zu settings x %u rounds x %u frames\n",
                 scene.name.c_str(), options.size.c_str(), points.size(), options.rounds,
                 options.frames);
    // Each run and reference as it finishes, with an ETA, on a terminal only.
    Progress progress("bench", double(points.size()) * options.rounds);
    results = runBenchmark(renderer, scene, points, bench, [&](const std::string& line) {
      if (line.rfind("round ", 0) == 0)
        progress.step(line);
      else
        progress.note(line);
    });
  }
  fs::path folder(options.output);
  std::string title = "Scene " + scene.name + " at " + options.size + ", against the " +
                      bench.reference.name + " reference";
  // The folder is made only now, with the results: a killed or failed bench
  // leaves no empty folder, and a failed write removes this run's files.
  OutputGroup outputs(folder);
  outputs.add(folder / "results.csv", [&](const std::filesystem::path& to) {
    writeTextFile(to, benchCsv(results, bench, scene.name));
  });
  // The error charts only when errors were measured (not with --reference none).
  bool measured = bool(bench.reference.render);
  if (measured) {
    outputs.add(folder / "error_vs_time.png", [&](const std::filesystem::path& to) {
      writeImage(errorTimeChart(results, chartedIndex, charted, title), to);
    });
    outputs.add(folder / "error_vs_triangles.png", [&](const std::filesystem::path& to) {
      writeImage(errorTriangleChart(results, chartedIndex, charted, title), to);
    });
  }
  ImageU8 scaling = scalingChart(results, "Scene " + scene.name);
  if (scaling.width > 0)
    outputs.add(folder / "scaling.png",
                [&](const std::filesystem::path& to) { writeImage(scaling, to); });
  ImageU8 levels = levelOfDetailChart(results, "Scene " + scene.name + " at " + options.size);
  if (levels.width > 0)
    outputs.add(folder / "lod.png",
                [&](const std::filesystem::path& to) { writeImage(levels, to); });
  outputs.keep();
  FILE* out = options.json.human();
  bool showFrame = axes.sizes.size() > 1 || axes.lights != std::vector<uint32_t>{0};
  bool showLod = axes.lodErrors != std::vector<float>{0.0f};
  printResults(results, charted, chartedIndex, showFrame, showLod, out);
  if (showLod)
    std::fprintf(out,
                 "lod px: --lod auto's error bound (off: every object in full); coarser: draws "
                 "at a simplified level; FLIP/off: mean FLIP against the same setting at --lod "
                 "off\n");
  std::fprintf(out,
               "device medians over %zu steady frames per setting; wrote %s/{results.csv%s%s%s}\n",
               results.empty() ? size_t(0) : results.front().frames, folder.c_str(),
               measured ? ", error_vs_time.png, error_vs_triangles.png" : "",
               scaling.width > 0 ? ", scaling.png" : "", levels.width > 0 ? ", lod.png" : "");
  nlohmann::json json = {{"scene", scene.name},
                         {"settings",
                          {{"width", size.x},
                           {"height", size.y},
                           {"frames", options.frames},
                           {"rounds", options.rounds},
                           {"reference", bench.reference.name},
                           {"charted_metric", charted.name}}},
                         {"results", nlohmann::json::array()},
                         {"outputs", {{"csv", jsonPath(folder / "results.csv")}}}};
  if (measured) {
    json["outputs"]["error_vs_time"] = jsonPath(folder / "error_vs_time.png");
    json["outputs"]["error_vs_triangles"] = jsonPath(folder / "error_vs_triangles.png");
  }
  if (scaling.width > 0) json["outputs"]["scaling"] = jsonPath(folder / "scaling.png");
  if (levels.width > 0) json["outputs"]["lod"] = jsonPath(folder / "lod.png");
  std::vector<size_t> front =
      benchParetoFront(results, chartedResults(results, chartedIndex), chartedIndex, charted);
  for (size_t i = 0; i < results.size(); ++i) {
    nlohmann::json entry = toJson(results[i], bench.metrics);
    entry["pareto"] = std::find(front.begin(), front.end(), i) != front.end();
    json["results"].push_back(entry);
  }
  options.json.emit("bench", json);
  return finishWithValidation(*context, 0);
}

}  // namespace

CommandRunner addBenchCommand(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<BenchCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "bench",
      "Measure frame time, memory and error per shading model, tessellation and MSAA, with "
      "charts (studies of one technique's failure: shadelab study)");
  command->add_option("scene", options->scene,
                      "Built-in scene name or scene file (default: the built-in default scene)");
  command
      ->add_option(
          "-o,--output", options->output,
          "Folder for results.csv and the charts (created if needed, in a folder that exists)")
      ->required();
  command
      ->add_option("--size", options->size,
                   "Frame sizes WIDTHxHEIGHT, comma-separated (more than one: the resolution "
                   "axis of scaling.png)")
      ->capture_default_str();
  command
      ->add_option("--modes", options->modes,
                   "Shading models to measure; unlit is the constant-colour floor")
      ->capture_default_str();
  command->add_option("--tess", options->tessellations, "Tessellation factors, comma-separated")
      ->capture_default_str();
  command->add_option("--msaa", options->msaa, "Sample counts, comma-separated (1 or 4)")
      ->capture_default_str();
  command
      ->add_option("--filters", options->filters,
                   "Texture filters, comma-separated: material (each material's own sampler), "
                   "nearest, bilinear, trilinear, aniso (slow on llvmpipe)")
      ->capture_default_str();
  command
      ->add_option("--shadows", options->shadows,
                   namedHelp("Shadow methods, comma-separated", kShadowMethodNames))
      ->capture_default_str();
  command
      ->add_option("--shadow-sizes", options->shadowSizes,
                   "Shadow map sizes in texels, comma-separated (with shadows on)")
      ->capture_default_str();
  command
      ->add_option("--lights", options->lights,
                   "Light counts, comma-separated: scene (the scene's own lights) or 1 to 8 "
                   "point lights on a ring above the scene, each 1/N as bright (the lights axis "
                   "of scaling.png)")
      ->capture_default_str();
  command
      ->add_option("--lod", options->lod,
                   "Levels of detail, comma-separated: off (every object in full) or --lod auto's "
                   "error bound in pixels; with off and a bound, each bound's image is measured "
                   "against off's (mean FLIP) and charted in lod.png")
      ->capture_default_str();
  command
      ->add_option(
          "--reference", options->reference,
          "What each setting's error is measured against: trace (the CPU Whitted ray "
          "tracer, 4 spp), raster (Phong, 4x tessellation, 4x MSAA, hard shadows) or none (time "
          "only; the charts of error are then empty)")
      ->capture_default_str();
  command
      ->add_option("--metric", options->metric,
                   "Error metric of the charts and the Pareto front: flip (mean FLIP), rmse, "
                   "psnr or ssim (the CSV has every metric)")
      ->capture_default_str();
  command
      ->add_option("--frames", options->frames,
                   "Frames per setting and round (first tenth is warm-up)")
      ->capture_default_str()
      ->check(CLI::Range(2u, 100000u));
  command->add_option("--rounds", options->rounds, "Interleaved rounds over all settings")
      ->capture_default_str()
      ->check(CLI::Range(1u, 1000u));
  options->json.add(command);
  return [options, &global] { return runBench(*options, global); };
}

}  // namespace shadelab
