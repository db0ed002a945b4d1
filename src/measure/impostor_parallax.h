#pragma once
// How far an impostor strays from the mesh it stands for, against the atlas's
// cells per side (the octahedral impostor's "re-render threshold": a view is
// shown as captured from the nearest cell, up to impostorParallaxAngle away,
// or from the three around it blended, impostorBlendAngle on average).
// One teapot seen from views spread over azimuth and elevation, each drawn in
// full and as its impostor (--lod auto at a bound that always picks it):
// unlit white on black for the silhouettes, Phong for FLIP.
#include <cstdint>
#include <vector>

#include "core/base/image.h"
#include "passes/renderer.h"

namespace shadelab {

struct ImpostorParallax {
  uint32_t cells = 0;
  bool blend = false;                // FrameSettings::impostorBlend
  double angleDegrees = 0.0;         // impostorParallaxAngle(cells), or impostorBlendAngle
  double boundPixels = 0.0;          // impostorError projected at the teapot's centre
  double parallaxBoundPixels = 0.0;  // its parallax part alone (radius sin(angle))
  // The silhouettes' disagreement (pixels covered by one image and not the
  // other) over the full mesh's outline length in pixels: the mean distance
  // between the outlines. Mean and largest over the views.
  double meanOutlinePixels = 0.0;
  double maxOutlinePixels = 0.0;
  double meanFlip = 0.0;  // Phong images about the teapot (2 cells' texels square), mean over views
  uint32_t views = 0;
  bool allImpostors = false;  // every impostor frame drew the teapot as its impostor
  ImageU8 worstPair;  // full mesh | impostor about the teapot, 4x, the largest outline error's view
};

// `views` views (at least 1) of the teapot, its radius half a cell's texels
// in pixels (the atlas seen one texel a pixel) at width x height, for each
// entry of `cellCounts`, the impostors drawn from the nearest cell or
// (`blend`) the three around the view.
std::vector<ImpostorParallax> measureImpostorParallax(Renderer& renderer,
                                                      const std::vector<uint32_t>& cellCounts,
                                                      uint32_t views, uint32_t width,
                                                      uint32_t height, bool blend = false);

}  // namespace shadelab
