#pragma once
// Bump mapping against real geometry, measured: the `bump` scene's sphere
// with its height map (dimples) drawn bump-mapped, beside the same height
// field applied as real displacement to a finely tessellated sphere. Bump
// mapping changes only normals, so its outline stays the plain sphere's
// circle; the displaced sphere's outline is notched by the dimples.
#include <cstdint>

#include "core/base/image.h"
#include "core/scene/scene.h"
#include "passes/renderer.h"

namespace shadelab {

// The `bump` scene with only its sphere, against the background.
Scene bumpSphereScene();
// The displacement amplitude (world units) that gives the same slopes as the
// bump map at the equator: bump_scale times one texel's length there.
float bumpDisplacementAmplitude(const Scene& bumpSphere);
// The sphere as geometry: `slices` x slices / 2 vertices moved along their
// normals by amplitude (h - 1) (dimples cut in, the flat part stays on the
// sphere), h sampled from the height map at level 0, bilinear, as the
// vertex's st; normals recomputed from the moved triangles; no height map.
Scene displacedSphereScene(const Scene& bumpSphere, uint32_t slices);

struct BumpSilhouetteMeasurement {
  uint32_t slices = 0;
  uint64_t triangles = 0;
  uint64_t coveredBump = 0;           // pixels showing the bump-mapped sphere
  uint64_t coveredDisplaced = 0;      // pixels showing the displaced sphere
  uint64_t coveredPlain = 0;          // pixels showing the plain sphere (no map)
  uint64_t silhouetteDifference = 0;  // covered by exactly one of bump and displaced
  uint64_t bumpVersusPlain = 0;       // covered by exactly one of bump and plain
  double interiorFlip = 0.0;          // mean FLIP over pixels both cover
  ImageRgba bump, displaced;
};

BumpSilhouetteMeasurement measureBumpSilhouette(Renderer& renderer, uint32_t slices, uint32_t width,
                                                uint32_t height);

}  // namespace shadelab
