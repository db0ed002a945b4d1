#pragma once
// Trimmed billboards: a cut-out or blended billboard copy is drawn as one
// triangle that holds every point of its quad where its texture can show,
// instead of the quad's two triangles. A tree sprite leaves a quarter of its
// quad transparent, and llvmpipe shades every 4x4 block a triangle touches
// whole: one tighter triangle is half the set-up and fewer blocks
// (docs/PERFORMANCE.md, "Trimmed outlines", has the figures). The fragments
// the quad draws and the triangle does not are all ones the alpha test or
// the blend would have dropped; those the triangle adds outside the quad
// billboard.frag discards. The image is the quad's up to the rounding of
// the uv each fragment interpolates (one RGBA16F step in a few texels).
//
// "Can show" is decided on the texture's alpha at each mip level, as
// MipGeneration builds them (each level a linear blit of the one above),
// under nearest (base level only), bilinear and trilinear filtering with the
// sampler's wrap modes: a filtered alpha is a convex combination of texels,
// and a bilinear blend over an axis-aligned rectangle inside one cell
// between texel centres is largest at a corner, so a point can pass only
// inside a sub-cell one of whose corners passes. A copy's triangle is the
// one for the coarsest level it can sample (billboardLevelBound): far copies
// read blurred levels whose alpha spreads wider. Anisotropic filtering
// reaches further along the footprint and is not covered: such draws keep
// the quad, as do multisampled targets (a sample outside the triangle would
// lose the colour its pixel's centre gave it).
#include <array>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "core/scene/scene.h"

namespace shadelab {

// In the quad's coordinates: x across (0 left, 1 right), y up (0 bottom,
// 1 top); st = (x, 1 - y) at a uv scale of 1.
struct BillboardOutline {
  std::array<glm::vec2, 3> corners;  // counter-clockwise; may lie outside the quad
  float area = 0.0f;                 // in quads
};

// The convex hulls (counter-clockwise, in quad coordinates) of the points
// where the filtered alpha can reach `cutoff` (an alpha test's cut-off; 0 for
// a blended billboard: any alpha above 0 shows), one per mip level L, each of
// levels 0..L together: a fragment whose level of detail is at most L
// samples no coarser level. A hull is empty when nothing can show. nullopt:
// a side larger than kMaxOutlineTextureSide (not examined).
// Examining a 512x512 texture takes ~75 ms (a 1024 one ~0.3 s); larger
// sprites keep the quad.
inline constexpr uint32_t kMaxOutlineTextureSide = 512;
// Outlines computed for at most this many (texture, wrap, cut-off) sets per
// scene (uploadScene): a scene of many large sprites keeps quads past them
// rather than spend seconds at upload.
inline constexpr size_t kMaxOutlineSets = 64;
std::optional<std::vector<std::vector<glm::vec2>>> billboardAlphaHulls(const Texture& texture,
                                                                       const SamplerDesc& sampler,
                                                                       float cutoff);

// How far the triangle's sides stand off the hull, in quads: covers the
// rasteriser's snapping of its corners (1/256 pixel) down to quads ~1 pixel
// across, and the interpolation's rounding.
inline constexpr float kOutlineMargin = 0.01f;

// The smallest triangle found around a convex, counter-clockwise `hull`
// whose sides lie along its supporting lines (at its edges' normals and at
// kOutlineDirections even directions), pushed out by `margin`; nullopt for
// fewer than 3 points.
inline constexpr int kOutlineDirections = 72;
std::optional<BillboardOutline> enclosingTriangle(const std::vector<glm::vec2>& hull, float margin);

// Per mip level L, the triangle around billboardAlphaHulls' hull L (margin
// kOutlineMargin), or nullopt where the quad is to be drawn: nothing can
// show, or no triangle is smaller than the quad. Empty: not examined.
std::vector<std::optional<BillboardOutline>> billboardOutlines(const Texture& texture,
                                                               const SamplerDesc& sampler,
                                                               float cutoff);

// A copy's quad as the camera sees it, for the level-of-detail bound.
struct BillboardView {
  glm::vec3 centre;  // the quad's centre, eye space
  glm::vec3 right;   // its unit axes, eye space, as billboard.vert turns them
  glm::vec3 up;
  glm::vec2 size;            // width and height, eye units
  glm::uvec2 texels;         // the texture's base level size
  float focalPixels = 0.0f;  // pixels per eye unit at distance 1 (|projection[1][1]| * height / 2)
};

// The coarsest mip level any fragment of the copy can sample, bounded from
// above. At the centre, the texel-per-pixel derivatives are diag(texels)
// J^-1, with J the Jacobian of the pixel position over the quad's
// coordinates; the length of a derivative is bounded by |du| + |dv| (the
// longest Vulkan allows an implementation to use). Across the quad the
// derivatives grow at most by ((q + r) / (q - r))^2, q the centre's depth
// and r the quad's half diagonal. The level returned is floor(log2) + 1 of
// that bound: trilinear filtering reads floor(lambda) and the level above.
// Returns `levels` - 1 (every level) when the quad reaches within 2 half
// diagonals of the eye plane or is seen edge-on.
uint32_t billboardLevelBound(const BillboardView& view, uint32_t levels);

}  // namespace shadelab
