#include <cstdio>
#include <cstdlib>
#include <memory>

#include "app/camera_options.h"
#include "app/cli_common.h"
#include "app/commands.h"
#include "app/look_options.h"
#include "core/scene/scene_loader.h"
#include "view/viewer.h"

#ifndef SHADELAB_SHADER_SOURCE_DIR
#define SHADELAB_SHADER_SOURCE_DIR "shaders"
#endif

namespace shadelab {
namespace {

struct ViewOptions {
  CameraOptions camera;
  std::string scene;
  std::string size = "1280x720";
  std::string present = "fifo";
  std::string script;
  std::string mode = "phong";
  std::string tessellation = "1";
  LookOptions look;  // --env, --filter, --bump, --mip-tint
  uint32_t msaa = 1;
  std::string depth = "d32f";
  bool keyLatency = false;
};

int runView(const ViewOptions& options, const GlobalOptions& global) {
  // Every input is checked before a window opens.
  Size size = parseSize(options.size, "--size");
  ViewerOptions viewer;
  viewer.presentMode = parsePresentMode(options.present);
  viewer.initial.shadingModel = parseNamed(kShadingModelNames, options.mode, "--mode");
  viewer.initial.msaaSamples = options.msaa;
  viewer.initial.depth = parseNamed(kDepthModeNames, options.depth, "--depth");
  applyLookOptions(options.look, viewer.initial);
  viewer.autoTessellation = options.tessellation == "auto";
  if (!viewer.autoTessellation) viewer.tessellation = parseTessellationFactor(options.tessellation);
  viewer.logKeyLatency = options.keyLatency;
  if (!options.script.empty())
    viewer.script = parseViewerScript(options.script, Viewer::keyNames());
  const char* shaders = std::getenv("SHADELAB_SHADER_DIR");
  viewer.shaderDirectory = shaders && *shaders ? shaders : SHADELAB_SHADER_SOURCE_DIR;
  Scene scene = loadScene(options.scene, {global.maxTriangles});
  applyCameraOptions(options.camera, float(size.width) / float(size.height), scene.camera);
  if (viewer.script) {
    checkScriptCameraPaths(*viewer.script, options.script, scene.camera);
    // A screenshot writes its camera beside it as .json: never over the scene.
    for (const ScriptStep& step : *viewer.script)
      if (step.kind == ScriptStep::Kind::Screenshot) {
        std::filesystem::path sidecar = std::filesystem::path(step.path).replace_extension(".json");
        checkNotInput(sidecar, options.scene, "the camera beside 'screenshot " + step.path + "'");
      }
  }
  checkTriangleBudget(scene, viewer.tessellation, global.maxTriangles,
                      "--tess " + options.tessellation, "--max-triangles");
  printSceneWarnings(scene, true);
  printDepthWarning(scene, viewer.initial.depth);

  std::unique_ptr<Window> window;
  try {
    window = std::make_unique<Window>("shadelab view " + scene.name, size.width, size.height);
  } catch (const WindowError& error) {
    std::fprintf(stderr, "shadelab: error: %s\n", error.what());
    return 1;
  }
  ContextOptions contextOptions;
  contextOptions.validation = global.validate;
  contextOptions.deviceName = global.device;
  contextOptions.instanceExtensions = Window::requiredInstanceExtensions();
  contextOptions.deviceExtensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
  auto context = std::make_unique<Context>(contextOptions);
  {
    Viewer view(*window, *context, std::move(scene), viewer);
    view.run();
  }
  return finishWithValidation(*context, 0);
}

}  // namespace

CommandRunner addViewCommand(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<ViewOptions>();
  CLI::App* command = app.add_subcommand(
      "view", "Interactive window: orbit the scene, toggle shading live (H: keys)");
  command->add_option("scene", options->scene,
                      "Built-in scene name or scene file (default: the built-in default scene)");
  addCameraOptions(command, options->camera);
  command->add_option("--size", options->size, "Initial window size WIDTHxHEIGHT")
      ->capture_default_str();
  command
      ->add_option("--present", options->present, "Present mode: fifo (vsync), mailbox, immediate")
      ->capture_default_str();
  command
      ->add_option("--mode", options->mode,
                   namedHelp("Initial shading model (keys 1-4 change it)", kShadingModelNames))
      ->capture_default_str();
  command
      ->add_option("--tess", options->tessellation,
                   "Initial tessellation scale 0.125..16 as for render, or auto: for the "
                   "initial view, chord error <= 0.5 px (T, G and A change it)")
      ->capture_default_str();
  options->look.lod = "auto";  // the viewer picks levels of detail unless told not to
  addLookOptions(command, options->look);
  command->add_option("--msaa", options->msaa, "Samples per pixel: 1 or 4")
      ->capture_default_str()
      ->check(CLI::IsMember({1u, 4u}));
  command->add_option("--depth", options->depth, namedHelp("Depth buffer", kDepthModeNames))
      ->capture_default_str();
  command->add_flag("--key-latency", options->keyLatency,
                    "Print, per key, the milliseconds from handling it to the next frame's "
                    "present and to that frame's end on the device");
  command->add_option("--script", options->script,
                      "Run the steps of FILE (key, frames, drag, scroll, resize, minimize, "
                      "restore, screenshot, memory, wait-reference, camera-path, quit) instead of "
                      "waiting for input");
  return [options, &global] { return runView(*options, global); };
}

}  // namespace shadelab
