#pragma once
// References the rasterised settings are measured against, by name: what
// `compare`, `bench` and `render --quality` compare with. `trace` is the CPU
// Whitted ray tracer (core/trace/raytracer.h) at 4 samples per pixel; `raster` is
// Phong at 4x tessellation with 4x MSAA.
#include <functional>
#include <string>
#include <vector>

#include "core/base/image.h"
#include "core/scene/scene.h"
#include "passes/renderer.h"

namespace shadelab {

struct Reference {
  std::string name;
  std::string description;
  std::function<ImageRgba(Renderer&, const Scene&, uint32_t width, uint32_t height)> render;
};

// Throws InputError naming `option` and the references that exist.
// `alsoAccepted`: a name the caller handles itself, listed first in the
// message (bench's none).
const Reference& findReference(const std::string& name, const std::string& option,
                               const std::string& alsoAccepted = {});

// The ray tracer as a reference with other settings than the table's `trace`
// (samplesPerPixel must be a square; see checkSamplesPerPixel).
Reference traceReference(uint32_t samplesPerPixel, bool shadows);
// Phong at 4x tessellation with 4x MSAA, with render's default shadow maps
// (the table's `raster`) or none.
Reference rasterReference(bool shadows);

}  // namespace shadelab
