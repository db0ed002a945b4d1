#include "measure/impostor_parallax.h"

#include <algorithm>
#include <cmath>

#include "core/metrics/metrics.h"
#include "core/scene/impostor.h"
#include "core/scene/lod.h"
#include "core/scene/shape.h"

namespace shadelab {
namespace {

constexpr float kFovy = 30.0f;

// Eye to the teapot's centre: where its radius covers half a cell's texels
// in pixels, so the atlas is seen one texel a pixel, as the bound allows it
// to be drawn at the most, and the outline error is the parallax's.
float viewDistance(float radius, uint32_t height) {
  float radiusPixels = 0.5f * float(kImpostorCellTexels);
  return radius * float(height) / (2.0f * std::tan(glm::radians(0.5f * kFovy)) * radiusPixels);
}

struct Teapot {
  Scene scene;
  glm::vec3 centre;
  float radius;
};

// The teapot and the sphere addImpostors captures it around.
Teapot teapotScene() {
  Teapot teapot;
  Scene& scene = teapot.scene;
  scene.name = "impostor-parallax";
  scene.background = glm::vec3(0.0f);
  scene.ambient = glm::vec3(0.25f);
  Light light;
  light.type = LightType::Directional;
  light.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.6f));
  light.shadows = false;
  scene.lights.push_back(light);
  ShapeDesc shape;
  shape.kind = ShapeKind::Teapot;
  shape.tessellation = 12;
  Object object;
  object.name = "teapot";
  object.mesh = scene.addShape(shape);
  object.material.kd = glm::vec3(0.8f, 0.45f, 0.3f);
  object.material.ks = glm::vec3(0.5f);
  object.material.shininess = 48.0f;
  scene.objects.push_back(object);
  ImpostorSphere sphere = impostorSphere(scene.meshes[0]);
  teapot.centre = sphere.centre;
  teapot.radius = sphere.radius;
  return teapot;
}

// Views spread over azimuth (a golden-angle step, so none lines up with the
// cells) and elevation (-30 to 75 degrees).
std::vector<Camera> viewsAround(glm::vec3 centre, float distance, uint32_t views) {
  std::vector<Camera> cameras;
  for (uint32_t i = 0; i < views; ++i) {
    float azimuth = glm::radians(137.508f * float(i) + 11.0f);
    float elevation = glm::radians(-30.0f + 105.0f * (float(i) + 0.5f) / float(views));
    Camera camera;
    camera.at = centre;
    camera.eye =
        centre + distance * glm::vec3(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                                      std::cos(elevation) * std::cos(azimuth));
    camera.fovyDegrees = kFovy;
    camera.near = 0.5f * distance;
    camera.far = 2.0f * distance;
    cameras.push_back(camera);
  }
  return cameras;
}

std::vector<ImageU8> renderViews(Renderer& renderer, const Scene& scene,
                                 const FrameSettings& settings, const std::vector<Camera>& cameras,
                                 uint32_t& impostorFrames) {
  std::vector<ImageU8> images(cameras.size());
  impostorFrames = 0;
  RenderStats stats = renderer.renderSequence(
      scene, settings, cameras,
      [&](uint32_t frame, ImageRgba&& image) { images[frame] = encodeSrgb8(image); });
  impostorFrames = stats.impostors;  // the last frame's
  return images;
}

bool covered(glm::u8vec4 pixel) {
  return pixel.r > 127;
}

// Pixels covered in exactly one image, and the outline of `full` (covered
// pixels with an uncovered 4-neighbour).
double outlineDistance(const ImageU8& full, const ImageU8& impostor) {
  uint64_t disagree = 0, outline = 0;
  for (uint32_t y = 0; y < full.height; ++y)
    for (uint32_t x = 0; x < full.width; ++x) {
      bool inside = covered(full.at(x, y));
      disagree += inside != covered(impostor.at(x, y));
      if (!inside) continue;
      bool edge = x == 0 || y == 0 || x + 1 == full.width || y + 1 == full.height ||
                  !covered(full.at(x - 1, y)) || !covered(full.at(x + 1, y)) ||
                  !covered(full.at(x, y - 1)) || !covered(full.at(x, y + 1));
      outline += edge;
    }
  return outline ? double(disagree) / double(outline) : 0.0;
}

// The square of side 2 cells' texels about the image's centre (the teapot
// and a margin of its radius around it): what FLIP compares, so the empty
// background does not dilute the mean.
ImageU8 aroundTheTeapot(const ImageU8& image) {
  uint32_t side = std::min({2 * kImpostorCellTexels, image.width, image.height});
  uint32_t left = (image.width - side) / 2, top = (image.height - side) / 2;
  ImageU8 out(side, side);
  for (uint32_t y = 0; y < side; ++y)
    for (uint32_t x = 0; x < side; ++x) out.set(x, y, image.at(left + x, top + y));
  return out;
}

// Two crops side by side, each pixel drawn `zoom` x `zoom`.
ImageU8 sideBySide(const ImageU8& left, const ImageU8& right, uint32_t zoom) {
  ImageU8 out((left.width + right.width) * zoom, left.height * zoom);
  for (uint32_t y = 0; y < out.height; ++y)
    for (uint32_t x = 0; x < out.width; ++x) {
      uint32_t sx = x / zoom, sy = y / zoom;
      out.set(x, y, sx < left.width ? left.at(sx, sy) : right.at(sx - left.width, sy));
    }
  return out;
}

}  // namespace

std::vector<ImpostorParallax> measureImpostorParallax(Renderer& renderer,
                                                      const std::vector<uint32_t>& cellCounts,
                                                      uint32_t views, uint32_t width,
                                                      uint32_t height, bool blend) {
  Teapot teapot = teapotScene();
  float distance = viewDistance(teapot.radius, height);
  std::vector<Camera> cameras = viewsAround(teapot.centre, distance, std::max(1u, views));
  FrameSettings settings;
  settings.width = width;
  settings.height = height;
  settings.shadows = ShadowMethod::Off;
  settings.environment = false;
  uint32_t ignored = 0;
  settings.shadingModel = ShadingModel::Unlit;
  Scene white = teapot.scene;
  white.objects[0].material.kd = glm::vec3(1.0f);
  std::vector<ImageU8> fullMasks = renderViews(renderer, white, settings, cameras, ignored);
  settings.shadingModel = ShadingModel::Phong;
  std::vector<ImageU8> fullShaded = renderViews(renderer, teapot.scene, settings, cameras, ignored);

  ViewSize view{cameras[0], width, height};
  double pixelsPerUnitAtCentre = pixelsPerUnit(view, distance);
  std::vector<ImpostorParallax> results;
  for (uint32_t cells : cellCounts) {
    ImpostorParallax result;
    result.cells = cells;
    result.blend = blend;
    result.views = uint32_t(cameras.size());
    float angle = blend ? impostorBlendAngle(cells) : impostorParallaxAngle(cells);
    result.angleDegrees = glm::degrees(double(angle));
    result.boundPixels =
        double(impostorError(teapot.radius, cells, kImpostorCellTexels)) * pixelsPerUnitAtCentre;
    result.parallaxBoundPixels =
        double(teapot.radius) * std::sin(double(angle)) * pixelsPerUnitAtCentre;
    FrameSettings lod = settings;
    lod.lod = true;
    lod.lodErrorPixels = 100.0f;  // the impostor's error is far below: always chosen
    lod.impostorCells = cells;
    lod.impostorBlend = blend;
    uint32_t maskImpostors = 0, shadedImpostors = 0;
    lod.shadingModel = ShadingModel::Unlit;
    std::vector<ImageU8> masks = renderViews(renderer, white, lod, cameras, maskImpostors);
    lod.shadingModel = ShadingModel::Phong;
    std::vector<ImageU8> shaded =
        renderViews(renderer, teapot.scene, lod, cameras, shadedImpostors);
    result.allImpostors = maskImpostors == 1 && shadedImpostors == 1;
    size_t worst = 0;
    for (size_t v = 0; v < cameras.size(); ++v) {
      double distance = outlineDistance(fullMasks[v], masks[v]);
      result.meanOutlinePixels += distance / double(cameras.size());
      if (distance > result.maxOutlinePixels) {
        result.maxOutlinePixels = distance;
        worst = v;
      }
      result.meanFlip +=
          flipError(aroundTheTeapot(fullShaded[v]), aroundTheTeapot(shaded[v])).mean /
          double(cameras.size());
    }
    result.worstPair =
        sideBySide(aroundTheTeapot(fullShaded[worst]), aroundTheTeapot(shaded[worst]), 4);
    results.push_back(std::move(result));
  }
  return results;
}

}  // namespace shadelab
