// The viewer's keys and what the overlay shows about them. A key whose
// feature is not in this build says so; when the feature lands as a
// FrameSettings field, its binding toggles that field like W does: a copy of
// the settings, changed, applied (validated) by the renderer. Only T, G and A
// upload the scene again.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/base/split_screen.h"
#include "core/base/stats.h"
#include "core/scene/lod.h"
#include "core/scene/texture.h"
#include "view/glsl_compiler.h"
#include "view/viewer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace shadelab {
namespace {

std::string formatMs(double ms) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.2f ms", ms);
  return text;
}

double nowSeconds() {
  using Clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
}

std::string withThousands(uint64_t value) {
  std::string digits = std::to_string(value);
  std::string grouped;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) grouped += ',';
    grouped += digits[i];
  }
  return grouped;
}

}  // namespace

const std::vector<KeyBinding>& Viewer::keyBindings() {
  auto modelKey = [](char name, ShadingModel model) {
    return KeyBinding{name, std::string(1, name),
                      "shading model: " + std::string(shadingModelName(model)),
                      [model](Viewer& viewer) { viewer.setModel(model); }};
  };
  static const std::vector<KeyBinding> bindings = {
      modelKey('1', ShadingModel::Flat),
      modelKey('2', ShadingModel::Gouraud),
      modelKey('3', ShadingModel::Phong),
      modelKey('4', ShadingModel::BlinnPhong),
      {'0', "0", "camera back to the scene's own",
       [](Viewer& v) {
         v.camera_ = CameraController(v.sceneCamera_);
         v.say("camera reset");
       }},
      {'V', "V", "print the camera as options for render, trace and compare",
       [](Viewer& v) {
         std::string line = cameraOptionLine(v.camera_.camera());
         std::printf("camera: %s\n", line.c_str());
         std::fflush(stdout);
         v.say("camera printed to the terminal: " + line);
       }},
      {'C', "C", "split screen: the four models side by side, errors against Phong",
       [](Viewer& v) {
         FrameSettings next = v.settings_;
         bool on = next.splitModels.empty();
         next.splitModels.clear();
         if (on)
           next.splitModels = {ShadingModel::Flat, ShadingModel::Gouraud, ShadingModel::Phong,
                               ShadingModel::BlinnPhong};
         if (!v.applySettings(next)) return;
         v.splitErrors_.clear();
         v.say(on ? "split screen on" : "split screen off");
       }},
      {'X', "X",
       "split-screen errors against the traced reference (traced in the background, again "
       "when the view changes) / against Phong",
       [](Viewer& v) {
         bool on = !v.measureAgainstReference_;
         if (on && v.settings_.splitModels.empty()) {
           FrameSettings next = v.settings_;
           next.splitModels = {ShadingModel::Flat, ShadingModel::Gouraud, ShadingModel::Phong,
                               ShadingModel::BlinnPhong};
           if (!v.applySettings(next)) return;
         }
         v.setMeasureAgainstReference(on);
         v.say(on ? "split screen: errors against the traced reference (tracing in the "
                    "background once the camera rests)"
                  : "split screen: errors against phong");
       }},
      {'W', "W", "wireframe overlay",
       [](Viewer& v) {
         if (!v.context_.features().fillModeNonSolid)
           return v.notAvailable("wireframe (the device lacks fillModeNonSolid)");
         FrameSettings next = v.settings_;
         next.wireframe = !next.wireframe;
         if (v.applySettings(next)) v.say(next.wireframe ? "wireframe on" : "wireframe off");
       }},
      {'T', "T", "tessellation x2", [](Viewer& v) { v.setTessellation(v.tessellation_ * 2.0f); }},
      {'G', "G", "tessellation / 2", [](Viewer& v) { v.setTessellation(v.tessellation_ * 0.5f); }},
      {'A', "A", "automatic tessellation for the current view (chord error <= 0.5 px)",
       [](Viewer& v) { v.autoTessellate(); }},
      {'B', "B", "bump mapping (normal and height maps) on / off",
       [](Viewer& v) {
         TextureOptions next = v.settings_.textures;
         next.bump = !next.bump;
         v.applyTextureOptions(next, std::string("bump mapping ") + (next.bump ? "on" : "off"));
       }},
      {'E', "E", "environment mapping (reflection, refraction, skybox) on / off",
       [](Viewer& v) {
         FrameSettings next = v.settings_;
         next.environment = !next.environment;
         if (!v.applySettings(next)) return;
         std::string state = next.environment ? "on" : "off";
         v.say(v.scene_.environment.present()
                   ? "environment mapping " + state
                   : "environment mapping " + state + " (this scene has no environment)");
       }},
      {'F', "F", "texture filter: materials' own, nearest, bilinear, trilinear, aniso",
       [](Viewer& v) {
         TextureOptions next = v.settings_.textures;
         std::optional<TextureFilter>& filter = next.filterOverride;
         // A choice the device cannot sample with (anisotropy) says so and is skipped.
         for (int choice = 0; choice <= int(TextureFilter::Anisotropic) + 1; ++choice) {
           if (!filter)
             filter = TextureFilter::Nearest;
           else if (*filter == TextureFilter::Anisotropic)
             filter.reset();
           else
             filter = TextureFilter(int(*filter) + 1);
           std::string name = filter ? textureFilterName(*filter) : "each material's own";
           // PLATFORM.md: llvmpipe can take tens of seconds a frame with anisotropy.
           if (filter == TextureFilter::Anisotropic) name += " (can be very slow on llvmpipe)";
           if (v.applyTextureOptions(next, "texture filter: " + name)) return;
         }
       }},
      {'S', "S", "shadow maps: off, hard, pcf3, pcf5 in turn",
       [](Viewer& v) {
         FrameSettings next = v.settings_;
         next.shadows = ShadowMethod((int(next.shadows) + 1) % int(kShadowMethodNames.size()));
         if (v.applySettings(next))
           v.say("shadows: " + std::string(nameOf(kShadowMethodNames, next.shadows)));
       }},
      {'I', "I", "impostors: from the nearest atlas cell / the three around the view, blended",
       [](Viewer& v) {
         FrameSettings next = v.settings_;
         next.impostorBlend = !next.impostorBlend;
         if (v.applySettings(next))
           v.say(next.impostorBlend ? "impostors: three cells blended" : "impostors: nearest cell");
       }},
      {'M', "M", "mip-level tint on / off",
       [](Viewer& v) {
         TextureOptions next = v.settings_.textures;
         next.mipTint = !next.mipTint;
         v.applyTextureOptions(next,
                               std::string("mip-level tint ") + (next.mipTint ? "on" : "off"));
       }},
      {'R', "R", "reload shaders from disk", [](Viewer& v) { v.reloadShaders(); }},
      {'P', "P", "screenshot of the presented frame (PNG)",
       [](Viewer& v) { v.screenshotRequest_ = v.nextScreenshotName(); }},
      {'O', "O", "overlay on / off", [](Viewer& v) { v.overlayVisible_ = !v.overlayVisible_; }},
      {'H', "H", "this help", [](Viewer& v) { v.helpVisible_ = !v.helpVisible_; }},
  };
  return bindings;
}

std::vector<std::string> Viewer::keyNames() {
  std::vector<std::string> names;
  for (const KeyBinding& binding : keyBindings()) names.push_back(binding.name);
  return names;
}

void Viewer::handleKey(int key) {
  if (key == GLFW_KEY_ESCAPE) {
    quit_ = true;
    return;
  }
  for (const KeyBinding& binding : keyBindings()) {
    if (binding.key != key) continue;
    if (options_.logKeyLatency) keysAwaitingFrame_.push_back({binding.name, nowSeconds()});
    return binding.action(*this);
  }
}

void Viewer::setModel(ShadingModel model) {
  FrameSettings next = settings_;
  next.shadingModel = model;
  if (!applySettings(next)) return;
  std::string name(shadingModelName(model));
  say(settings_.splitModels.empty() ? name
                                    : name + " (split screen shows all models: C leaves it)");
}

void Viewer::notAvailable(const std::string& feature) {
  say(feature + ": not available in this build");
}

void Viewer::setTessellation(float scale) {
  float clamped = std::clamp(scale, 0.125f, 16.0f);
  if (clamped == tessellation_) return say("tessellation already at its limit");
  tessellation_ = clamped;
  scene_.retessellate(tessellation_);
  uploadScene();  // waits for frames in flight
  char text[96];
  std::snprintf(text, sizeof(text), "tessellation x%g: %s triangles", double(tessellation_),
                withThousands(gpuScene_.triangles).c_str());
  say(text);
}

// As render --tess auto, for the view on screen now; the camera may move on
// afterwards (press A again), T and G go back to a fixed factor.
void Viewer::autoTessellate() {
  VkExtent2D extent = swapchain_.extent();
  tessellateForView(scene_, ViewSize{camera_.camera(), extent.width, extent.height},
                    kAutoTessellationErrorPixels);
  uploadScene();
  say("automatic tessellation for this view (chord error <= 0.5 px): " +
      withThousands(gpuScene_.triangles) + " triangles");
}

// Per-frame switches: the filter picks the material sets bound, bump and mip
// tint the flags pushed per draw.
bool Viewer::applyTextureOptions(const TextureOptions& textures, const std::string& message) {
  FrameSettings next = settings_;
  next.textures = textures;
  if (!applySettings(next)) return false;
  say(gpuScene_.anyTextured ? message : message + " (no textured material in this scene)");
  return true;
}

void Viewer::reloadShaders() {
  std::map<std::string, std::vector<uint32_t>> spirv;
  for (const ShaderVariant& variant : Renderer::shaderVariants()) {
    GlslCompileResult result = compileGlsl(options_.shaderDirectory, variant);
    // Keep every last good pipeline: replace nothing unless all compile.
    if (!result.ok())
      return say("shader reload failed, kept the last good shaders:\n" + result.log, true);
    spirv[std::string(variant.name)] = std::move(result.spirv);
  }
  renderer_.reloadShaders(spirv);
  say("shaders reloaded from " + options_.shaderDirectory.string());
}

std::string Viewer::nextScreenshotName() const {
  for (int i = 1;; ++i) {
    // Both files must be free: the camera sidecar goes beside the image.
    std::string stem = "shadelab-screenshot-" + std::to_string(i);
    if (!std::filesystem::exists(stem + ".png") && !std::filesystem::exists(stem + ".json"))
      return stem + ".png";
  }
}

OverlayText Viewer::overlayText() const {
  OverlayText text;
  std::vector<double> device(deviceMs_.begin(), deviceMs_.end());
  std::vector<double> wall(wallMs_.begin(), wallMs_.end());
  VkExtent2D extent = swapchain_.extent();
  size_t views = std::max<size_t>(1, settings_.splitModels.size());
  text.status.push_back(scene_.name + "  " + std::to_string(extent.width) + "x" +
                        std::to_string(extent.height) + "  present " +
                        presentModeName(swapchain_.presentMode()));
  // Device time of the scene alone (what `render --frames` reports) and of
  // the whole frame (blit, overlay, screenshot copy too); wall time is the
  // interval between presented frames.
  std::vector<double> frameDevice(frameDeviceMs_.begin(), frameDeviceMs_.end());
  text.status.push_back("device: scene " + formatMs(median(device)) + ", frame " +
                        formatMs(median(frameDevice)) + "; wall " + formatMs(median(wall)) +
                        " (medians of " + std::to_string(device.size()) + ")");
  std::vector<double> shadowMs(shadowMs_.begin(), shadowMs_.end());
  text.status.push_back("shadows " + std::string(nameOf(kShadowMethodNames, settings_.shadows)) +
                        ", " + std::to_string(settings_.shadowMapSize) +
                        "^2 maps: " + formatMs(median(shadowMs)) + " of the scene's device time");
  text.status.push_back("triangles " + withThousands(submittedTriangles_ * views) + " submitted" +
                        (views > 1 ? " (" + std::to_string(views) + " views)" : "") + ", " +
                        withThousands(gpuScene_.triangles) + " in the scene" +
                        (settings_.lod
                             ? "; lod " + std::to_string(coarserDraws_) + " draws simplified, " +
                                   std::to_string(impostors_) + " as impostors" +
                                   (impostors_ > 0 && settings_.impostorBlend ? " (blended)" : "")
                             : ""));
  if (billboardCopies_ > 0)
    text.status.push_back("billboards " + withThousands(billboardCopies_) + " copies, " +
                          withThousands(trimmedCopies_) + " trimmed to one triangle" +
                          (settings_.trimBillboards ? "" : " (--billboard-outline quad)"));
  if (settings_.lod) {
    // Objects per level, 0 in full; the last entry also counts coarser ones.
    std::string levels;
    for (size_t i = 0; i < levelDraws_.size(); ++i)
      if (levelDraws_[i] > 0)
        levels += (levels.empty() ? "" : " ") + std::to_string(i) +
                  (i + 1 == levelDraws_.size() ? "+" : "") + ":" + std::to_string(levelDraws_[i]);
    std::vector<double> select(lodSelectMs_.begin(), lodSelectMs_.end());
    text.status.push_back("lod levels " + (levels.empty() ? std::string("-") : levels) +
                          " (level:objects); chosen in " + formatMs(median(select)));
  }
  std::string models;
  for (ShadingModel model : settings_.splitModels)
    models += (models.empty() ? "" : " | ") + std::string(shadingModelName(model));
  text.status.push_back(models.empty()
                            ? "model " + std::string(shadingModelName(settings_.shadingModel))
                            : "split " + models);
  char line[128];
  const TextureOptions& textures = settings_.textures;
  std::snprintf(
      line, sizeof(line), "tessellation x%g  wireframe %s  bump %s  filter %s  mip tint %s",
      double(tessellation_), settings_.wireframe ? "on" : "off", textures.bump ? "on" : "off",
      textures.filterOverride ? textureFilterName(*textures.filterOverride) : "own",
      textures.mipTint ? "on" : "off");
  text.status.push_back(line);
  if (measureAgainstReference_) text.status.push_back(referenceStatus());
  for (const SplitError& error : splitErrors_) {
    std::string model(shadingModelName(error.model));
    if (error.flip)
      std::snprintf(line, sizeof(line), "%-12s vs reference: FLIP %.4f  RMSE %5.2f  PSNR %5.1f dB",
                    model.c_str(), *error.flip, error.difference.rmse, error.difference.psnr);
    else
      std::snprintf(line, sizeof(line), "%-12s vs phong: RMSE %5.2f  PSNR %5.1f dB", model.c_str(),
                    error.difference.rmse, error.difference.psnr);
    text.status.push_back(line);
  }
  text.status.push_back("H help");
  if (!settings_.splitModels.empty()) {
    std::vector<ScreenColumn> columns = splitColumns(extent.width, uint32_t(views));
    for (size_t i = 0; i < views; ++i)
      text.columnLabels.push_back(
          {float(columns[i].left), std::string(shadingModelName(settings_.splitModels[i]))});
  }
  text.message = message_;
  text.messageIsError = messageIsError_;
  if (helpVisible_) {
    text.help.push_back("mouse: left drag orbits, right/middle drag pans, wheel zooms");
    for (const KeyBinding& binding : keyBindings())
      text.help.push_back(binding.name + "  " + binding.help);
    text.help.push_back("Esc  quit");
  }
  return text;
}

}  // namespace shadelab
