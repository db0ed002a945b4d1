// headless_capture: what a test of another project does with shadelab.
// Opens a Vulkan device (lavapipe in CI), loads a scene (a built-in name or
// a .json/.gltf/.glb file), renders it headless with Phong shading, writes the
// image, then renders Gouraud (another upload: renderToImage uploads per call) and measures it
// against the Phong image with FLIP.
//
//   headless_capture OUTPUT.png [SCENE] [--size WxH] [--validate]
//
// Exit 0 on success, 1 on a validation message or an error, 2 on bad usage.
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "core/base/errors.h"
#include "core/base/image.h"
#include "core/metrics/metrics.h"
#include "core/scene/scene_loader.h"
#include "core/vulkan/context.h"
#include "passes/renderer.h"

int main(int argc, char** argv) {
  std::string output;
  std::string sceneName = "default";
  uint32_t width = 320, height = 180;
  bool validate = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--validate") == 0) {
      validate = true;
    } else if (std::strcmp(argv[i], "--size") == 0 && i + 1 < argc) {
      if (std::sscanf(argv[++i], "%ux%u", &width, &height) != 2 || width == 0 || height == 0) {
        std::fprintf(stderr, "headless_capture: --size '%s': expected WIDTHxHEIGHT\n", argv[i]);
        return 2;
      }
    } else if (output.empty()) {
      output = argv[i];
    } else {
      sceneName = argv[i];
    }
  }
  if (output.empty()) {
    std::fprintf(stderr, "usage: headless_capture OUTPUT.png [SCENE] [--size WxH] [--validate]\n");
    return 2;
  }
  try {
    shadelab::ContextOptions contextOptions;
    contextOptions.validation = validate;
    shadelab::Context context(contextOptions);
    shadelab::Scene scene = shadelab::loadScene(sceneName);
    // The camera is the scene's; a program may move it here, e.g.
    // scene.camera.eye = {0.0f, 3.0f, 8.0f};

    shadelab::Renderer renderer(context);
    shadelab::RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.shadingModel = shadelab::ShadingModel::Phong;
    shadelab::RenderResult phong = renderer.renderToImage(scene, settings);
    shadelab::writeImage(phong.image, output);

    settings.shadingModel = shadelab::ShadingModel::Gouraud;
    shadelab::RenderResult gouraud = renderer.renderToImage(scene, settings);
    shadelab::MetricMap flip = shadelab::flipError(shadelab::encodeSrgb8(phong.image),
                                                   shadelab::encodeSrgb8(gouraud.image));
    std::printf("wrote %s (%ux%u, %llu triangles); Gouraud against Phong: mean FLIP %.4f\n",
                output.c_str(), width, height,
                static_cast<unsigned long long>(phong.stats.triangles), flip.mean);
    shadelab::ValidationReport report = context.validationReport();
    if (report.total() != 0) {
      std::fprintf(stderr, "headless_capture: %u validation messages\n", report.total());
      return 1;
    }
    return 0;
  } catch (const shadelab::InputError& error) {
    std::fprintf(stderr, "headless_capture: %s\n", error.what());
    return 2;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "headless_capture: %s\n", error.what());
    return 1;
  }
}
