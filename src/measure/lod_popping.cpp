#include "measure/lod_popping.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/metrics/metrics.h"
#include "core/scene/frustum.h"
#include "core/scene/lod.h"
#include "core/scene/transform.h"
#include "core/vulkan/gpu_scene.h"

namespace shadelab {
namespace {

// The eye's height and the direction it always looks (slightly down, as the
// levels-of-detail tests' cameras).
constexpr float kEyeHeight = 1.5f;
const glm::vec3 kLook{0.0f, -1.0f, -16.0f};

Camera cameraAt(float z) {
  Camera camera;
  camera.eye = glm::vec3(0.0f, kEyeHeight, z);
  camera.at = camera.eye + kLook;
  camera.near = 0.1f;
  camera.far = 200.0f;
  return camera;
}

// What the renderer's level choice reads, copied from an upload of the scene.
struct LevelModel {
  std::vector<DrawItem> draws;
  std::vector<DrawLevel> levels;
};

LevelModel uploadedLevels(Renderer& renderer, const Scene& scene) {
  GpuScene gpu =
      renderer.upload(scene, {.environmentCube = false, .detailChains = true, .impostorCells = 0});
  return {gpu.draws, gpu.levels};
}

// Renderer::chooseLevels for one frame (every draw visible: the runs turn
// frustum culling off), updating `drawn` (by object) and returning the
// triangles submitted.
uint64_t chooseModelLevels(const LevelModel& model, const Camera& camera, uint32_t width,
                           uint32_t height, float bound, float hysteresis,
                           std::vector<uint32_t>& drawn) {
  ViewSize view{camera, width, height};
  uint64_t triangles = 0;
  std::vector<float> projected;
  for (const DrawItem& draw : model.draws) {
    uint32_t indexCount = draw.indexCount;
    if (draw.levelCount > 0) {
      uint32_t& level = drawn[uint32_t(draw.constants.object.x)];
      level = chooseDrawLevel(model.levels, draw, view, level, bound, hysteresis, projected);
      if (level > 0) indexCount = model.levels[draw.firstLevel + level - 1].indexCount;
    }
    triangles += indexCount / 3;
  }
  return triangles;
}

FrameSettings runSettings(uint32_t width, uint32_t height, bool lod, float bound,
                          float hysteresis) {
  FrameSettings settings;
  settings.width = width;
  settings.height = height;
  settings.environment = false;
  settings.frustumCulling = false;  // every object's level chosen every frame, as the model's
  settings.lod = lod;
  settings.lodErrorPixels = bound;
  settings.lodHysteresis = hysteresis;
  // Switches between meshes, which the model counts in triangles; what an
  // impostor costs in accuracy is study impostor-parallax's.
  settings.impostorCells = 0;
  return settings;
}

std::vector<ImageU8> renderPath(Renderer& renderer, const Scene& scene, const LodCameraPath& path,
                                const FrameSettings& settings, RenderStats& stats) {
  std::vector<ImageU8> frames(path.cameras.size());
  stats = renderer.renderSequence(
      scene, settings, path.cameras,
      [&](uint32_t index, ImageRgba&& image) { frames[index] = encodeSrgb8(image); });
  return frames;
}

}  // namespace

bool popped(const ImageU8& lodBefore, const ImageU8& offBefore, const ImageU8& lod,
            const ImageU8& off, size_t pixel) {
  for (size_t c = 4 * pixel; c < 4 * pixel + 3; ++c) {
    int before = int(lodBefore.pixels[c]) - int(offBefore.pixels[c]);
    int now = int(lod.pixels[c]) - int(off.pixels[c]);
    if (std::abs(now - before) > kPopCodes) return true;
  }
  return false;
}

ImageU8 popMap(const ImageU8& lodBefore, const ImageU8& offBefore, const ImageU8& lod,
               const ImageU8& off) {
  ImageU8 map = lod;
  for (size_t i = 0; i < map.pixels.size() / 4; ++i) {
    bool hit = popped(lodBefore, offBefore, lod, off, i);
    for (size_t c = 4 * i; c < 4 * i + 3; ++c)
      map.pixels[c] = hit ? uint8_t(255 * (c % 4 == 0)) : uint8_t(map.pixels[c] / 3);
  }
  return map;
}

Scene lodPoppingScene() {
  Scene scene;
  scene.name = "lod-popping";
  scene.background = glm::vec3(0.35f, 0.45f, 0.6f);
  scene.ambient = glm::vec3(0.3f);
  scene.lights.push_back(Light{});
  scene.lights.back().position = glm::vec3(2.0f, 6.0f, 4.0f);
  scene.lights.push_back(Light{});
  scene.lights.back().type = LightType::Directional;
  scene.lights.back().direction = glm::vec3(-1.0f, -2.0f, -1.5f);
  scene.lights.back().intensity = glm::vec3(0.6f);
  uint32_t sphere =
      scene.addShape({.kind = ShapeKind::UvSphere, .radius = 1.0f, .tessellation = 128});
  uint32_t teapot = scene.addShape({.kind = ShapeKind::Teapot, .tessellation = 16});
  for (int i = 0; i < 6; ++i) {
    Material material;
    material.kd = i % 2 ? glm::vec3(0.8f, 0.5f, 0.2f) : glm::vec3(0.3f, 0.5f, 0.8f);
    material.ks = glm::vec3(0.6f);
    material.shininess = 60.0f;
    // A diagonal row, nearer on the left, so no shape hides another.
    glm::mat4 transform = translation(glm::vec3(-3.0f + 1.5f * float(i), 0.0f, -5.0f * float(i)));
    if (i % 2) transform = transform * scaling(glm::vec3(0.5f));
    scene.objects.push_back(
        {"shape " + std::to_string(i), i % 2 ? teapot : sphere, transform, material});
  }
  return scene;
}

LodCameraPath dollyPath(uint32_t frames) {
  LodCameraPath path{"dolly", {}, {}};
  for (uint32_t i = 0; i < frames; ++i) {
    // The same factor each frame, so the shapes' sizes change slowly
    // throughout (a step a tenth of the path's is under 1% at 241 frames).
    float z = 4.0f * std::pow(10.0f, float(i) / float(std::max(frames, 2u) - 1));
    path.cameras.push_back(cameraAt(z));
    path.eyeZ.push_back(z);
  }
  return path;
}

LodCameraPath oscillationPath(const Scene& scene, Renderer& renderer, uint32_t frames,
                              uint32_t height, float lodErrorPixels) {
  LevelModel model = uploadedLevels(renderer, scene);
  // The first object (the nearest sphere) and its third coarser level, 16
  // slices: its error reaches the bound at eye-space depth
  // error * height / (2 tan(fovy / 2) bound) (lod.h, pixelsPerUnit).
  const DrawItem& draw = model.draws.at(0);
  const uint32_t level = 3;
  float error = model.levels.at(draw.firstLevel + level - 1).error * draw.objectScale;
  Camera camera = cameraAt(0.0f);
  float depth = error * float(height) /
                (2.0f * std::tan(glm::radians(camera.fovyDegrees) * 0.5f) * lodErrorPixels);
  // The nearest point of the box's sphere at that depth along the view:
  // depth = dot(centre - eye, forward) - radius, solved for the eye's z.
  glm::vec3 forward = glm::normalize(kLook);
  glm::vec3 middle = centre(draw.worldBounds);
  float radius = boundingRadius(draw.worldBounds);
  float along = depth + radius - forward.y * (middle.y - kEyeHeight);
  float switchZ = middle.z + along / -forward.z;
  float amplitude = 0.03f * depth;
  LodCameraPath path{"oscillate", {}, {}};
  const float kPi = 3.14159265f;
  for (uint32_t i = 0; i < frames; ++i) {
    // A quarter frame of phase, so no frame sits exactly on the threshold.
    float z = switchZ + amplitude * std::sin(2.0f * kPi * (float(i) + 0.25f) / 12.0f);
    path.cameras.push_back(cameraAt(z));
    path.eyeZ.push_back(z);
  }
  return path;
}

uint32_t LodPoppingRun::switches() const {
  uint32_t total = 0;
  for (const LodPoppingFrame& frame : frames) total += frame.switches;
  return total;
}

uint32_t LodPoppingRun::switchFrames() const {
  uint32_t total = 0;
  for (const LodPoppingFrame& frame : frames) total += frame.switches > 0;
  return total;
}

double LodPoppingRun::stepRatio(bool atSwitch) const {
  double lod = 0.0, off = 0.0;
  for (size_t i = 1; i < frames.size(); ++i) {
    if ((frames[i].switches > 0) != atSwitch) continue;
    lod += frames[i].stepLod;
    off += frames[i].stepOff;
  }
  return off > 0.0 ? lod / off : 0.0;
}

double LodPoppingRun::meanPopped(bool atSwitch) const {
  double sum = 0.0;
  uint32_t count = 0;
  for (size_t i = 1; i < frames.size(); ++i) {
    if ((frames[i].switches > 0) != atSwitch) continue;
    sum += double(frames[i].poppedPixels);
    ++count;
  }
  return count ? sum / count : 0.0;
}

double LodPoppingRun::meanErrorAgainstOff() const {
  double sum = 0.0;
  for (const LodPoppingFrame& frame : frames) sum += frame.errorAgainstOff;
  return frames.empty() ? 0.0 : sum / double(frames.size());
}

double LodPoppingRun::maxErrorAgainstOff() const {
  double most = 0.0;
  for (const LodPoppingFrame& frame : frames) most = std::max(most, frame.errorAgainstOff);
  return most;
}

std::vector<LodPoppingRun> measureLodPopping(Renderer& renderer, const Scene& scene,
                                             const LodCameraPath& path,
                                             std::span<const float> hysteresis, uint32_t width,
                                             uint32_t height, float lodErrorPixels) {
  LevelModel model = uploadedLevels(renderer, scene);
  RenderStats stats;
  std::vector<ImageU8> off = renderPath(
      renderer, scene, path, runSettings(width, height, false, lodErrorPixels, 1.0f), stats);
  std::vector<double> stepOff(off.size(), 0.0);
  for (size_t i = 1; i < off.size(); ++i) stepOff[i] = flipError(off[i - 1], off[i]).mean;

  std::vector<LodPoppingRun> runs;
  for (float factor : hysteresis) {
    LodPoppingRun run{path.name, lodErrorPixels, factor, {}};
    std::vector<ImageU8> lod = renderPath(
        renderer, scene, path, runSettings(width, height, true, lodErrorPixels, factor), stats);
    std::vector<uint32_t> drawn(scene.objects.size(), kNoLevel);
    double mostStandingOut = -1.0;
    for (size_t i = 0; i < lod.size(); ++i) {
      std::vector<uint32_t> before = drawn;
      LodPoppingFrame frame;
      frame.triangles =
          chooseModelLevels(model, path.cameras[i], width, height, lodErrorPixels, factor, drawn);
      for (size_t object = 0; object < drawn.size(); ++object)
        frame.switches += i > 0 && drawn[object] != before[object];
      frame.stepOff = stepOff[i];
      if (i > 0) {
        frame.stepLod = flipError(lod[i - 1], lod[i]).mean;
        for (size_t pixel = 0; pixel < lod[i].pixels.size() / 4; ++pixel)
          frame.poppedPixels += popped(lod[i - 1], off[i - 1], lod[i], off[i], pixel);
      }
      frame.errorAgainstOff = flipError(off[i], lod[i]).mean;
      double standingOut = double(frame.poppedPixels);
      if (frame.switches > 0 && standingOut > mostStandingOut) {
        mostStandingOut = standingOut;
        run.shownFrame = uint32_t(i);
      }
      run.frames.push_back(frame);
    }
    run.rendererTriangles = stats.triangles;
    run.modelAgrees = !run.frames.empty() && run.frames.back().triangles == stats.triangles;
    if (mostStandingOut >= 0.0) {
      run.shownBefore = lod[run.shownFrame - 1];
      run.shownAfter = lod[run.shownFrame];
      run.offBefore = off[run.shownFrame - 1];
      run.offAfter = off[run.shownFrame];
    }
    runs.push_back(std::move(run));
  }
  return runs;
}

}  // namespace shadelab
