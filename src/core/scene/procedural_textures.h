#pragma once
// Textures the project generates itself, deterministically (no files): height
// fields in 0..1 and the colour, height and normal maps made from them.
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace shadelab {

enum class HeightPattern {
  Checker,  // 1 on one colour of the board, 0 on the other
  Bricks,   // 1 on a brick, 0 in the mortar, a bevelled edge between (running bond)
  Dimples,  // 1 on the flat, a smooth cosine dip to 0 at each cell's centre
  Waves,    // 0.5 + 0.25 (sin 2 pi u + sin 2 pi v): ripples along both axes
};
inline constexpr NameTable<HeightPattern, 4> kHeightPatternNames = {
    {{HeightPattern::Checker, "checker"},
     {HeightPattern::Bricks, "bricks"},
     {HeightPattern::Dimples, "dimples"},
     {HeightPattern::Waves, "waves"}}};

struct ProceduralTexture {
  HeightPattern pattern = HeightPattern::Checker;
  uint32_t size = 256;   // texels per side (square), 1..4096
  uint32_t repeats = 8;  // cells per side: checks, brick rows, dimples, wave periods (>= 1)
};

// A square height field, row 0 at the top. Every pattern has period
// size / repeats in both axes, so the texture tiles seamlessly.
struct HeightField {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> values;             // width * height, 0..1
  float at(int32_t x, int32_t y) const;  // wraps around (the patterns tile)
};

HeightField proceduralHeight(const ProceduralTexture& desc);
// As a C string for messages (the table's names are literals).
inline const char* heightPatternName(HeightPattern pattern) {
  return nameOf(kHeightPatternNames, pattern).data();
}

// The tangent-space normal of a height field at a texel, from central
// differences (wrapping): n = normalize(-depth dh/du, -depth dh/dv, 1), with u
// to the right and v up the image (toward row 0), derivatives per texel:
// `depth` is how many texels a height of 1 stands for. The same formula
// shaders/bump.glsl applies to height maps with depth = bump scale.
glm::vec3 heightFieldNormal(const HeightField& field, int32_t x, int32_t y, float depth);

// Colour texture: linear mix(low, high, h), sRGB encoded.
Texture heightColorTexture(const HeightField& field, glm::vec3 low, glm::vec3 high,
                           const std::string& name);
// Data texture: r = g = b = h.
Texture heightMapTexture(const HeightField& field, const std::string& name);
// Data texture: rgb = n * 0.5 + 0.5 from heightFieldNormal.
Texture normalMapTexture(const HeightField& field, float depth, const std::string& name);

// A colour texture with alpha, for billboards: a conifer seen from the side
// (a brown trunk under three tiers of green crown, shaded by a fixed ripple),
// opaque on the tree and fully transparent around it. size x size texels,
// row 0 at the top (the tree's tip).
Texture treeTexture(uint32_t size, const std::string& name);

}  // namespace shadelab
