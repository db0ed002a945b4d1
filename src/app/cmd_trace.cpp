// shadelab trace: the CPU Whitted ray tracer's image of a scene, the ground
// truth `compare` measures the rasterised modes against. No Vulkan device.

#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

#include "app/camera_options.h"
#include "app/cli_common.h"
#include "app/commands.h"
#include "app/json_output.h"
#include "app/progress.h"
#include "core/base/errors.h"
#include "core/base/image.h"
#include "core/scene/scene_loader.h"
#include "core/trace/raytracer.h"

namespace shadelab {
namespace {

struct TraceOptions {
  CameraOptions camera;
  std::string scene;
  std::string output;
  std::string size = "1280x720";
  uint32_t samplesPerPixel = 16;
  uint32_t bounces = 5;
  uint32_t threads = 0;
  std::string shadows = "on";
  std::string fresnel = "on";
  std::optional<std::string> epsilon;  // none: TraceSettings' default; '' is an error
  JsonOutput json;
};

// --epsilon: a finite number of world units from 0 to 1; throws InputError.
float parseEpsilon(const std::string& text) {
  // Read as a double: from_chars into a float refuses 1e-50 as out of
  // range, though it lies between 0 and 1 (it becomes 0).
  double value = 0.0;
  const char* end = text.data() + text.size();
  auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end || !std::isfinite(value) || value < 0.0 ||
      value > 1.0)
    throw InputError("--epsilon '" + text +
                     "': expected a number from 0 to 1 (world units the new rays start off the "
                     "surface; default " +
                     std::to_string(TraceSettings{}.epsilon).substr(0, 6) + ")");
  return float(value);
}

int runTrace(const TraceOptions& options, const GlobalOptions& global) {
  Size size = parseSize(options.size, "--size");
  checkSamplesPerPixel(options.samplesPerPixel, "--spp");
  bool shadows = parseNamed(kOnOffNames, options.shadows, "--shadows");
  bool fresnel = parseNamed(kOnOffNames, options.fresnel, "--fresnel");
  const float epsilon = options.epsilon ? parseEpsilon(*options.epsilon) : TraceSettings{}.epsilon;
  checkOutputPath(options.output);  // fail before the expensive work
  Scene scene = loadScene(options.scene, {global.maxTriangles});
  applyCameraOptions(options.camera, float(size.width) / float(size.height), scene.camera);
  checkTriangleBudget(scene, 1.0f, global.maxTriangles, "trace", "--max-triangles");
  printSceneWarnings(scene, false);
  TraceSettings settings;
  settings.width = size.width;
  settings.height = size.height;
  settings.samplesPerPixel = options.samplesPerPixel;
  settings.maxDepth = options.bounces;
  settings.threads = options.threads;
  settings.shadows = shadows;
  settings.fresnel = fresnel;
  settings.epsilon = epsilon;
  // Progress on a terminal only, so logs and pipes get just the summary.
  Progress progress("tracing", 1.0);
  settings.progress = [&](float fraction) { progress.set(fraction); };

  const auto start = std::chrono::steady_clock::now();
  RayTracer tracer(scene);
  const auto built = std::chrono::steady_clock::now();
  TraceResult result = tracer.render(settings);
  progress.finish();
  const auto done = std::chrono::steady_clock::now();
  writeImage(result.image, options.output);

  const double buildSeconds = std::chrono::duration<double>(built - start).count();
  const double traceSeconds = std::chrono::duration<double>(done - built).count();
  const TraceStats& stats = result.stats;
  FILE* out = options.json.human();
  std::fprintf(out, "wrote %s (%ux%u, scene %s, %u spp, %u bounces)\n", options.output.c_str(),
               size.width, size.height, scene.name.c_str(), settings.samplesPerPixel,
               settings.maxDepth);
  const double raysPerSecond = double(stats.total()) / traceSeconds;
  std::fprintf(out,
               "trace: %.3f s (+ %.3f s BVH build), %.2f Mrays/s: %llu primary, %llu shadow, "
               "%llu reflected/refracted (%llu total internal reflections)\n",
               traceSeconds, buildSeconds, raysPerSecond * 1e-6,
               static_cast<unsigned long long>(stats.primaryRays),
               static_cast<unsigned long long>(stats.shadowRays),
               static_cast<unsigned long long>(stats.secondaryRays),
               static_cast<unsigned long long>(stats.totalInternalReflections));
  options.json.emit("trace",
                    {{"scene", scene.name},
                     {"settings",
                      {{"width", size.width},
                       {"height", size.height},
                       {"spp", settings.samplesPerPixel},
                       {"bounces", settings.maxDepth},
                       {"shadows", settings.shadows},
                       {"fresnel", settings.fresnel},
                       {"epsilon", settings.epsilon},
                       {"threads", settings.threads}}},
                     {"timings",
                      {{"trace_seconds", traceSeconds},
                       {"bvh_build_seconds", buildSeconds},
                       {"rays_per_second", raysPerSecond}}},
                     // The scene's meshes, all objects (the tracer culls nothing; it intersects
                     // spheres, planes and boxes exactly, their meshes stand for the rasteriser's).
                     {"triangles", scene.triangleCount()},
                     {"rays",
                      {{"primary", stats.primaryRays},
                       {"shadow", stats.shadowRays},
                       {"secondary", stats.secondaryRays},
                       {"total_internal_reflections", stats.totalInternalReflections}}},
                     {"outputs", {{"image", jsonPath(options.output)}}}});
  return 0;
}

}  // namespace

CommandRunner addTraceCommand(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<TraceOptions>();
  CLI::App* command =
      app.add_subcommand("trace", "Ray trace a scene on the CPU (Whitted): the reference image");
  command->add_option("scene", options->scene,
                      "Built-in scene name or scene file (default: the built-in default scene)");
  addCameraOptions(command, options->camera);
  command->add_option("-o,--output", options->output, "Output image (.png sRGB, .exr linear)")
      ->required();
  options->json.add(command);
  command->add_option("--size", options->size, "Image size WIDTHxHEIGHT")->capture_default_str();
  command
      ->add_option("--spp", options->samplesPerPixel,
                   "Samples per pixel, a square (1, 4, 9, 16, ...): stratified, jittered by a "
                   "fixed hash; 1 samples pixel centres")
      ->capture_default_str()
      ->check(CLI::Range(1u, 256u));
  command
      ->add_option("--bounces", options->bounces,
                   "Reflection/refraction bounces after the primary ray (0: local shading); "
                   "render's --depth is the depth buffer")
      ->capture_default_str()
      ->check(CLI::Range(0u, 64u));
  command
      ->add_option("--threads", options->threads,
                   "Worker threads (0: one per hardware thread); the image does not depend on it")
      ->capture_default_str()
      ->check(CLI::Range(0u, 256u));
  command
      ->add_option("--shadows", options->shadows,
                   namedHelp("Shadow rays (off: as the rasteriser)", kOnOffNames))
      ->capture_default_str();
  command
      ->add_option("--fresnel", options->fresnel,
                   namedHelp("Dielectric Fresnel (Schlick) on glass and its shadows (off: fixed "
                             "kr and kt)",
                             kOnOffNames))
      ->capture_default_str();
  command->add_option("--epsilon", options->epsilon,
                      "Offset of new rays off the surface against self-intersection (shadow "
                      "acne), world units 0..1, times the hit's largest coordinate above 1 "
                      "(default 1e-4)");
  return [options, &global] { return runTrace(*options, global); };
}

}  // namespace shadelab
