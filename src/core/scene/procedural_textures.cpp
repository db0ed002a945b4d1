#include "core/scene/procedural_textures.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

#include "core/base/image.h"

namespace shadelab {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

float fract(float x) {
  return x - std::floor(x);
}

float smoothstep(float edge0, float edge1, float x) {
  float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// u and v count cells (one period per unit); v runs down the rows here.
float patternHeight(HeightPattern pattern, float u, float v) {
  switch (pattern) {
    case HeightPattern::Checker:
      return (int64_t(std::floor(u)) + int64_t(std::floor(v))) % 2 == 0 ? 1.0f : 0.0f;
    case HeightPattern::Bricks: {
      // Bricks twice as long as high; odd rows offset by half a brick.
      float row = std::floor(v);
      float along = u * 0.5f + (int64_t(row) % 2 ? 0.5f : 0.0f);
      float edgeU = std::min(fract(along), 1.0f - fract(along)) * 2.0f;  // in brick heights
      float edgeV = std::min(fract(v), 1.0f - fract(v));
      return smoothstep(0.04f, 0.12f, std::min(edgeU, edgeV));
    }
    case HeightPattern::Dimples: {
      float du = fract(u) - 0.5f, dv = fract(v) - 0.5f;
      float r = std::sqrt(du * du + dv * dv) / 0.4f;  // dimple radius 0.4 cells
      return r < 1.0f ? 0.5f - 0.5f * std::cos(kPi * r) : 1.0f;
    }
    case HeightPattern::Waves:
      return 0.5f + 0.25f * (std::sin(2.0f * kPi * u) + std::sin(2.0f * kPi * v));
  }
  return 0.0f;
}

uint8_t unorm8(float value) {
  return uint8_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
}

Texture emptyTexture(const HeightField& field, const std::string& name, bool srgb) {
  Texture texture;
  texture.name = name;
  texture.width = field.width;
  texture.height = field.height;
  texture.srgb = srgb;
  texture.rgba8.resize(size_t(field.width) * field.height * 4);
  return texture;
}

}  // namespace

float HeightField::at(int32_t x, int32_t y) const {
  int32_t w = int32_t(width), h = int32_t(height);
  x = ((x % w) + w) % w;
  y = ((y % h) + h) % h;
  return values[size_t(y) * width + size_t(x)];
}

HeightField proceduralHeight(const ProceduralTexture& desc) {
  assert(desc.size >= 1 && desc.repeats >= 1);
  HeightField field{desc.size, desc.size, std::vector<float>(size_t(desc.size) * desc.size)};
  float cellsPerTexel = float(desc.repeats) / float(desc.size);
  for (uint32_t y = 0; y < desc.size; ++y)
    for (uint32_t x = 0; x < desc.size; ++x)
      field.values[size_t(y) * desc.size + x] = patternHeight(
          desc.pattern, (float(x) + 0.5f) * cellsPerTexel, (float(y) + 0.5f) * cellsPerTexel);
  return field;
}

glm::vec3 heightFieldNormal(const HeightField& field, int32_t x, int32_t y, float depth) {
  float dhdu = 0.5f * (field.at(x + 1, y) - field.at(x - 1, y));
  float dhdv = 0.5f * (field.at(x, y - 1) - field.at(x, y + 1));  // v runs up, toward row 0
  return glm::normalize(glm::vec3(-depth * dhdu, -depth * dhdv, 1.0f));
}

Texture heightColorTexture(const HeightField& field, glm::vec3 low, glm::vec3 high,
                           const std::string& name) {
  Texture texture = emptyTexture(field, name, true);
  for (size_t p = 0; p < field.values.size(); ++p) {
    glm::vec3 color = glm::mix(low, high, field.values[p]);
    for (int c = 0; c < 3; ++c) texture.rgba8[p * 4 + c] = unorm8(linearToSrgb(color[c]));
    texture.rgba8[p * 4 + 3] = 255;
  }
  return texture;
}

Texture heightMapTexture(const HeightField& field, const std::string& name) {
  Texture texture = emptyTexture(field, name, false);
  for (size_t p = 0; p < field.values.size(); ++p) {
    uint8_t value = unorm8(field.values[p]);
    for (int c = 0; c < 3; ++c) texture.rgba8[p * 4 + c] = value;
    texture.rgba8[p * 4 + 3] = 255;
  }
  return texture;
}

Texture normalMapTexture(const HeightField& field, float depth, const std::string& name) {
  Texture texture = emptyTexture(field, name, false);
  for (uint32_t y = 0; y < field.height; ++y)
    for (uint32_t x = 0; x < field.width; ++x) {
      glm::vec3 n = heightFieldNormal(field, int32_t(x), int32_t(y), depth);
      size_t p = size_t(y) * field.width + x;
      for (int c = 0; c < 3; ++c) texture.rgba8[p * 4 + c] = unorm8(n[c] * 0.5f + 0.5f);
      texture.rgba8[p * 4 + 3] = 255;
    }
  return texture;
}

Texture treeTexture(uint32_t size, const std::string& name) {
  assert(size > 0);
  Texture texture;
  texture.name = name;
  texture.width = texture.height = size;
  texture.srgb = true;
  texture.rgba8.assign(size_t(size) * size * 4, 0);
  const glm::vec3 trunk{0.20f, 0.11f, 0.04f};
  for (uint32_t y = 0; y < size; ++y)
    for (uint32_t x = 0; x < size; ++x) {
      // Texel centres; v runs up from the bottom row, u across from the centre line.
      float u = (float(x) + 0.5f) / float(size) - 0.5f;
      float v = 1.0f - (float(y) + 0.5f) / float(size);
      bool inTrunk = std::abs(u) < 0.05f && v < 0.22f;
      // Three tiers, each a triangle narrowing upwards, the lower ones wider.
      bool inCrown = false;
      float shade = 0.0f;
      for (int tier = 0; tier < 3; ++tier) {
        float base = 0.15f + 0.25f * float(tier), top = base + 0.45f;
        float halfWidth = (0.46f - 0.1f * float(tier)) * (top - v) / (top - base);
        if (v >= base && v <= top && std::abs(u) <= halfWidth) {
          inCrown = true;
          shade = std::abs(u) / std::max(halfWidth, 1e-6f);  // 0 at the centre, 1 at the edge
        }
      }
      if (!inTrunk && !inCrown) continue;
      float ripple =
          0.5f + 0.5f * std::sin(40.0f * u + 23.0f * v) * std::sin(31.0f * v - 17.0f * u);
      glm::vec3 green = glm::mix(glm::vec3(0.02f, 0.16f, 0.03f), glm::vec3(0.08f, 0.42f, 0.07f),
                                 0.6f * ripple + 0.4f * (1.0f - shade));
      glm::vec3 color = inCrown ? green : trunk;
      size_t p = (size_t(y) * size + x) * 4;
      for (int c = 0; c < 3; ++c) texture.rgba8[p + size_t(c)] = unorm8(linearToSrgb(color[c]));
      texture.rgba8[p + 3] = 255;
    }
  return texture;
}

}  // namespace shadelab
