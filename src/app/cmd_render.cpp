#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>

#include "app/camera_options.h"
#include "app/cli_common.h"
#include "app/commands.h"
#include "app/json_output.h"
#include "app/look_options.h"
#include "app/progress.h"
#include "core/base/errors.h"
#include "core/base/files.h"
#include "core/base/image.h"
#include "core/base/stats.h"
#include "core/scene/camera_path.h"
#include "core/scene/lod.h"
#include "core/scene/scene_loader.h"
#include "core/scene/texture.h"
#include "measure/quality.h"
#include "passes/renderer.h"

namespace shadelab {
namespace {

struct RenderOptions {
  CameraOptions camera;
  std::string scene;
  std::string output;
  std::string size = "1280x720";
  std::string mode = "phong";
  uint32_t frames = 1;
  std::string tessellation = "1";
  float tessellationError = 0.5f;
  float simplify = 0.0f;
  uint32_t msaa = 1;
  LookOptions look;  // --env, --filter, --bump, --mip-tint
  std::string depth = "d32f";
  std::optional<double> quality;  // a bound in `metric`'s units
  std::string metric = "flip";
  std::string reference = "trace";
  std::string benchFolder;  // cached bench results; empty: a quick sweep
  JsonOutput json;
  // Sequences: numbered frames NAME-0001.EXT ... instead of one image.
  std::optional<int64_t> turntable;  // N frames orbiting the look-at point
  std::string cameraPath;            // a JSON file of cameras
  bool gif = false;                  // also NAME.gif, animated
  int framesPerSecond = 12;
};

// The cameras of a sequence (turntable or path), or none for one image.
std::vector<Camera> sequenceCameras(const RenderOptions& options, const Camera& camera) {
  if (options.turntable) return turntableCameras(camera, *options.turntable);
  if (options.cameraPath.empty()) return {};
  std::string text = readInputFile(options.cameraPath, "camera path", kMaxTextInputBytes);
  return parseCameraPath(text, options.cameraPath, camera);
}

// Renders one frame per camera into NAME-0001.EXT ..., all or nothing: a
// failure part-way leaves no file of this run and an earlier run's files as
// they were (OutputGroup). With --gif, also NAME.gif. Returns the frame paths (and the GIF's, last)
// and the stats.
std::vector<std::string> writeSequence(Renderer& renderer, const Scene& scene,
                                       const FrameSettings& settings,
                                       const std::vector<Camera>& cameras,
                                       const RenderOptions& options, RenderStats& stats) {
  OutputGroup outputs;
  std::vector<std::string> written;
  std::vector<ImageU8> animation;
  Progress progress("frames", double(cameras.size()));
  stats = renderer.renderSequence(scene, settings, cameras, [&](uint32_t i, ImageRgba&& image) {
    std::string path = sequenceFramePath(options.output, i + 1);
    if (options.gif) animation.push_back(encodeSrgb8(image));
    outputs.add(path, [&](const std::filesystem::path& to) { writeImage(image, to); });
    written.push_back(path);
    progress.step();
  });
  progress.finish();
  if (options.gif) {
    std::string gif = std::filesystem::path(options.output).replace_extension(".gif").string();
    outputs.add(gif, [&](const std::filesystem::path& to) {
      writeAnimatedGif(animation, to, options.framesPerSecond);
    });
    written.push_back(gif);
  }
  outputs.keep();
  return written;
}

std::vector<QualityCandidate> readBenchCandidates(const std::string& folder, const Scene& scene,
                                                  const ErrorMetric& metric, uint32_t msaa) {
  std::filesystem::path csv = std::filesystem::path(folder) / "results.csv";
  std::error_code error;
  if (!std::filesystem::exists(csv, error))
    throw InputError("--bench '" + folder + "': no readable results.csv in it");
  std::string text = readInputFile(csv, "--bench", kMaxTextInputBytes);
  return candidatesFromBench(parseBenchCsv(text, csv.string()), csv.string(), scene.name, metric,
                             msaa);
}

// A candidate's name with its shadows said even when off (benchPointName
// leaves "off" out): --quality weighs shadows too, and a user who did not
// ask for them has to see that the choice dropped them.
std::string candidateName(const BenchPoint& point) {
  return benchPointName(point) + (point.shadows == ShadowMethod::Off ? " no shadows" : "");
}

// Prints every candidate, cheapest first, and why the chosen one won;
// throws InputError when none meets the bound.
BenchPoint reportQualityChoice(std::vector<QualityCandidate> candidates, const ErrorMetric& metric,
                               double bound, const std::string& source, FILE* out) {
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const auto& a, const auto& b) { return a.costMs < b.costMs; });
  std::optional<size_t> chosen = cheapestMeeting(candidates, metric, bound);
  const char* relation = metric.lowerIsBetter ? "<=" : ">=";
  std::fprintf(out, "quality: %s %s %g, from %s\n", metric.name.c_str(), relation, bound,
               source.c_str());
  std::fprintf(out, "  %-34s %10s %10s %9s\n", "setting", "triangles", "device ms",
               metric.name.c_str());
  for (size_t i = 0; i < candidates.size(); ++i) {
    const QualityCandidate& c = candidates[i];
    std::fprintf(out, "  %-34s %10llu %10.3f %9.3f %s\n", candidateName(c.point).c_str(),
                 static_cast<unsigned long long>(c.triangles), c.costMs, c.error,
                 chosen == i                    ? "<- chosen"
                 : metric.meets(c.error, bound) ? "meets"
                                                : "");
  }
  std::fflush(out);  // the table before any error message on stderr
  if (!chosen) {
    size_t best = 0;
    for (size_t i = 1; i < candidates.size(); ++i)
      if (metric.badness(candidates[i].error) < metric.badness(candidates[best].error)) best = i;
    char message[256];
    std::snprintf(message, sizeof message,
                  "--quality %g: no setting reaches %s %s %g; the best is %s with %s %.3f", bound,
                  metric.name.c_str(), relation, bound,
                  candidateName(candidates[best].point).c_str(), metric.name.c_str(),
                  candidates[best].error);
    throw InputError(message);
  }
  const QualityCandidate& c = candidates[*chosen];
  std::fprintf(out,
               "chose %s: the cheapest setting with %s %s %g (%.3f ms device median, %s %.3f)\n",
               candidateName(c.point).c_str(), metric.name.c_str(), relation, bound, c.costMs,
               metric.name.c_str(), c.error);
  // Costs within a tenth of each other are within this machine's timing
  // noise: say so, since another run may rank them the other way.
  for (size_t i = 0; i < candidates.size(); ++i)
    if (i != *chosen && metric.meets(candidates[i].error, bound) &&
        candidates[i].costMs <= c.costMs * 1.1)
      std::fprintf(out,
                   "note: %s costs within 10%% (%.3f ms), inside timing noise; pass --bench DIR "
                   "to choose from fixed measurements\n",
                   candidateName(candidates[i].point).c_str(), candidates[i].costMs);
  return c.point;
}

void printTimings(const FrameTimings& timings, uint32_t shadowDraws, FILE* out) {
  std::fprintf(out, "first frame: %.2f ms wall, %.2f ms device\n", timings.firstWallMs,
               timings.firstDeviceMs);
  std::fprintf(out,
               "steady (%zu frames after %zu warm-up): device median %.3f ms, p95 %.3f ms; "
               "wall median %.3f ms, mean %.3f ms, p95 %.3f ms\n",
               timings.steadyFrames, timings.warmup, timings.deviceMedianMs, timings.deviceP95Ms,
               timings.wallMedianMs, timings.wallMeanMs, timings.wallP95Ms);
  if (timings.shadowMedianMs > 0.0)
    std::fprintf(out,
                 "shadow maps: device median %.3f ms of the frame (%u caster draws in the last "
                 "frame%s)\n",
                 timings.shadowMedianMs, shadowDraws,
                 shadowDraws == 0 ? "; its maps were kept from an earlier frame" : "");
}

int reportSequence(const RenderOptions& options, const Scene& scene, const RenderSettings& settings,
                   const BenchPoint& point, const std::vector<std::string>& written,
                   const RenderStats& stats, const GlobalOptions& global, Context& context) {
  (void)global;
  size_t frames = written.size() - (options.gif ? 1 : 0);
  FILE* out = options.json.human();
  std::fprintf(
      out, "wrote %zu frames %s .. %s (%ux%u, scene %s, %s, %llu triangles in %u draws)%s%s\n",
      frames, written.front().c_str(), written[frames - 1].c_str(), settings.width, settings.height,
      scene.name.c_str(), std::string(shadingModelName(point.model)).c_str(),
      static_cast<unsigned long long>(stats.triangles), stats.drawCalls, options.gif ? " and " : "",
      options.gif ? written.back().c_str() : "");
  FrameTimings timings = frameTimings(stats);
  nlohmann::json json = {{"scene", scene.name},
                         {"settings", toJson(settings)},
                         {"timings", toJson(timings)},
                         {"triangles", stats.triangles},
                         {"draw_calls", stats.drawCalls},
                         {"culled_draws", stats.culledDraws},
                         {"device_memory_bytes", stats.deviceMemoryBytes},
                         {"outputs", {{"frames", nlohmann::json::array()}}}};
  json["settings"]["frames"] = frames;
  json["settings"]["tess"] = point.tessellation;
  json["settings"]["sequence"] = options.turntable ? "turntable" : "camera-path";
  for (size_t i = 0; i < frames; ++i) json["outputs"]["frames"].push_back(jsonPath(written[i]));
  if (options.gif) json["outputs"]["animation"] = jsonPath(written.back());
  options.json.emit("render", json);
  return finishWithValidation(context, 0);
}

int runRender(const RenderOptions& options, const GlobalOptions& global) {
  // One image is no animation (it was ignored without a word).
  if (options.gif && !options.turntable && options.cameraPath.empty())
    throw InputError(
        "--gif: expected --turntable N or --camera-path FILE with it (a sequence to "
        "animate)");
  Size size = parseSize(options.size, "--size");
  bool autoTessellation = options.tessellation == "auto";
  float factor = autoTessellation ? 1.0f : parseTessellationFactor(options.tessellation);
  BenchPoint point{parseNamed(kShadingModelNames, options.mode, "--mode"), factor, options.msaa};
  point.width = size.width;
  point.height = size.height;
  DepthMode depth = parseNamed(kDepthModeNames, options.depth, "--depth");
  FrameSettings look;
  applyLookOptions(options.look, look);
  const ErrorMetric& metric = findErrorMetric(options.metric, "--metric");
  if (options.quality) checkMetricBound(metric, *options.quality, "--quality");
  const Reference& reference = findReference(options.reference, "--reference");
  checkOutputPath(options.output);  // fail before the expensive work
  FILE* out = options.json.human();
  Scene scene = loadScene(options.scene, {global.maxTriangles});
  applyCameraOptions(options.camera, float(size.width) / float(size.height), scene.camera);
  std::vector<Camera> cameras = sequenceCameras(options, scene.camera);
  ViewSize view{scene.camera, size.width, size.height};
  if (autoTessellation) tessellateForView(scene, view, options.tessellationError);
  // Before building: --quality may sweep up to 4x (quality.cpp), the raster reference is 4x.
  float largest = options.quality ? std::max(factor, 4.0f) : factor;
  checkTriangleBudget(scene, largest, global.maxTriangles,
                      options.quality ? "--quality" : "--tess " + options.tessellation,
                      "--max-triangles");
  printSceneWarnings(scene, true);
  printDepthWarning(scene, depth);
  if (options.simplify > 0.0f) {
    SimplifyStats simplified = simplifyForView(scene, view, options.simplify);
    std::fprintf(out, "simplified loaded meshes to %g px: %llu -> %llu triangles\n",
                 options.simplify, static_cast<unsigned long long>(simplified.trianglesBefore),
                 static_cast<unsigned long long>(simplified.trianglesAfter));
  }
  std::vector<QualityCandidate> cached;
  if (options.quality && !options.benchFolder.empty())
    cached = readBenchCandidates(options.benchFolder, scene, metric, options.msaa);

  std::unique_ptr<Context> context = openContext(global);
  RenderResult result;
  // Every look option as applyLookOptions set it (one list: look_options.cpp),
  // then what render chooses itself.
  RenderSettings settings;
  static_cast<FrameSettings&>(settings) = look;
  settings.width = size.width;
  settings.height = size.height;
  std::vector<std::string> written;  // a sequence's files
  {
    Renderer renderer(*context);
    if (options.quality) {
      bool quick = options.benchFolder.empty();
      if (quick) {
        std::fprintf(stderr, "quality: quick sweep of %zu settings against the %s reference\n",
                     kQuickSweepSettings, reference.name.c_str());
        Progress progress("quality sweep", double(kQuickSweepSettings));
        cached = quickQualitySweep(renderer, scene, reference, metric, size.width, size.height,
                                   options.msaa, [&](const std::string& line) {
                                     if (line.rfind("round ", 0) == 0)
                                       progress.step(line);
                                     else
                                       progress.note(line);
                                   });
      }
      point =
          reportQualityChoice(cached, metric, *options.quality,
                              quick ? "a quick sweep against the " + reference.name + " reference"
                                    : options.benchFolder + "/results.csv",
                              out);
      point.width = size.width;  // chosen for this render's size, whatever the table's
      point.height = size.height;
    }
    // A bench table's choice may be finer than the 4x checked above.
    if (options.quality && point.tessellation > largest)
      checkTriangleBudget(scene, point.tessellation, global.maxTriangles,
                          "--quality's choice " + benchPointName(point), "--max-triangles");
    if (point.tessellation != 1.0f) scene.retessellate(point.tessellation);
    settings.shadingModel = point.model;
    settings.frames = options.frames;
    settings.msaaSamples = point.msaaSamples;
    settings.depth = depth;
    // --quality chooses the shadow method and map size with the model.
    settings.shadows = options.quality ? point.shadows : look.shadows;
    settings.shadowMapSize = options.quality ? point.shadowMapSize : look.shadowMapSize;
    bool constants = options.look.materialConstants != "auto" || settings.frames > 1;
    settings.materialConstants = look.materialConstants && (constants || !cameras.empty());
    // Eye-space lights stay the same only while the camera does.
    settings.lightConstants = look.materialConstants && constants && cameras.empty();
    settings.srgb8 = !isLinearOutput(options.output);
    if (!cameras.empty())
      written = writeSequence(renderer, scene, settings, cameras, options, result.stats);
    else
      result = renderer.renderToImage(scene, settings);
  }
  // After the renderer is gone: finishWithValidation shuts the device down.
  if (!cameras.empty())
    return reportSequence(options, scene, settings, point, written, result.stats, global, *context);
  if (settings.srgb8)
    writeImage(result.srgb8, options.output);
  else
    writeImage(result.image, options.output);
  std::string levels = settings.lod ? ", " + std::to_string(result.stats.coarserDraws) +
                                          " at a coarser level of detail (" +
                                          std::to_string(result.stats.impostors) + " impostors)"
                                    : "";
  std::fprintf(out, "wrote %s (%ux%u, scene %s, %s, %llu triangles in %u draws, %u culled%s)\n",
               options.output.c_str(), size.width, size.height, scene.name.c_str(),
               std::string(shadingModelName(point.model)).c_str(),
               static_cast<unsigned long long>(result.stats.triangles), result.stats.drawCalls,
               result.stats.culledDraws, levels.c_str());
  FrameTimings timings = frameTimings(result.stats);
  if (options.frames > 1) printTimings(timings, result.stats.shadowDraws, out);
  nlohmann::json json = {{"scene", scene.name},
                         {"settings", toJson(settings)},
                         {"timings", toJson(timings)},
                         {"triangles", result.stats.triangles},
                         {"draw_calls", result.stats.drawCalls},
                         {"culled_draws", result.stats.culledDraws},
                         {"coarser_draws", result.stats.coarserDraws},
                         {"impostors", result.stats.impostors},
                         {"billboard_copies", result.stats.billboardInstances},
                         {"trimmed_copies", result.stats.trimmedInstances},
                         {"device_memory_bytes", result.stats.deviceMemoryBytes},
                         {"outputs", {{"image", jsonPath(options.output)}}}};
  json["settings"]["frames"] = settings.frames;
  json["settings"]["tess"] =
      autoTessellation ? nlohmann::json("auto") : nlohmann::json(point.tessellation);
  if (options.quality)
    json["quality"] = {
        {"metric", metric.name}, {"bound", *options.quality}, {"chosen", toJson(point)}};
  options.json.emit("render", json);
  return finishWithValidation(*context, 0);
}

}  // namespace

CommandRunner addRenderCommand(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* command = app.add_subcommand("render", "Render a scene headless to an image file");
  command->add_option("scene", options->scene,
                      "Built-in scene name or scene file (default: the built-in default scene)");
  addCameraOptions(command, options->camera);
  command->add_option("-o,--output", options->output, "Output image (.png sRGB, .exr linear)")
      ->required();
  command->add_option("--size", options->size, "Image size WIDTHxHEIGHT")->capture_default_str();
  CLI::Option* mode =
      command
          ->add_option("--mode", options->mode,
                       namedHelp("Shading model (unlit: constant colour, the timing floor)",
                                 kShadingModelNames))
          ->capture_default_str();
  command
      ->add_option("--frames", options->frames,
                   "Frames to draw (2 in flight); above 1, prints frame-time statistics")
      ->capture_default_str()
      ->check(CLI::Range(1u, 100000u));
  CLI::Option* tess =
      command
          ->add_option("--tess", options->tessellation,
                       "Scale the tessellation of procedural shapes and Bezier patches (segments "
                       "per side x FACTOR, 0.125..16; icosphere levels + log2 FACTOR), or 'auto': "
                       "from each shape's projected size, chord error within --tess-error")
          ->capture_default_str();
  command
      ->add_option("--tess-error", options->tessellationError,
                   "Screen-space chord error bound of --tess auto, in pixels")
      ->capture_default_str()
      ->check(finiteRange(0.01, 100.0));
  command
      ->add_option("--simplify", options->simplify,
                   "Simplify loaded (glTF) meshes until their error would exceed PX pixels "
                   "at this view (meshoptimizer); 0: off")
      ->capture_default_str()
      ->check(finiteRange(0.0, 100.0));
  command->add_option("--msaa", options->msaa, "Samples per pixel: 1 or 4")
      ->capture_default_str()
      ->check(CLI::IsMember({1u, 4u}));
  addLookOptions(command, options->look);
  options->json.add(command);
  command
      ->add_option(
          "--depth", options->depth,
          namedHelp("Depth buffer (reversed: D32_SFLOAT, near -> 1, far -> 0)", kDepthModeNames))
      ->capture_default_str();
  CLI::Option* quality =
      command
          ->add_option("--quality", options->quality,
                       "Render with the cheapest model and tessellation whose error meets X in "
                       "--metric units: a mean FLIP or RMSE ceiling, or a PSNR (dB) or SSIM floor")
          ->excludes(mode)
          ->excludes(tess);
  command
      ->add_option("--metric", options->metric,
                   "Error metric of --quality: flip (mean FLIP), rmse, psnr or ssim")
      ->capture_default_str()
      ->needs(quality);
  command
      ->add_option(
          "--reference", options->reference,
          "What --quality measures against: trace (the CPU Whitted ray tracer, 4 spp) or raster "
          "(Phong, 4x tessellation, 4x MSAA, hard shadows)")
      ->capture_default_str()
      ->needs(quality);
  command
      ->add_option("--bench", options->benchFolder,
                   "--quality: choose from DIR/results.csv of an earlier bench run instead of a "
                   "quick sweep")
      ->needs(quality);
  CLI::Option* turntable =
      command
          ->add_option("--turntable", options->turntable,
                       "Render N frames orbiting the look-at point about the up axis into "
                       "NAME-0001.EXT ... (the -o name numbered)")
          ->excludes(quality);
  command
      ->add_option("--camera-path", options->cameraPath,
                   "Render one frame per camera of a JSON file (a list of {eye, at, up, fovy}, "
                   "or {\"frames\": N, \"cameras\": [...]} interpolated) into NAME-0001.EXT ...")
      ->excludes(turntable)
      ->excludes(quality);
  CLI::Option* gif =
      command->add_flag("--gif", options->gif,
                        "With --turntable or --camera-path: also NAME.gif, the frames animated");
  command->add_option("--fps", options->framesPerSecond, "Frames per second of --gif")
      ->capture_default_str()
      ->check(CLI::Range(1, 100))
      ->needs(gif);
  return [options, &global] { return runRender(*options, global); };
}

}  // namespace shadelab
