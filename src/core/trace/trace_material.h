#pragma once
// Textured materials at a traced hit: the diffuse texel (it scales ka and
// kd, as in shaders/forward_fragment.glsl), each map looked up through its
// KHR_texture_transform (shaders/uv_transform.glsl: the diffuse map's, and
// the normal map's for the normal and height maps), and the bump-mapped normal
// (shaders/bump.glsl: tangent-space normal maps and height maps, whiteout
// blending), both looked up at a level of detail from the ray's footprint.
//
// Footprint: every ray carries a cone (Amanatides 1984; "ray cones" in
// Akenine-Moller et al. 2019): camera rays a pixel wide (one stratum of it
// with supersampling, whose box filter covers the rest), secondary rays
// keep their parent's spread from the width it had at the hit (flat-mirror
// approximation: curvature is ignored). On the surface the cone covers
// width / |cos| along the ray's projection and width across it; the level of
// detail is log2 of the longer of the two in texels, which is the GPU's
// isotropic max(|dst/dx|, |dst/dy|) rule for the same pixel.
#include <glm/glm.hpp>
#include <vector>

#include "core/scene/scene.h"
#include "core/trace/trace_textures.h"

namespace shadelab {

// The uv at a hit and its rates of change along two orthonormal directions
// of the tangent plane: `along` (the incident ray projected onto the plane)
// and `across` (normal x along).
struct UvFrame {
  glm::vec2 uv{0.0f};
  glm::vec3 along{1.0f, 0.0f, 0.0f}, across{0.0f, 0.0f, 1.0f};
  glm::vec2 uvPerAlong{0.0f}, uvPerAcross{0.0f};  // uv per world unit
};

// Tangent-plane directions for a hit with unit `normal` seen along unit `incident`.
void tangentPlaneAxes(glm::vec3 normal, glm::vec3 incident, glm::vec3& along, glm::vec3& across);

// The material with its diffuse texel applied (for a coverage material,
// Material::alphaCoverage, its alpha too); `normal` (unit, world space)
// is replaced by the bumped normal when the material has a normal or height
// map. `footprint` is the cone's width at the hit, `cosine` |N.incident|.
Material texturedMaterial(const Material& material, const std::vector<TraceTexture>& textures,
                          const UvFrame& frame, float footprint, float cosine, glm::vec3& normal);

// glTF alphaMode MASK (Material::alphaCutoff): whether the surface at `uv` is
// cut away, its alpha (the factor's times the diffuse texel's) below the
// cut-off. The texel is the base level's: the surface's own outline, which
// supersampling filters, where the rasteriser tests the mip level a pixel's
// footprint picks (shaders/forward_fragment.glsl).
bool cutAway(const Material& material, const std::vector<TraceTexture>& textures, glm::vec2 uv);

// A coverage material's (Material::alphaCoverage) share of a shadow ray it
// stops at `uv`: 1 - transparency times the base level's diffuse alpha.
float coverage(const Material& material, const std::vector<TraceTexture>& textures, glm::vec2 uv);

}  // namespace shadelab
