// Trimmed billboard outlines (core/scene/billboard_outline.h): the triangle
// must hold every point where the filtered alpha can pass, at every mip
// level, and be smaller than the quad when the texture leaves room.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/scene/billboard_outline.h"
#include "core/scene/procedural_textures.h"

namespace shadelab {
namespace {

Texture alphaTexture(uint32_t width, uint32_t height, const std::vector<uint8_t>& alpha) {
  Texture texture;
  texture.name = "test";
  texture.width = width;
  texture.height = height;
  texture.rgba8.assign(size_t(width) * height * 4, 255);
  for (size_t i = 0; i < alpha.size(); ++i) texture.rgba8[i * 4 + 3] = alpha[i];
  return texture;
}

SamplerDesc clamped() {
  SamplerDesc sampler;
  sampler.wrapU = sampler.wrapV = TextureWrap::ClampToEdge;
  return sampler;
}

bool inside(const BillboardOutline& outline, glm::vec2 p) {
  for (int i = 0; i < 3; ++i) {
    glm::vec2 a = outline.corners[size_t(i)], b = outline.corners[size_t((i + 1) % 3)];
    glm::vec2 e = b - a, d = p - a;
    if (e.x * d.y - e.y * d.x < 0.0f) return false;
  }
  return true;
}

// The test's own mip chain (2x2 box averages of a power-of-two texture) and
// edge-clamped bilinear lookup, written apart from the library's.
std::vector<std::vector<float>> boxChain(const Texture& texture) {
  std::vector<std::vector<float>> levels(1);
  for (size_t i = 0; i < size_t(texture.width) * texture.height; ++i)
    levels[0].push_back(texture.rgba8[i * 4 + 3] / 255.0f);
  for (uint32_t size = texture.width / 2; size >= 1; size /= 2) {
    const std::vector<float>& above = levels.back();
    std::vector<float> level(size_t(size) * size);
    for (uint32_t y = 0; y < size; ++y)
      for (uint32_t x = 0; x < size; ++x) {
        auto a = [&](uint32_t u, uint32_t v) { return above[size_t(v) * 2 * size + u]; };
        level[size_t(y) * size + x] = 0.25f * (a(2 * x, 2 * y) + a(2 * x + 1, 2 * y) +
                                               a(2 * x, 2 * y + 1) + a(2 * x + 1, 2 * y + 1));
      }
    levels.push_back(level);
  }
  return levels;
}

float clampedBilinear(const std::vector<float>& level, int size, float s, float t) {
  float x = s * size - 0.5f, y = t * size - 0.5f;
  int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  float fx = x - std::floor(x), fy = y - std::floor(y);
  auto at = [&](int u, int v) {
    return level[size_t(std::clamp(v, 0, size - 1)) * size_t(size) +
                 size_t(std::clamp(u, 0, size - 1))];
  };
  float top = at(x0, y0) * (1 - fx) + at(x0 + 1, y0) * fx;
  float bottom = at(x0, y0 + 1) * (1 - fx) + at(x0 + 1, y0 + 1) * fx;
  return top * (1 - fy) + bottom * fy;
}

// Points where the test's own trilinear/bilinear/nearest lookups of the
// tree reach the cut-off, at random, each with the finest level sampled.
struct Passing {
  glm::vec2 quad;  // quad coordinates
  size_t level;
};

std::vector<Passing> passingPoints(const Texture& texture, float cutoff, int count) {
  std::vector<std::vector<float>> chain = boxChain(texture);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<Passing> points;
  for (int n = 0; n < count; ++n) {
    float s = unit(random), t = unit(random);
    for (size_t level = 0; level < chain.size(); ++level) {
      int size = int(texture.width >> level);
      bool passes = clampedBilinear(chain[level], size, s, t) >= cutoff;
      if (level == 0) {  // nearest, the base level
        int x = std::min(int(s * size), size - 1), y = std::min(int(t * size), size - 1);
        passes = passes || chain[0][size_t(y) * size_t(size) + size_t(x)] >= cutoff;
      }
      if (passes) points.push_back({glm::vec2(s, 1.0f - t), level});
    }
  }
  return points;
}

TEST(BillboardOutline, TreeOutlinesHoldEveryPassingPointOfTheirLevels) {
  Texture tree = treeTexture(128, "tree");
  std::vector<std::optional<BillboardOutline>> outlines = billboardOutlines(tree, clamped(), 0.5f);
  ASSERT_EQ(outlines.size(), 8u);
  std::vector<Passing> points = passingPoints(tree, 0.5f, 20000);
  ASSERT_GT(points.size(), 20000u);  // about half the quad passes at each level
  size_t outside = 0, checked = 0;
  for (size_t level = 0; level < outlines.size(); ++level) {
    ASSERT_TRUE(outlines[level]) << "level " << level << " keeps the quad";
    for (const Passing& point : points)
      if (point.level <= level) {
        ++checked;
        if (!inside(*outlines[level], point.quad)) ++outside;
      }
  }
  EXPECT_GT(checked, 100000u);
  EXPECT_EQ(outside, 0u);
  // Twin: the finest outline shrunk by 5% about its centroid leaves points out.
  BillboardOutline shrunk = *outlines[0];
  glm::vec2 centroid = (shrunk.corners[0] + shrunk.corners[1] + shrunk.corners[2]) / 3.0f;
  for (glm::vec2& corner : shrunk.corners) corner = centroid + 0.95f * (corner - centroid);
  size_t lost = 0;
  for (const Passing& point : points)
    if (point.level == 0 && !inside(shrunk, point.quad)) ++lost;
  EXPECT_GT(lost, 10u);
}

// The tree leaves a quarter of the quad out at the levels a near copy reads,
// and the coarsest levels' blur still fits a triangle smaller than the quad.
TEST(BillboardOutline, TreeTrianglesAreSmallerThanTheQuad) {
  std::vector<std::optional<BillboardOutline>> outlines =
      billboardOutlines(treeTexture(128, "tree"), clamped(), 0.5f);
  ASSERT_EQ(outlines.size(), 8u);
  ASSERT_TRUE(outlines[0] && outlines[7]);
  EXPECT_LT(outlines[0]->area, 0.75f);
  EXPECT_LT(outlines[7]->area, 1.0f);
  for (size_t level = 1; level < outlines.size(); ++level)
    EXPECT_GE(outlines[level]->area, outlines[level - 1]->area) << "level " << level;
}

TEST(BillboardOutline, OpaqueTextureKeepsTheQuad) {
  std::vector<std::optional<BillboardOutline>> outlines =
      billboardOutlines(alphaTexture(16, 16, std::vector<uint8_t>(256, 255)), clamped(), 0.5f);
  ASSERT_EQ(outlines.size(), 5u);
  for (const auto& outline : outlines) EXPECT_FALSE(outline);
  // Not examined: too large a side.
  Texture large = alphaTexture(kMaxOutlineTextureSide + 1, 1, {});
  EXPECT_TRUE(billboardOutlines(large, clamped(), 0.5f).empty());
}

// Repeat wrapping blends the first column into the last texels' cells: the
// hull reaches the far edge; clamped, it stays by the opaque column.
TEST(BillboardOutline, RepeatWrapReachesAcrossTheEdge) {
  std::vector<uint8_t> alpha(16 * 16, 0);
  for (int y = 0; y < 16; ++y) alpha[size_t(y) * 16] = 255;
  Texture column = alphaTexture(16, 16, alpha);
  auto rightmost = [](const std::vector<glm::vec2>& hull) {
    float x = -1.0f;
    for (glm::vec2 p : hull) x = std::max(x, p.x);
    return x;
  };
  auto clampedHulls = billboardAlphaHulls(column, clamped(), 0.5f);
  SamplerDesc repeat = clamped();
  repeat.wrapU = TextureWrap::Repeat;
  auto repeatHulls = billboardAlphaHulls(column, repeat, 0.5f);
  ASSERT_TRUE(clampedHulls && repeatHulls);
  EXPECT_LE(rightmost((*clampedHulls)[0]), 2.0f / 16.0f);
  EXPECT_EQ(rightmost((*repeatHulls)[0]), 1.0f);
}

// Blended billboards show wherever alpha is above 0; a cut-out only where
// it can reach the cut-off.
TEST(BillboardOutline, BlendShowsAnyAlphaCutOutOnlyTheCutOff) {
  std::vector<uint8_t> alpha(16 * 16, 0);
  for (int y = 6; y < 10; ++y)
    for (int x = 6; x < 10; ++x) alpha[size_t(y) * 16 + size_t(x)] = 255;
  alpha[0] = 2;  // the top-left texel, nearly transparent
  Texture texture = alphaTexture(16, 16, alpha);
  auto blended = billboardAlphaHulls(texture, clamped(), 0.0f);
  auto cutOut = billboardAlphaHulls(texture, clamped(), 0.5f);
  ASSERT_TRUE(blended && cutOut);
  auto reachesTopLeft = [](const std::vector<glm::vec2>& hull) {
    return std::any_of(hull.begin(), hull.end(),
                       [](glm::vec2 p) { return p.x == 0.0f && p.y == 1.0f; });
  };
  EXPECT_TRUE(reachesTopLeft((*blended)[0]));
  EXPECT_FALSE(reachesTopLeft((*cutOut)[0]));
}

// The smallest triangle around a unit square has twice its area, one side
// along a side of the square (a classic result).
TEST(BillboardOutline, SmallestTriangleAroundASquareHasTwiceItsArea) {
  std::optional<BillboardOutline> triangle =
      enclosingTriangle({{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}}, 0.0f);
  ASSERT_TRUE(triangle);
  EXPECT_NEAR(triangle->area, 2.0f, 1e-5f);
  for (glm::vec2 p :
       {glm::vec2(0.0f), glm::vec2(1.0f, 0.0f), glm::vec2(1.0f), glm::vec2(0.0f, 1.0f)})
    EXPECT_TRUE(inside(*triangle, p + 1e-4f * (glm::vec2(0.5f) - p)));
  EXPECT_FALSE(enclosingTriangle({{0.0f, 0.0f}, {1.0f, 0.0f}}, 0.0f));
}

// The level bound against the level of detail a facing quad really has:
// never below it, and no more than the sum approximation (half a level), the
// depth growth and one level above it.
TEST(BillboardOutline, LevelBoundCoversAFacingQuadsLevel) {
  const float focal = 400.0f;
  for (float distance : {0.5f, 2.0f, 7.0f, 30.0f, 300.0f}) {
    BillboardView view{glm::vec3(0.1f, -0.2f, -distance),
                       glm::vec3(1, 0, 0),
                       glm::vec3(0, 1, 0),
                       glm::vec2(0.2f, 0.2f),
                       glm::uvec2(256),
                       focal};
    // Texels per pixel at the centre: 256 texels over 0.2 units seen from
    // `distance` by a `focal` pixel lens.
    float lambda = std::log2(256.0f / 0.2f * distance / focal);
    uint32_t bound = billboardLevelBound(view, 9);
    SCOPED_TRACE(distance);
    if (lambda >= 8.0f) {
      EXPECT_EQ(bound, 8u);
      continue;
    }
    EXPECT_GE(float(bound), std::floor(std::max(lambda, 0.0f)) + (lambda > 0.0f ? 1.0f : 0.0f));
    EXPECT_LE(float(bound), std::max(lambda, 0.0f) + 2.6f);
  }
  // Edge-on, or the eye near the quad: every level.
  BillboardView edgeOn{glm::vec3(0, 0, -5), glm::vec3(1, 0, 0), glm::vec3(0, 0, 1),
                       glm::vec2(0.2f),     glm::uvec2(256),    focal};
  EXPECT_EQ(billboardLevelBound(edgeOn, 9), 8u);
  BillboardView near{glm::vec3(0, 0, -0.2f), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0),
                     glm::vec2(0.2f),        glm::uvec2(256),    focal};
  EXPECT_EQ(billboardLevelBound(near, 9), 8u);
}

}  // namespace
}  // namespace shadelab
