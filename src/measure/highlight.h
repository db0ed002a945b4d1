#pragma once
// Gouraud losing a highlight, measured: the `highlight` scene's plane, whose
// highlight falls inside one of two large triangles, cut into N x N quads
// and drawn in Gouraud and Phong; the brightest pixel of each. Gouraud
// evaluates the equation only at vertices, so its peak comes back only when
// a vertex lands near the highlight.
#include <cstdint>

#include "core/base/image.h"
#include "passes/renderer.h"

namespace shadelab {

// Rec. 709 luma of linear RGB; the brightest pixel's.
float peakLuminance(const ImageRgba& image);

struct HighlightMeasurement {
  uint32_t quadsPerSide = 1;
  uint64_t triangles = 0;
  float gouraudPeak = 0.0f;
  float phongPeak = 0.0f;
  ImageRgba gouraud;  // the Gouraud render
  double ratio() const { return phongPeak > 0.0f ? double(gouraudPeak) / phongPeak : 0.0; }
};

HighlightMeasurement measureHighlight(Renderer& renderer, uint32_t quadsPerSide, uint32_t width,
                                      uint32_t height);

}  // namespace shadelab
