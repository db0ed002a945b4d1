#include "core/trace/trace_textures.h"

#include <algorithm>
#include <cmath>

#include "core/base/image.h"
#include "core/scene/texture.h"

namespace shadelab {

int32_t wrapTexel(int32_t i, int32_t size, TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::Repeat:
      return ((i % size) + size) % size;
    case TextureWrap::MirroredRepeat: {
      const int32_t period = 2 * size;
      const int32_t m = ((i % period) + period) % period;
      return m < size ? m : period - 1 - m;
    }
    case TextureWrap::ClampToEdge:
      return std::clamp(i, 0, size - 1);
  }
  return 0;
}

namespace {
// A float texel coordinate as an integer the wrap can take: far outside
// 0..1 (a huge uv scale) floats lose their fraction anyway.
int32_t texelIndex(float coordinate) {
  return int32_t(std::clamp(coordinate, -1e9f, 1e9f));
}
}  // namespace

TraceTexture::TraceTexture(const Texture& texture) {
  Level base{texture.width, texture.height, {}};
  base.texels.resize(size_t(texture.width) * texture.height);
  for (size_t i = 0; i < base.texels.size(); ++i) {
    glm::vec4 texel;
    for (int c = 0; c < 4; ++c) {
      const float value = float(texture.rgba8[4 * i + size_t(c)]) / 255.0f;
      texel[c] = texture.srgb && c < 3 ? srgbToLinear(value) : value;
    }
    base.texels[i] = texel;
  }
  levels_.push_back(std::move(base));
  const SamplerDesc clamp{TextureWrap::ClampToEdge, TextureWrap::ClampToEdge};
  for (uint32_t l = 1; l < mipLevelCount(texture.width, texture.height); ++l) {
    const glm::uvec2 size = mipLevelSize(texture.width, texture.height, l);
    Level level{size.x, size.y, std::vector<glm::vec4>(size_t(size.x) * size.y)};
    for (uint32_t y = 0; y < size.y; ++y)
      for (uint32_t x = 0; x < size.x; ++x)
        level.texels[size_t(y) * size.x + x] =
            bilinear(levels_.back(), (glm::vec2(x, y) + 0.5f) / glm::vec2(size), clamp);
    levels_.push_back(std::move(level));
  }
}

glm::vec4 TraceTexture::bilinear(const Level& level, glm::vec2 st,
                                 const SamplerDesc& sampler) const {
  const int32_t w = int32_t(level.width), h = int32_t(level.height);
  const float x = st.x * float(w) - 0.5f, y = st.y * float(h) - 0.5f;
  const float x0 = std::floor(x), y0 = std::floor(y);
  const float fx = x - x0, fy = y - y0;
  auto texel = [&](int32_t tx, int32_t ty) {
    tx = wrapTexel(tx, w, sampler.wrapU);
    ty = wrapTexel(ty, h, sampler.wrapV);
    return level.texels[size_t(ty) * level.width + size_t(tx)];
  };
  const int32_t ix = texelIndex(x0), iy = texelIndex(y0);
  const glm::vec4 top = glm::mix(texel(ix, iy), texel(ix + 1, iy), fx);
  const glm::vec4 bottom = glm::mix(texel(ix, iy + 1), texel(ix + 1, iy + 1), fx);
  return glm::mix(top, bottom, fy);
}

glm::vec4 TraceTexture::nearest(const Level& level, glm::vec2 st,
                                const SamplerDesc& sampler) const {
  const int32_t w = int32_t(level.width), h = int32_t(level.height);
  const int32_t x = texelIndex(std::floor(st.x * float(w)));
  const int32_t y = texelIndex(std::floor(st.y * float(h)));
  return level.texels[size_t(wrapTexel(y, h, sampler.wrapV)) * level.width +
                      size_t(wrapTexel(x, w, sampler.wrapU))];
}

glm::vec4 TraceTexture::sample(glm::vec2 st, float lod, const SamplerDesc& sampler) const {
  // A coordinate that is not finite (a hostile texture transform's inf x 0
  // or overflow) has no texel: the first, not a NaN colour or an undefined
  // float-to-int conversion.
  if (!std::isfinite(st.x)) st.x = 0.0f;
  if (!std::isfinite(st.y)) st.y = 0.0f;
  // A nearest sampler magnifying shows the texel the point falls in: the
  // author's hard texels (pixel art), as the rasteriser draws them.
  if (sampler.filter == TextureFilter::Nearest && !(lod > 0.0f))
    return nearest(levels_[0], st, sampler);
  const float maxLevel = float(levels_.size() - 1);
  const float level = std::isnan(lod) ? 0.0f : std::clamp(lod, 0.0f, maxLevel);
  const uint32_t low = uint32_t(level);
  const uint32_t high = std::min<uint32_t>(low + 1, uint32_t(levels_.size() - 1));
  const glm::vec4 a = bilinear(levels_[low], st, sampler);
  if (high == low) return a;
  return glm::mix(a, bilinear(levels_[high], st, sampler), level - float(low));
}

}  // namespace shadelab
