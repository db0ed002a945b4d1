#pragma once
// The billboard pass's known failures, measured with an opaque white quad
// (unlit, a 4x4 white texture, so every covered pixel is white):
//   coverage: a cylindrical billboard turns about its axis only, so as the
//   eye rises towards the axis the quad goes edge-on, where a spherical one
//   keeps facing the eye. Seen in orthographic projection the quad's area in
//   pixels is exactly w h cos(elevation) (cylindrical) and w h (spherical).
//   ground cut: quads are built in eye space with real depth, so a billboard
//   sunk into the ground is cut by it along the straight line where the
//   quad's plane meets y = 0, projected. A spherical quad leans back as the
//   eye rises (it faces the eye), so a sunk one sinks further out of sight.
#include <cstdint>

#include "core/base/image.h"
#include "passes/renderer.h"

namespace shadelab {

struct BillboardCoverage {
  uint64_t covered = 0;   // white pixels
  double expected = 0.0;  // the quad's projected area in pixels
  double fullArea = 0.0;  // the same seen face-on (w h in pixels)
  ImageU8 image;
};
// A 2 x 3 quad at the origin seen from `elevationDegrees` (0: level, 90:
// straight down its axis), orthographic, 30 pixels a unit at 180 rows.
BillboardCoverage measureBillboardCoverage(Renderer& renderer, BillboardKind kind,
                                           float elevationDegrees, uint32_t width, uint32_t height);

struct BillboardGroundCut {
  uint32_t columns = 0;       // columns where the quad shows above the ground
  double meanRowError = 0.0;  // |measured cut - expected cut|, pixels, over `columns`
  double maxRowError = 0.0;
  double maxLineResidual = 0.0;  // the measured cut against its own least-squares line
  double bottomEdgeGap = 0.0;    // mean rows between the quad's own bottom edge and the cut
  uint64_t visible = 0;          // white pixels with the ground
  uint64_t unhidden = 0;         // white pixels without it (the whole quad)
  double cutHeight = 0.0;        // where the ground meets the quad: 0 bottom edge, 1 top
  ImageU8 image;                 // with the expected cut line drawn in red
  double visibleShare() const { return unhidden ? double(visible) / double(unhidden) : 0.0; }
};
// A 2 x 2 quad anchored at its centre `sink` below a ground plane (y = 0),
// near the origin, seen in perspective from `elevationDegrees` above the
// origin, 6 units away.
BillboardGroundCut measureGroundCut(Renderer& renderer, BillboardKind kind, float elevationDegrees,
                                    float sink, uint32_t width, uint32_t height);

}  // namespace shadelab
