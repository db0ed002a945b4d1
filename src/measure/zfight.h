#pragma once
// Z-fighting measured: the `zfight` scene's two parallel planes drawn with a
// depth mode, projection and near plane, and the fraction of the pixels they
// cover where the farther plane wins. Like the benchmark, a measurement that
// drives the renderer, not a pass.
#include <functional>
#include <string>
#include <vector>

#include "core/base/image.h"
#include "core/scene/scene.h"
#include "core/vulkan/depth.h"
#include "passes/renderer.h"

namespace shadelab {

struct ZFightMeasurement {
  DepthMode depth = DepthMode::D32F;
  Projection projection = Projection::Perspective;
  float near = 0.1f;
  float distanceScale = 1.0f;  // see zfightSceneAt
  uint64_t coveredPixels = 0;  // showing either plane
  uint64_t wrongPixels = 0;    // showing the farther plane
  double wrongFraction() const {
    return coveredPixels ? double(wrongPixels) / double(coveredPixels) : 0.0;
  }
};

// Which plane an unlit render of the zfight scene shows at pixel p.
enum class ZFightPixel { Background, NearPlane, FarPlane };
ZFightPixel classifyZFightPixel(const ImageRgba& image, size_t p);

// The zfight scene with the planes `distanceScale` times as far away: the
// eye moves along its line of sight and the planes (and an orthographic
// window) grow by the same factor, so the image keeps its framing and only the
// distance changes; the planes' gap stays kZFightGap.
Scene zfightSceneAt(Projection projection, float near, float distanceScale);
// Distance from the eye to the planes' centre in that scene.
double zfightDistance(float distanceScale);

// Renders twice, the far plane drawn first and then last: a depth tie keeps
// the first plane under LESS but the second under GREATER_OR_EQUAL, so one
// order alone would flatter one of the compare ops. A pixel is wrong where
// the farther plane shows in either order.
ZFightMeasurement measureZFight(Renderer& renderer, DepthMode depth, Projection projection,
                                float near, uint32_t width, uint32_t height,
                                float distanceScale = 1.0f);

// Every depth mode x {perspective, orthographic} x (near plane, distance
// scale) pair; `progress` receives one line per measurement.
struct ZFightSetting {
  float near = 0.1f;
  float distanceScale = 1.0f;
};
std::vector<ZFightMeasurement> runZFightSweep(
    Renderer& renderer, const std::vector<ZFightSetting>& settings, uint32_t width, uint32_t height,
    const std::function<void(const std::string&)>& progress);

std::string zfightCsv(const std::vector<ZFightMeasurement>& measurements, uint32_t width,
                      uint32_t height);
// Wrong-pixel fraction against the near plane (x = near) or the distance
// (x = distance to the planes' centre), one line per depth mode; a panel per
// projection.
enum class ZFightAxis { Near, Distance };
ImageU8 zfightChart(const std::vector<ZFightMeasurement>& measurements, ZFightAxis axis);

}  // namespace shadelab
