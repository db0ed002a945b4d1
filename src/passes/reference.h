#pragma once
// References the rasterised settings are measured against, by name: what
// `compare`, `bench` and `render --quality` compare with. `raster` is Phong
// at 4x tessellation with 4x MSAA; the ray tracer joins as `trace`.
#include <functional>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/scene.h"
#include "passes/renderer.h"

namespace shadelab {

struct Reference {
  std::string name;
  std::string description;
  std::function<ImageRgba(Renderer&, const Scene&, uint32_t width, uint32_t height)> render;
};

// Throws InputError naming `option` and the references that exist.
const Reference& findReference(const std::string& name, const std::string& option);

}  // namespace shadelab
