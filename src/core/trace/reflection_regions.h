#pragma once
// Where environment mapping must fail, found by tracing: each pixel whose
// surface reflects or transmits (kr or kt > 0) is classified by the path
// environment mapping assumes escapes to infinity. The mirror ray (or, when
// kt > kr, the refracted ray, followed through its own object) either
// escapes, and env(R) is right up to distortion (the cube is looked up from
// the scene's centre, not the surface point: parallax), or it hits an
// object, possibly the same one (self-reflection), which no environment map
// shows. `compare` splits FLIP by these regions.
#include <cstdint>
#include <vector>

#include "core/base/image.h"
#include "core/metrics/metrics.h"
#include "core/scene/scene.h"

namespace shadelab {

enum class ReflectionRegion : uint8_t {
  None,        // a miss, or a surface with kr = kt = 0
  Escapes,     // the specular path leaves the scene
  HitsObject,  // the specular path meets an object: inter- or self-reflection
};

struct ReflectionRegions {
  uint32_t width = 0, height = 0;
  std::vector<ReflectionRegion> pixels;  // row-major, row 0 at the top
  uint64_t count(ReflectionRegion region) const;
};

// One camera ray per pixel centre, as the rasteriser samples.
ReflectionRegions classifyReflections(const Scene& scene, uint32_t width, uint32_t height);

// The mean of `map` over the pixels in `region` (0 when there are none).
double meanOver(const MetricMap& map, const ReflectionRegions& regions, ReflectionRegion region);

// The regions as a picture: escaping paths blue, paths that hit an object
// orange, the rest dark.
ImageU8 regionImage(const ReflectionRegions& regions);

}  // namespace shadelab
