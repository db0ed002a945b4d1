// shadelab compare: the shading models side by side in viewports of one
// frame (one camera), or columns of any settings (compare_columns.h) drawn
// one by one, each with a heatmap of its difference from a reference (or a
// column) and its error numbers; the numbers also go to a JSON file beside
// the sheet.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "app/camera_options.h"
#include "app/cli_common.h"
#include "app/commands.h"
#include "app/compare_columns.h"
#include "app/json_output.h"
#include "app/look_options.h"
#include "core/base/errors.h"
#include "core/base/files.h"
#include "core/base/split_screen.h"
#include "core/metrics/metrics.h"
#include "core/metrics/sheet.h"
#include "core/scene/lod.h"
#include "core/scene/scene_loader.h"
#include "core/scene/texture.h"
#include "core/trace/raytracer.h"
#include "core/trace/reflection_regions.h"
#include "core/vulkan/depth.h"
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
  std::vector<std::string> columns;            // --column specs (compare_columns.h)
  std::string against = kReferenceColumnName;  // --against
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

// tess=auto: render --tess-error's default bound, in pixels.
constexpr float kCompareAutoTessellationErrorPixels = 0.5f;

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

// A column as drawn, and the triangles it submitted. (No time: one frame,
// its first, is all compare draws; `bench` measures time.)
struct DrawnColumn {
  ImageU8 image;
  uint64_t triangles = 0;
};

// Columns that differ in model alone are one split frame of one camera (the
// --modes case, exactly as before columns existed); others are drawn one by
// one at the cell's size, each with its own tessellation, MSAA, ...
std::vector<DrawnColumn> drawColumns(Renderer& renderer, const Scene& scene,
                                     const std::vector<CompareColumn>& columns, Size cell,
                                     RenderSettings& settings, RenderStats& splitStats) {
  std::vector<DrawnColumn> drawn;
  settings = RenderSettings{};
  static_cast<FrameSettings&>(settings) = columns.front().settings;
  settings.shadingModel = ShadingModel::Phong;
  settings.width = cell.width * uint32_t(columns.size());
  settings.height = cell.height;
  for (const CompareColumn& column : columns)
    settings.splitModels.push_back(column.settings.shadingModel);
  if (drawableAsOneSplitFrame(columns)) {
    RenderResult rendered = renderer.renderToImage(scene, settings);
    ImageU8 split = encodeSrgb8(rendered.image);
    splitStats = rendered.stats;
    // The split frame is exactly columns.size() cells wide: every column is one cell.
    std::vector<ScreenColumn> cells = splitColumns(split.width, uint32_t(columns.size()));
    for (const ScreenColumn& part : cells)
      drawn.push_back({cropColumns(split, part.left, part.width), rendered.stats.triangles});
    return drawn;
  }
  for (const CompareColumn& column : columns) {
    RenderSettings one;
    static_cast<FrameSettings&>(one) = column.settings;
    one.width = cell.width;
    one.height = cell.height;
    RenderResult rendered;
    if (column.autoTessellation || column.tessellation.value_or(1.0f) != 1.0f) {
      Scene tessellated = scene;
      if (column.autoTessellation)
        tessellateForView(tessellated, ViewSize{scene.camera, cell.width, cell.height},
                          kCompareAutoTessellationErrorPixels);
      else
        tessellated.retessellate(*column.tessellation);
      rendered = renderer.renderToImage(tessellated, one);
    } else {
      rendered = renderer.renderToImage(scene, one);
    }
    drawn.push_back({encodeSrgb8(rendered.image), rendered.stats.triangles});
  }
  return drawn;
}

// Two lines under a column's picture: its settings, for a sheet read alone.
// 0.5 -> "0.5", 2 -> "2": the shortest of up to three decimals.
std::string compactNumber(float value) {
  std::string text = fixed(value, 3);
  text.erase(text.find_last_not_of('0') + 1);
  if (text.back() == '.') text.pop_back();
  return text;
}

std::vector<std::string> settingsLines(const CompareColumn& column) {
  const FrameSettings& s = column.settings;
  std::string tess =
      column.autoTessellation ? "auto" : compactNumber(column.tessellation.value_or(1.0f));
  std::string filter =
      s.textures.filterOverride ? textureFilterName(*s.textures.filterOverride) : "material";
  std::string shadows(nameOf(kShadowMethodNames, s.shadows));
  if (s.shadows != ShadowMethod::Off) shadows += " " + std::to_string(s.shadowMapSize);
  // Short lines: a cell may be as narrow as 240 pixels (30 characters).
  return {std::string(shadingModelName(s.shadingModel)) + "  tess " + tess + "  msaa " +
              std::to_string(s.msaaSamples),
          std::string(depthModeName(s.depth)) + "  env " + (s.environment ? "on" : "off") +
              "  bump " + (s.textures.bump ? "on" : "off"),
          "filter " + filter + (s.lod ? "  lod " + compactNumber(s.lodErrorPixels) + " px" : ""),
          "shadows " + shadows};
}

// What a compare run measures, checked before any device is opened.
struct ComparePlan {
  Size cell;
  std::vector<CompareColumn> columns;
  std::optional<size_t> against;  // none: the reference
  bool columnReport = false;      // --column or --against: the JSON file lists columns
  Reference reference;
  std::filesystem::path sheetPath, jsonPath;
  Scene scene;
};

ComparePlan planCompare(const CompareOptions& options, const GlobalOptions& global) {
  ComparePlan plan;
  plan.cell = parseSize(options.size, "--size");
  FrameSettings defaults;
  options.shadows.apply(defaults);
  plan.columns = options.columns.empty()
                     ? modelColumns(parseShadingModelList(options.modes, "--modes"), defaults)
                     : parseCompareColumns(options.columns, defaults);
  plan.against = findAgainstColumn(plan.columns, options.against);
  // The sheet and JSON beside it keep their --modes form unless columns are asked for.
  plan.columnReport = !options.columns.empty() || plan.against;
  if (plan.against && plan.columns.size() < 2)
    throw InputError("--against '" + options.against +
                     "': expected another column to measure against it");
  checkSamplesPerPixel(options.samplesPerPixel, "--spp");
  plan.reference = findReference(options.reference, "--reference");
  bool referenceShadows = parseNamed(kOnOffNames, options.referenceShadows, "--reference-shadows");
  if (plan.reference.name == "trace")
    plan.reference = traceReference(options.samplesPerPixel, referenceShadows);
  else if (plan.reference.name == "raster")
    plan.reference = rasterReference(referenceShadows);
  plan.sheetPath = options.output;
  if (plan.sheetPath.extension() != ".png")
    throw InputError("output '" + options.output + "': expected a .png file name");
  checkOutputPath(plan.sheetPath);
  plan.jsonPath = std::filesystem::path(plan.sheetPath).replace_extension(".json");
  checkNotInput(plan.jsonPath, options.scene, "the numbers beside the sheet");
  plan.scene = loadScene(options.scene, {global.maxTriangles});
  applyCameraOptions(options.camera, float(plan.cell.width) / float(plan.cell.height),
                     plan.scene.camera);
  // The raster reference draws the scene at 4x; the tracer traces it as
  // loaded, and with --against no reference is drawn.
  bool rasterReference = plan.reference.name == "raster" && !plan.against;
  float columnsFinest = 0.125f;
  for (const CompareColumn& column : plan.columns)
    columnsFinest = std::max(columnsFinest, column.tessellation.value_or(1.0f));
  checkTriangleBudget(
      plan.scene, std::max(columnsFinest, rasterReference ? 4.0f : 0.0f), global.maxTriangles,
      std::string("compare (") + (rasterReference ? "its raster reference is 4x, " : "") +
          "its columns' tess up to " + fixed(columnsFinest, 3) + "x)",
      "--max-triangles");
  // A tess=auto column's tessellation comes from the view: estimated as it will be built.
  for (const CompareColumn& column : plan.columns)
    if (column.autoTessellation) {
      Scene tessellated = plan.scene;
      tessellateForView(tessellated, ViewSize{plan.scene.camera, plan.cell.width, plan.cell.height},
                        kCompareAutoTessellationErrorPixels);
      checkTriangleBudget(tessellated, 1.0f, global.maxTriangles,
                          "compare (a tess=auto column, for its view)", "--max-triangles");
      break;  // every auto column tessellates for the same view
    }
  printSceneWarnings(plan.scene, true);
  // Once per depth mode the columns use.
  std::vector<DepthMode> warned;
  for (const CompareColumn& column : plan.columns)
    if (std::find(warned.begin(), warned.end(), column.settings.depth) == warned.end()) {
      warned.push_back(column.settings.depth);
      printDepthWarning(plan.scene, column.settings.depth);
    }
  return plan;
}

// The sheet's rows and the reports as the columns are measured.
struct CompareSheet {
  std::vector<SheetCell> renders, heatmaps;
  nlohmann::json report;                                 // the .json beside the sheet
  nlohmann::json columnsJson = nlohmann::json::array();  // for stdout, in every form
};

// Each column against `expected` (the reference or the --against column):
// a picture and heatmap cell each, a table line, the JSON entries.
void measureColumns(const ComparePlan& plan, const std::vector<DrawnColumn>& drawn,
                    const ImageU8& expected, const std::string& baseline,
                    const std::optional<ReflectionRegions>& regions, CompareSheet& sheet,
                    FILE* out) {
  int nameWidth = 12;  // the names' column: as wide as the longest
  for (const CompareColumn& column : plan.columns)
    nameWidth = std::max(nameWidth, int(column.name.size()));
  std::fprintf(out, "%-*s %10s %10s %8s %8s %10s\n", nameWidth,
               plan.columnReport ? "column" : "mode", "RMSE", "PSNR dB", "max", "SSIM",
               "mean FLIP");
  const char* listName = plan.columnReport ? "columns" : "modes";
  for (size_t i = 0; i < plan.columns.size(); ++i) {
    const CompareColumn& column = plan.columns[i];
    nlohmann::json columnJson = {{"name", column.name},
                                 {"spec", column.spec},
                                 {"settings", columnSettingsJson(column)},
                                 {"triangles", drawn[i].triangles},
                                 {"against", baseline}};
    if (plan.against && i == *plan.against) {  // the baseline: nothing to measure
      sheet.columnsJson.push_back(columnJson);
      if (plan.columnReport) sheet.report[listName].push_back(columnJson);
      continue;
    }
    const std::string& name = column.name;
    const ImageU8& image = drawn[i].image;
    ImageDifference difference = compareImages(expected, image);
    const double ssim = structuralSimilarity(expected, image).mean;
    const MetricMap flip = flipError(expected, image);
    sheet.renders.push_back(
        {image, name, plan.columnReport ? settingsLines(column) : std::vector<std::string>{}});
    std::vector<std::string> lines{
        "RMSE " + fixed(difference.rmse, 3) + "  PSNR " + fixed(difference.psnr, 2) + " dB",
        "SSIM " + fixed(ssim, 4) + "  FLIP " + fixed(flip.mean, 4),
        "max difference " + std::to_string(difference.maxDifference) + "/255"};
    nlohmann::json numbers = {{"mode", std::string(shadingModelName(column.settings.shadingModel))},
                              {"rmse", difference.rmse},
                              {"psnr", difference.psnr},
                              {"ssim", ssim},
                              {"flip", flip.mean},
                              {"maxDifference", difference.maxDifference}};
    std::fprintf(out, "%-*s %10.3f %10.2f %8d %8.4f %10.4f", nameWidth, name.c_str(),
                 difference.rmse, difference.psnr, difference.maxDifference, ssim, flip.mean);
    if (regions) splitByRegion(flip, *regions, lines, numbers, out);
    std::fprintf(out, "\n");
    sheet.heatmaps.push_back({magmaHeatmap(flip), name + " vs " + baseline, lines});
    nlohmann::json metrics = numbers;
    metrics.erase("mode");
    columnJson["metrics"] = metrics;
    sheet.columnsJson.push_back(columnJson);
    sheet.report[listName].push_back(plan.columnReport ? columnJson : numbers);
  }
}

int runCompare(const CompareOptions& options, const GlobalOptions& global) {
  const ComparePlan plan = planCompare(options, global);
  const Size cell = plan.cell;
  const std::optional<size_t> against = plan.against;
  std::unique_ptr<Context> context = openContext(global);
  std::vector<DrawnColumn> drawn;
  ImageU8 expected;
  double referenceSeconds = 0.0;
  RenderSettings settings;
  RenderStats splitStats;
  {
    Renderer renderer(*context);
    drawn = drawColumns(renderer, plan.scene, plan.columns, cell, settings, splitStats);
    if (!against) {
      const auto start = std::chrono::steady_clock::now();
      expected = encodeSrgb8(plan.reference.render(renderer, plan.scene, cell.width, cell.height));
      referenceSeconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  }
  const std::string baseline = against ? plan.columns[*against].name : kReferenceColumnName;
  if (against) expected = drawn[*against].image;

  const std::string& description = plan.reference.description;
  CompareSheet sheet;
  if (against)
    sheet.renders.push_back(
        {expected, baseline + " (baseline)", settingsLines(plan.columns[*against])});
  else
    sheet.renders.push_back({expected, "reference", {description}});
  sheet.heatmaps.push_back({flipLegend(cell.width, cell.height),
                            "FLIP error",
                            {"0 (left): no visible difference", "1 (right): the largest",
                             "viewed at 67 pixels/degree"}});
  sheet.report = {{"scene", plan.scene.name},
                  {"size", options.size},
                  {"reference", against ? "column '" + baseline + "'" : description}};
  sheet.report[plan.columnReport ? "columns" : "modes"] = nlohmann::json::array();
  if (plan.columnReport) sheet.report["against"] = baseline;
  std::optional<ReflectionRegions> regions;
  if (plan.scene.environment.present() && plan.reference.name == "trace" && !against)
    regions = classifyReflections(plan.scene, cell.width, cell.height);
  FILE* out = options.json.human();
  if (against)
    std::fprintf(out, "against: column '%s'\n", baseline.c_str());
  else
    std::fprintf(out, "reference: %s, %.2f s\n", description.c_str(), referenceSeconds);
  measureColumns(plan, drawn, expected, baseline, regions, sheet, out);
  std::vector<std::vector<SheetCell>> rows{sheet.renders, sheet.heatmaps};
  if (regions) rows.push_back({regionCell(*regions, sheet.report)});
  const std::filesystem::path &sheetPath = plan.sheetPath, &jsonPath = plan.jsonPath;
  OutputGroup outputs;
  outputs.add(sheetPath,
              [&](const std::filesystem::path& to) { writeImage(composeSheet(rows), to); });
  outputs.add(jsonPath, [&](const std::filesystem::path& to) {
    writeTextFile(to, sheet.report.dump(2) + "\n");
  });
  outputs.keep();
  std::fprintf(out, "wrote %s and %s\n", sheetPath.c_str(), jsonPath.c_str());
  // The report written beside the sheet, with what only this run knows.
  nlohmann::json json = sheet.report;
  json["columns"] = sheet.columnsJson;
  json["against"] = baseline;
  json["settings"] = toJson(settings);
  json["settings"]["cell_width"] = cell.width;
  json["settings"]["spp"] = options.samplesPerPixel;
  json["timings"] = {{"reference_seconds", referenceSeconds}};
  if (!splitStats.deviceMs.empty())
    json["timings"]["split_frame_device_ms"] = splitStats.deviceMs.front();
  // The split frame draws the scene once per column; columns drawn apart: their sum.
  uint64_t triangles = splitStats.triangles;
  if (splitStats.deviceMs.empty())
    for (const DrawnColumn& column : drawn) triangles += column.triangles;
  json["triangles"] = triangles;
  json["outputs"] = {{"sheet", shadelab::jsonPath(sheetPath)},
                     {"json", shadelab::jsonPath(jsonPath)}};
  options.json.emit("compare", json);
  return finishWithValidation(*context, 0);
}

}  // namespace

CommandRunner addCompareCommand(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<CompareOptions>();
  CLI::App* command = app.add_subcommand(
      "compare",
      "Shading models (or any settings, --column) side by side with heatmaps and errors against "
      "a reference or a column");
  command->add_option("scene", options->scene, "Built-in scene name or scene file");
  addCameraOptions(command, options->camera);
  command->add_option("-o,--output", options->output, "Sheet image (.png); numbers go to .json")
      ->required();
  command->add_option("--size", options->size, "Size of each view WIDTHxHEIGHT")
      ->capture_default_str();
  CLI::Option* modes =
      command->add_option("--modes", options->modes, "Comma-separated shading models")
          ->capture_default_str();
  command
      ->add_option("--column", options->columns,
                   "A column (repeat for more), instead of --modes: comma-separated key=value "
                   "pairs, a bare word being the model: \"name=fine,phong,tess=4,msaa=4\". Keys: "
                   "name (default: the spec), mode, tess (0.125..16, auto), msaa (1, 4), filter "
                   "(material, nearest, bilinear, trilinear, aniso), env, bump (on, off), depth "
                   "(d16, d24, d32f, reversed), shadows (off, hard, pcf3, pcf5), shadow-size, lod "
                   "(off or an error bound in pixels: as render --lod auto --lod-error)")
      ->excludes(modes)
      ->allow_extra_args(false);
  command
      ->add_option("--against", options->against,
                   "What every column is measured against: reference, or a column's name")
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
      ->add_option(
          "--reference-shadows", options->referenceShadows,
          namedHelp("Shadows in the reference: the tracer's shadow rays, or the raster "
                    "reference's hard shadow maps (off, with --shadows off: shading alone)",
                    kOnOffNames))
      ->capture_default_str();
  options->shadows.add(command);
  options->json.add(command);
  return [options, &global] { return runCompare(*options, global); };
}

}  // namespace shadelab
