#include <cstdio>
#include <memory>

#include "app/cli_common.h"
#include "app/commands.h"
#include "core/errors.h"
#include "core/image.h"
#include "core/scene_loader.h"
#include "core/stats.h"
#include "core/texture.h"
#include "passes/renderer.h"

namespace shadelab {
namespace {

struct RenderOptions {
  std::string scene;
  std::string output;
  std::string size = "1280x720";
  std::string mode = "phong";
  uint32_t frames = 1;
  float tessellation = 1.0f;
  uint32_t msaa = 1;
  std::string environment = "on";
  std::string filter;  // empty: each material's own sampler
  std::string bump = "on";
  bool mipTint = false;
};

TextureOptions parseTextureOptions(const RenderOptions& options) {
  TextureOptions textures;
  if (!options.filter.empty()) {
    textures.filterOverride = parseTextureFilter(options.filter);
    if (!textures.filterOverride)
      throw InputError("--filter '" + options.filter +
                       "': expected one of nearest, bilinear, trilinear, aniso");
  }
  if (options.bump != "on" && options.bump != "off")
    throw InputError("--bump '" + options.bump + "': expected on or off");
  textures.bump = options.bump == "on";
  textures.mipTint = options.mipTint;
  return textures;
}

void printTimings(const RenderStats& stats) {
  // The first frames include lavapipe's lazy pipeline compile: report them
  // apart and take the steady statistics over the rest.
  size_t warmup = warmupFrames(stats.deviceMs.size());
  std::vector<double> device(stats.deviceMs.begin() + long(warmup), stats.deviceMs.end());
  std::vector<double> wall(stats.wallMs.begin() + long(warmup), stats.wallMs.end());
  std::printf("first frame: %.2f ms wall, %.2f ms device\n", stats.wallMs.front(),
              stats.deviceMs.front());
  std::printf("steady (%zu frames after %zu warm-up): device median %.3f ms, p95 %.3f ms; "
              "wall median %.3f ms, p95 %.3f ms\n",
              device.size(), warmup, median(device), percentile(device, 95.0), median(wall),
              percentile(wall, 95.0));
}

int runRender(const RenderOptions& options, const GlobalOptions& global) {
  Size size = parseSize(options.size, "--size");
  ShadingModel model = parseShadingModelOption(options.mode, "--mode");
  TextureOptions textures = parseTextureOptions(options);
  checkOutputPath(options.output);  // fail before the expensive work
  Scene scene = loadScene(options.scene);
  if (options.tessellation != 1.0f) scene.retessellate(options.tessellation);

  std::unique_ptr<Context> context = openContext(global);
  RenderResult result;
  {
    Renderer renderer(*context);
    RenderSettings settings{size.width, size.height, model, options.frames};
    settings.msaaSamples = options.msaa;
    settings.environment = options.environment == "on";
    settings.textures = textures;
    result = renderer.renderToImage(scene, settings);
  }
  writeImage(result.image, options.output);
  std::printf("wrote %s (%ux%u, scene %s, %s, %llu triangles in %u draws)\n",
              options.output.c_str(), size.width, size.height, scene.name.c_str(),
              options.mode.c_str(), static_cast<unsigned long long>(result.stats.triangles),
              result.stats.drawCalls);
  if (options.frames > 1) printTimings(result.stats);
  return finishWithValidation(*context, 0);
}

}  // namespace

CommandRunner addRenderCommand(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* command = app.add_subcommand("render", "Render a scene headless to an image file");
  command->add_option("scene", options->scene,
                      "Built-in scene name or scene file (default: the built-in default scene)");
  command->add_option("-o,--output", options->output, "Output image (.png sRGB, .exr linear)")
      ->required();
  command->add_option("--size", options->size, "Image size WIDTHxHEIGHT")
      ->capture_default_str();
  command->add_option("--mode", options->mode, "Shading model: flat, gouraud, phong, blinn-phong, "
                      "unlit (constant colour, the timing floor)")
      ->capture_default_str();
  command->add_option("--frames", options->frames,
                      "Frames to draw (2 in flight); above 1, prints frame-time statistics")
      ->capture_default_str()
      ->check(CLI::Range(1u, 100000u));
  command->add_option("--tess", options->tessellation,
                      "Scale the tessellation of procedural shapes and Bezier patches (segments "
                      "per side x FACTOR; icosphere levels + log2 FACTOR)")
      ->capture_default_str()
      ->check(CLI::Range(0.125f, 16.0f));
  command->add_option("--msaa", options->msaa, "Samples per pixel: 1 or 4")
      ->capture_default_str()
      ->check(CLI::IsMember({1u, 4u}));
  command->add_option("--env", options->environment,
                      "Environment mapping (reflections, refraction, skybox) when the scene has "
                      "an environment: on or off")
      ->capture_default_str()
      ->check(CLI::IsMember({"on", "off"}));
  command->add_option("--filter", options->filter,
                      "Texture filter for every texture, overriding the materials' samplers: "
                      "nearest (base level, no mipmaps), bilinear (nearest mip level), "
                      "trilinear, aniso (trilinear + anisotropic; slow on llvmpipe)");
  command->add_option("--bump", options->bump,
                      "Bump mapping (normal and height maps; Phong and Blinn-Phong only): on, off")
      ->capture_default_str();
  command->add_flag("--mip-tint", options->mipTint,
                    "Debug view: tint diffuse textures by the mip level sampled (0 white, 1 red, "
                    "2 orange, 3 yellow, 4 green, 5 cyan, 6 blue, 7+ magenta)");
  return [options, &global] { return runRender(*options, global); };
}

}  // namespace shadelab
