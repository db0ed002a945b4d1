#include "measure/highlight.h"

#include <algorithm>

namespace shadelab {

float peakLuminance(const ImageRgba& image) {
  float peak = 0.0f;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      const glm::vec4 c = image.at(x, y);
      peak = std::max(peak, 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b);
    }
  return peak;
}

HighlightMeasurement measureHighlight(Renderer& renderer, uint32_t quadsPerSide, uint32_t width,
                                      uint32_t height) {
  const Scene scene = highlightScene(quadsPerSide);
  HighlightMeasurement result;
  result.quadsPerSide = quadsPerSide;
  result.triangles = scene.triangleCount();
  result.gouraud = renderer.renderToImage(scene, {width, height, ShadingModel::Gouraud}).image;
  result.gouraudPeak = peakLuminance(result.gouraud);
  result.phongPeak =
      peakLuminance(renderer.renderToImage(scene, {width, height, ShadingModel::Phong}).image);
  return result;
}

}  // namespace shadelab
