// shadelab compare: the shading models side by side in viewports of one
// frame (one camera), each with a heatmap of its difference from a reference
// and its error numbers; the numbers also go to a JSON file beside the sheet.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "app/camera_options.h"
#include "app/cli_common.h"
#include "app/commands.h"
#include "app/json_output.h"
#include "app/look_options.h"
#include "core/base/errors.h"
#include "core/base/files.h"
#include "core/base/split_screen.h"
#include "core/metrics/metrics.h"
#include "core/metrics/sheet.h"
#include "core/scene/scene_loader.h"
#include "core/trace/raytracer.h"
#include "core/trace/reflection_regions.h"
#include "measure/reference.h"
#include "passes/renderer.h"

namespace shadelab {
namespace {

struct CompareOptions {
  CameraOptions camera;
  std::string scene;
  std::string output;
  std::string size = "480x270";
  std::string modes = "flat,gouraud,phong,blinn-phong";
  std::string reference = "trace";
  uint32_t samplesPerPixel = 4;
  std::string referenceShadows = "on";
  ShadowOptions shadows;  // of the rasterised views
  JsonOutput json;
};

// The heatmaps' key: the FLIP ramp from 0 (left) to 1 (right) in a band
// across the cell, on the sheet's background.
ImageU8 flipLegend(uint32_t width, uint32_t height) {
  MetricMap ramp{width, height, std::vector<float>(size_t(width) * height), 0.0};
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x)
      ramp.values[size_t(y) * width + x] = float(x) / float(std::max(1u, width - 1));
  ImageU8 legend = magmaHeatmap(ramp);
  for (uint32_t y = 0; y < height; ++y)
    if (y < height * 2 / 5 || y >= height * 3 / 5)
      for (uint32_t x = 0; x < width; ++x) legend.set(x, y, {20, 20, 23, 255});
  return legend;
}

std::string fixed(double value, int digits) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(digits);
  out << value;
  return out.str();
}

// Environment mapping against traced reflection (core/trace/reflection_regions.h):
// the regions as a sheet cell (their sizes also into the report) and each
// mode's FLIP split by them.
SheetCell regionCell(const ReflectionRegions& regions, nlohmann::json& report) {
  const uint64_t hits = regions.count(ReflectionRegion::HitsObject);
  const uint64_t escapes = regions.count(ReflectionRegion::Escapes);
  report["reflectionRegions"] = {{"hitsObjectPixels", hits}, {"escapesPixels", escapes}};
  return {
      regionImage(regions),
      "traced reflection paths",
      {"orange: hit an object (" + std::to_string(hits) + " px)",
       "blue: escape (" + std::to_string(escapes) + " px)", "env mapping shows only what escapes"}};
}

void splitByRegion(const MetricMap& flip, const ReflectionRegions& regions,
                   std::vector<std::string>& lines, nlohmann::json& numbers, FILE* out) {
  const double hitting = meanOver(flip, regions, ReflectionRegion::HitsObject);
  const double escaping = meanOver(flip, regions, ReflectionRegion::Escapes);
  lines.push_back("FLIP hit " + fixed(hitting, 4) + "  escape " + fixed(escaping, 4));
  numbers["flipHitsObject"] = hitting;
  numbers["flipEscapes"] = escaping;
  std::fprintf(out, "   FLIP where the reflection hits an object %.4f, escapes %.4f", hitting,
               escaping);
}

int runCompare(const CompareOptions& options, const GlobalOptions& global) {
  Size cell = parseSize(options.size, "--size");
  std::vector<ShadingModel> models = parseShadingModelList(options.modes, "--modes");
  checkSamplesPerPixel(options.samplesPerPixel, "--spp");
  Reference reference = findReference(options.reference, "--reference");
  if (reference.name == "trace")
    reference =
        traceReference(options.samplesPerPixel,
                       parseNamed(kOnOffNames, options.referenceShadows, "--reference-shadows"));
  FrameSettings shadowSettings;
  options.shadows.apply(shadowSettings);
  std::filesystem::path sheetPath(options.output);
  if (sheetPath.extension() != ".png")
    throw InputError("output '" + options.output + "': expected a .png file name");
  checkOutputPath(sheetPath);
  std::filesystem::path jsonPath = std::filesystem::path(sheetPath).replace_extension(".json");
  Scene scene = loadScene(options.scene, {global.maxTriangles});
  applyCameraOptions(options.camera, float(cell.width) / float(cell.height), scene.camera);
  checkTriangleBudget(scene, 4.0f, global.maxTriangles, "compare (its raster reference is 4x)",
                      "--max-triangles");
  printSceneWarnings(scene, true);

  std::unique_ptr<Context> context = openContext(global);
  ImageU8 split, expected;
  double referenceSeconds = 0.0;
  RenderSettings settings{cell.width * uint32_t(models.size()), cell.height};
  RenderStats splitStats;
  {
    Renderer renderer(*context);
    settings.splitModels = models;
    settings.shadows = shadowSettings.shadows;
    settings.shadowBias = shadowSettings.shadowBias;
    settings.shadowMapSize = shadowSettings.shadowMapSize;
    RenderResult rendered = renderer.renderToImage(scene, settings);
    split = encodeSrgb8(rendered.image);
    splitStats = rendered.stats;
    const auto start = std::chrono::steady_clock::now();
    expected = encodeSrgb8(reference.render(renderer, scene, cell.width, cell.height));
    referenceSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  const std::string& description = reference.description;
  std::vector<SheetCell> renders{{expected, "reference", {description}}};
  std::vector<SheetCell> heatmaps{{flipLegend(cell.width, cell.height),
                                   "FLIP error",
                                   {"0 (left): no visible difference", "1 (right): the largest",
                                    "viewed at 67 pixels/degree"}}};
  nlohmann::json report = {{"scene", scene.name},
                           {"size", options.size},
                           {"reference", description},
                           {"modes", nlohmann::json::array()}};
  std::optional<ReflectionRegions> regions;
  if (scene.environment.present() && reference.name == "trace")
    regions = classifyReflections(scene, cell.width, cell.height);
  FILE* out = options.json.human();
  std::fprintf(out, "reference: %s, %.2f s\n", description.c_str(), referenceSeconds);
  std::fprintf(out, "%-12s %10s %10s %8s %8s %10s\n", "mode", "RMSE", "PSNR dB", "max", "SSIM",
               "mean FLIP");
  // The split frame is exactly models.size() cells wide: every column is one cell.
  std::vector<ScreenColumn> columns = splitColumns(split.width, uint32_t(models.size()));
  for (size_t i = 0; i < models.size(); ++i) {
    std::string name(shadingModelName(models[i]));
    ImageU8 image = cropColumns(split, columns[i].left, columns[i].width);
    ImageDifference difference = compareImages(expected, image);
    const double ssim = structuralSimilarity(expected, image).mean;
    const MetricMap flip = flipError(expected, image);
    renders.push_back({image, name, {}});
    std::vector<std::string> lines{
        "RMSE " + fixed(difference.rmse, 3) + "  PSNR " + fixed(difference.psnr, 2) + " dB",
        "SSIM " + fixed(ssim, 4) + "  FLIP " + fixed(flip.mean, 4),
        "max difference " + std::to_string(difference.maxDifference) + "/255"};
    nlohmann::json numbers = {
        {"mode", name}, {"rmse", difference.rmse}, {"psnr", difference.psnr},
        {"ssim", ssim}, {"flip", flip.mean},       {"maxDifference", difference.maxDifference}};
    std::fprintf(out, "%-12s %10.3f %10.2f %8d %8.4f %10.4f", name.c_str(), difference.rmse,
                 difference.psnr, difference.maxDifference, ssim, flip.mean);
    if (regions) splitByRegion(flip, *regions, lines, numbers, out);
    std::fprintf(out, "\n");
    heatmaps.push_back({magmaHeatmap(flip), name + " vs reference", lines});
    report["modes"].push_back(numbers);
  }
  std::vector<std::vector<SheetCell>> sheet{renders, heatmaps};
  if (regions) sheet.push_back({regionCell(*regions, report)});
  OutputGroup outputs;
  outputs.add(sheetPath, [&] { writeImage(composeSheet(sheet), sheetPath); });
  outputs.add(jsonPath, [&] { writeTextFile(jsonPath, report.dump(2) + "\n"); });
  outputs.keep();
  std::fprintf(out, "wrote %s and %s\n", sheetPath.c_str(), jsonPath.c_str());
  // The report written beside the sheet, with what only this run knows.
  nlohmann::json json = report;
  json["settings"] = toJson(settings);
  json["settings"]["cell_width"] = cell.width;
  json["settings"]["spp"] = options.samplesPerPixel;
  json["timings"] = {{"reference_seconds", referenceSeconds},
                     {"split_frame_device_ms", splitStats.deviceMs.front()}};
  // The split frame draws the scene once per column.
  json["triangles"] = splitStats.triangles;
  json["outputs"] = {{"sheet", shadelab::jsonPath(sheetPath)},
                     {"json", shadelab::jsonPath(jsonPath)}};
  options.json.emit("compare", json);
  return finishWithValidation(*context, 0);
}

}  // namespace

CommandRunner addCompareCommand(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<CompareOptions>();
  CLI::App* command = app.add_subcommand(
      "compare", "Shading models side by side with heatmaps and errors against a reference");
  command->add_option("scene", options->scene, "Built-in scene name or scene file");
  addCameraOptions(command, options->camera);
  command->add_option("-o,--output", options->output, "Sheet image (.png); numbers go to .json")
      ->required();
  command->add_option("--size", options->size, "Size of each view WIDTHxHEIGHT")
      ->capture_default_str();
  command->add_option("--modes", options->modes, "Comma-separated shading models")
      ->capture_default_str();
  command
      ->add_option("--reference", options->reference,
                   "Reference: trace (the CPU Whitted ray tracer) or raster (Phong at 4x "
                   "tessellation with 4x MSAA)")
      ->capture_default_str();
  command
      ->add_option("--spp", options->samplesPerPixel,
                   "Samples per pixel of the traced reference, a square (1, 4, 9, ...)")
      ->capture_default_str()
      ->check(CLI::Range(1u, 256u));
  command
      ->add_option("--reference-shadows", options->referenceShadows,
                   namedHelp("Shadow rays in the traced reference (off, with --shadows off: "
                             "shading alone)",
                             kOnOffNames))
      ->capture_default_str();
  options->shadows.add(command);
  options->json.add(command);
  return [options, &global] { return runCompare(*options, global); };
}

}  // namespace shadelab
