#pragma once
// Textures as the ray tracer samples them: each scene texture decoded to
// linear float (sRGB colour textures through the sRGB curve, data textures
// as value / 255, as the device's _SRGB and _UNORM formats do) with a mip
// chain made the way passes/mip_generation makes it (each level a linear
// blit of the one above: a bilinear tap at every smaller texel's centre, in
// linear light). Lookups are trilinear at a level of detail the caller
// computes from the ray's footprint, with the sampler's wrap modes. When
// minifying, the sampler's filter is what the rasteriser is measured on, so
// the reference ignores it and always filters by area; when magnifying, a
// nearest sampler gives the texel the point falls in (hard texels, as the
// author asked for them), every other the bilinear blend.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "core/scene/scene.h"

namespace shadelab {

class TraceTexture {
 public:
  explicit TraceTexture(const Texture& texture);
  // `st` as the shaders take it (t = 0 at the top row); `lod` as
  // textureQueryLod reports it: log2 of the footprint in level-0 texels.
  glm::vec4 sample(glm::vec2 st, float lod, const SamplerDesc& sampler) const;
  glm::uvec2 size() const { return {levels_[0].width, levels_[0].height}; }
  uint32_t levelCount() const { return uint32_t(levels_.size()); }

 private:
  struct Level {
    uint32_t width = 0, height = 0;
    std::vector<glm::vec4> texels;
  };
  glm::vec4 bilinear(const Level& level, glm::vec2 st, const SamplerDesc& sampler) const;
  glm::vec4 nearest(const Level& level, glm::vec2 st, const SamplerDesc& sampler) const;
  std::vector<Level> levels_;
};

// Wraps integer texel coordinate `i` into 0..size-1 (Vulkan's repeat,
// mirrored repeat and clamp-to-edge address modes).
int32_t wrapTexel(int32_t i, int32_t size, TextureWrap wrap);

}  // namespace shadelab
