#pragma once
// Shadow acne measured: a floor and a sphere under a low light, traced with
// and without shadow rays at an epsilon (TraceSettings::epsilon), each pixel
// compared with the exact answer of whether its point is lit. Too small an
// epsilon lets a shadow ray hit the surface it starts on (acne: lit points
// shadowed); the CPU tracer alone, no device.
#include <cstdint>

#include "core/base/image.h"
#include "core/scene/scene.h"

namespace shadelab {

// A floor (y = -0.7, moved there by its transform as in most scenes) and a
// unit sphere on it, lit by a directional light 30 degrees above the horizon:
// the low angle that makes acne easy to get.
Scene acneScene();

struct AcneMeasurement {
  float epsilon = 0.0f;
  uint64_t litPixels = 0;       // lit in exact arithmetic (away from shadow boundaries)
  uint64_t acnePixels = 0;      // of those, darker with shadow rays than without
  uint64_t acneOnSphere = 0;    // of those, on the sphere
  uint64_t shadowedPixels = 0;  // in the sphere's shadow or facing away, exactly
  uint64_t leakingPixels = 0;   // of those, lit with shadow rays (the offset jumped past)
  ImageRgba image;              // the traced image with shadows
  double acneFraction() const { return litPixels ? double(acnePixels) / double(litPixels) : 0.0; }
  double leakFraction() const {
    return shadowedPixels ? double(leakingPixels) / double(shadowedPixels) : 0.0;
  }
};

// One sample per pixel centre, local shading only (depth 0).
AcneMeasurement measureAcne(const Scene& scene, float epsilon, uint32_t width, uint32_t height);

}  // namespace shadelab
