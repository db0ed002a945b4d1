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
  uint64_t coveredPixels = 0;  // showing either plane
  uint64_t wrongPixels = 0;    // showing the farther plane
  double wrongFraction() const {
    return coveredPixels ? double(wrongPixels) / double(coveredPixels) : 0.0;
  }
};

// Which plane an unlit render of the zfight scene shows at pixel p.
enum class ZFightPixel { Background, NearPlane, FarPlane };
ZFightPixel classifyZFightPixel(const ImageRgba& image, size_t p);

// Renders twice, the far plane drawn first and then last: a depth tie keeps
// the first plane under LESS but the second under GREATER_OR_EQUAL, so one
// order alone would flatter one of the compare ops. A pixel is wrong where
// the farther plane shows in either order.
ZFightMeasurement measureZFight(Renderer& renderer, DepthMode depth, Projection projection,
                                float near, uint32_t width, uint32_t height);

// Every depth mode x {perspective, orthographic} x near plane; `progress`
// receives one line per measurement.
std::vector<ZFightMeasurement> runZFightSweep(
    Renderer& renderer, const std::vector<float>& nearPlanes, uint32_t width, uint32_t height,
    const std::function<void(const std::string&)>& progress);

std::string zfightCsv(const std::vector<ZFightMeasurement>& measurements, uint32_t width,
                      uint32_t height);
// Wrong-pixel fraction against the near plane, one line per depth mode; a
// panel per projection.
ImageU8 zfightChart(const std::vector<ZFightMeasurement>& measurements);

}  // namespace shadelab
