// shadelab compare: the shading models side by side in viewports of one
// frame (one camera), each with a heatmap of its difference from a reference
// and its error numbers; the numbers also go to a JSON file beside the sheet.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <sstream>

#include "app/cli_common.h"
#include "app/commands.h"
#include "core/errors.h"
#include "core/files.h"
#include "core/metrics.h"
#include "core/scene_loader.h"
#include "core/sheet.h"
#include "passes/reference.h"
#include "passes/renderer.h"

namespace shadelab {
namespace {

struct CompareOptions {
  std::string scene;
  std::string output;
  std::string size = "480x270";
  std::string modes = "flat,gouraud,phong,blinn-phong";
  std::string reference = "raster";
};

ImageU8 crop(const ImageU8& image, uint32_t x0, uint32_t width) {
  ImageU8 result(width, image.height);
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < width; ++x) result.set(x, y, image.at(x0 + x, y));
  return result;
}

std::string fixed(double value, int digits) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(digits);
  out << value;
  return out.str();
}

int runCompare(const CompareOptions& options, const GlobalOptions& global) {
  Size cell = parseSize(options.size, "--size");
  std::vector<ShadingModel> models = parseShadingModelList(options.modes, "--modes");
  const Reference& reference = findReference(options.reference, "--reference");
  std::filesystem::path sheetPath(options.output);
  if (sheetPath.extension() != ".png")
    throw InputError("output '" + options.output + "': expected a .png file name");
  checkOutputPath(sheetPath);
  std::filesystem::path jsonPath = std::filesystem::path(sheetPath).replace_extension(".json");
  Scene scene = loadScene(options.scene);

  std::unique_ptr<Context> context = openContext(global);
  ImageU8 split, expected;
  {
    Renderer renderer(*context);
    RenderSettings settings{cell.width * uint32_t(models.size()), cell.height};
    settings.splitModels = models;
    split = encodeSrgb8(renderer.renderToImage(scene, settings).image);
    expected = encodeSrgb8(reference.render(renderer, scene, cell.width, cell.height));
  }

  std::vector<SheetCell> renders{{expected, "reference", {reference.description}}};
  std::vector<SheetCell> heatmaps{{ImageU8(), "", {"heatmaps: |difference| x8", "black = equal"}}};
  nlohmann::json report = {{"scene", scene.name},
                           {"size", options.size},
                           {"reference", reference.description},
                           {"modes", nlohmann::json::array()}};
  std::printf("%-12s %10s %10s %8s\n", "mode", "RMSE", "PSNR dB", "max");
  for (size_t i = 0; i < models.size(); ++i) {
    std::string name(shadingModelName(models[i]));
    ImageU8 image = crop(split, uint32_t(i) * cell.width, cell.width);
    ImageDifference difference = compareImages(expected, image);
    renders.push_back({image, name, {}});
    heatmaps.push_back({differenceHeatmap(expected, image), name + " vs reference",
                        {"RMSE " + fixed(difference.rmse, 3) + "  PSNR " +
                             fixed(difference.psnr, 2) + " dB",
                         "max difference " + std::to_string(difference.maxDifference) + "/255"}});
    report["modes"].push_back({{"mode", name},
                               {"rmse", difference.rmse},
                               {"psnr", difference.psnr},
                               {"maxDifference", difference.maxDifference}});
    std::printf("%-12s %10.3f %10.2f %8d\n", name.c_str(), difference.rmse, difference.psnr,
                difference.maxDifference);
  }
  writeImage(composeSheet({renders, heatmaps}), sheetPath);
  writeTextFile(jsonPath, report.dump(2) + "\n");
  std::printf("wrote %s and %s\n", sheetPath.c_str(), jsonPath.c_str());
  return finishWithValidation(*context, 0);
}

}  // namespace

CommandRunner addCompareCommand(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<CompareOptions>();
  CLI::App* command = app.add_subcommand(
      "compare", "Shading models side by side with heatmaps and errors against a reference");
  command->add_option("scene", options->scene, "Built-in scene name or scene file");
  command->add_option("-o,--output", options->output, "Sheet image (.png); numbers go to .json")
      ->required();
  command->add_option("--size", options->size, "Size of each view WIDTHxHEIGHT")
      ->capture_default_str();
  command->add_option("--modes", options->modes, "Comma-separated shading models")
      ->capture_default_str();
  command->add_option("--reference", options->reference, "Reference renderer: raster")
      ->capture_default_str();
  return [options, &global] { return runCompare(*options, global); };
}

}  // namespace shadelab
