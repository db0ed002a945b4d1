// shadelab bench: frame times of a scene under each combination of shading
// model, tessellation and MSAA, measured in interleaved rounds, printed as a
// table with each mode's cost against the constant-colour floor (unlit) and
// written to DIR/results.csv. Error against the reference and the charts come
// with the ray-traced reference.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/cli_common.h"
#include "app/commands.h"
#include "core/errors.h"
#include "core/files.h"
#include "core/scene_loader.h"
#include "passes/benchmark.h"

namespace shadelab {
namespace {
namespace fs = std::filesystem;

struct BenchCommandOptions {
  std::string scene;
  std::string output;
  std::string size = "1280x720";
  std::string modes = "unlit,flat,gouraud,phong,blinn-phong";
  std::vector<float> tessellations{1.0f};
  std::vector<uint32_t> msaa{1};
  uint32_t frames = 120;
  uint32_t rounds = 3;
};

// Creates DIR if needed (its parent must exist); throws InputError naming it.
void prepareOutputFolder(const fs::path& folder) {
  std::error_code error;
  if (fs::is_directory(folder, error)) {
    checkWritableFolder(folder / "results.csv");
    return;
  }
  if (fs::exists(folder, error))
    throw InputError("output '" + folder.string() + "' exists and is not a folder");
  checkWritableFolder(folder);  // the parent
  if (!fs::create_directory(folder, error))
    throw InputError("cannot create output folder '" + folder.string() + "': " + error.message());
}

int runBench(const BenchCommandOptions& options, const GlobalOptions& global) {
  Size size = parseSize(options.size, "--size");
  std::vector<ShadingModel> models = parseShadingModelList(options.modes, "--modes");
  Scene scene = loadScene(options.scene);
  prepareOutputFolder(options.output);

  std::vector<BenchPoint> points;
  for (float tessellation : options.tessellations)
    for (uint32_t samples : options.msaa)
      for (ShadingModel model : models) points.push_back({model, tessellation, samples});
  BenchOptions bench{size.width, size.height, options.frames, options.rounds};

  std::unique_ptr<Context> context = openContext(global);
  std::vector<BenchResult> results;
  {
    Renderer renderer(*context);
    std::fprintf(stderr, "bench: scene %s at %ux%u, %zu settings x %u rounds x %u frames\n",
                 scene.name.c_str(), size.width, size.height, points.size(), options.rounds,
                 options.frames);
    results = runBenchmark(renderer, scene, points, bench, [](const std::string& line) {
      std::fprintf(stderr, "  %s\n", line.c_str());
    });
  }
  fs::path csv = fs::path(options.output) / "results.csv";
  writeTextFile(csv, benchCsv(results, bench, scene.name));

  std::printf("%-12s %6s %5s %10s %12s %9s %9s\n", "mode", "tess", "msaa", "triangles", "median ms",
              "p95 ms", "x floor");
  for (const BenchResult& r : results) {
    const BenchResult* floor = nullptr;
    for (const BenchResult& f : results)
      if (f.point.model == ShadingModel::Unlit && f.point.tessellation == r.point.tessellation &&
          f.point.msaaSamples == r.point.msaaSamples)
        floor = &f;
    char ratio[16] = "-";
    if (floor) std::snprintf(ratio, sizeof ratio, "%.2f", r.deviceMedianMs / floor->deviceMedianMs);
    std::printf("%-12s %6g %5u %10llu %12.3f %9.3f %9s\n",
                std::string(shadingModelName(r.point.model)).c_str(), r.point.tessellation,
                r.point.msaaSamples, static_cast<unsigned long long>(r.triangles), r.deviceMedianMs,
                r.deviceP95Ms, ratio);
  }
  std::printf("device medians over %zu steady frames per setting; wrote %s\n",
              results.empty() ? size_t(0) : results.front().frames, csv.string().c_str());
  return finishWithValidation(*context, 0);
}

}  // namespace

CommandRunner addBenchCommand(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<BenchCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "bench", "Measure frame times per shading model, tessellation and MSAA (a benchmark)");
  command->add_option("scene", options->scene,
                      "Built-in scene name or scene file (default: the built-in default scene)");
  command->add_option("-o,--output", options->output, "Folder for results.csv (created if needed)")
      ->required();
  command->add_option("--size", options->size, "Frame size WIDTHxHEIGHT")->capture_default_str();
  command
      ->add_option("--modes", options->modes,
                   "Shading models to measure; unlit is the constant-colour floor")
      ->capture_default_str();
  command->add_option("--tess", options->tessellations, "Tessellation factors, comma-separated")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::Range(0.125f, 16.0f));
  command->add_option("--msaa", options->msaa, "Sample counts, comma-separated (1 or 4)")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::IsMember({1u, 4u}));
  command
      ->add_option("--frames", options->frames,
                   "Frames per setting and round (first tenth is warm-up)")
      ->capture_default_str()
      ->check(CLI::Range(2u, 100000u));
  command->add_option("--rounds", options->rounds, "Interleaved rounds over all settings")
      ->capture_default_str()
      ->check(CLI::Range(1u, 1000u));
  return [options, &global] { return runBench(*options, global); };
}

}  // namespace shadelab
