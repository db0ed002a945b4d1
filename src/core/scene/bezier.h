#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "core/scene/mesh.h"

namespace shadelab {

// Cubic curves as the course writes them: p(u) = u^T M G with u = (u^3, u^2, u, 1)
// and G the four geometry points as rows. In GLM, u^T M is `u * M`.
glm::vec4 powerBasis(float u);  // (u^3, u^2, u, 1)
glm::mat4 bezierBasisMatrix();  // M_B
glm::mat4
interpolatingBasisMatrix();  // M_I: the cubic through its four points at u = 0, 1/3, 2/3, 1

// Bernstein polynomials b0..b3 = (1-u)^3, 3u(1-u)^2, 3u^2(1-u), u^3 and their derivatives.
glm::vec4 bezierBlending(float u);
glm::vec4 bezierBlendingDerivative(float u);

glm::vec3 evalCubic(const glm::mat4& basis, const std::array<glm::vec3, 4>& geometry, float u);
glm::vec3 evalBezierCurve(const std::array<glm::vec3, 4>& p, float u);
glm::vec3 evalBezierCurveDerivative(const std::array<glm::vec3, 4>& p, float u);

// Row-major control net: control[4*i + j], i along u, j along v.
struct BezierPatch {
  std::array<glm::vec3, 16> control;
};

struct PatchSample {
  glm::vec3 position;
  glm::vec3 dPdu;
  glm::vec3 dPdv;
  glm::vec3 normal;  // unit; at degenerate points, the limit taken from just inside the patch
};

PatchSample evalBezierPatch(const BezierPatch& patch, float u, float v);

// `level` quads per patch side (level >= 1, 0 is treated as 1), two triangles each,
// counter-clockwise seen from the side the normal cross(dP/du, dP/dv) points to.
// Each patch gets its own (level+1)^2 vertices; UV = (u, v); tangent = dP/du
// made orthogonal to the normal, w = handedness of (T, N x T, dP/dv).
Mesh tessellatePatches(const std::vector<BezierPatch>& patches, uint32_t level);

// Newell's Utah teapot, 32 patches in the classic order: rim 0-3, body 4-11,
// handle 12-15, spout 16-19, lid 20-27, bottom 28-31. Converted to y up, standing
// on y = 0, spout along +x, every patch oriented so its normals point outward.
const std::vector<BezierPatch>& utahTeapotPatches();

}  // namespace shadelab
