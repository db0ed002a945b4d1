#pragma once

// Transformation math of the course. Every matrix is built element by element from the
// textbook formula so students can compare the code with the lecture notes; GLM supplies only
// the vector/matrix types. GLM is column-major: m[col][row].
//
// Conventions: angles in radians; right-handed eye space with the camera looking down -z, y up.
// The *GL projections follow the OpenGL red book (clip y up, NDC z in [-1, 1]); the unsuffixed
// projections are the Vulkan ones (clip y down, NDC z in [0, 1]).

#include <glm/glm.hpp>

namespace shadelab {

// Affine modelling transforms.
glm::mat4 translation(glm::vec3 offset);
// Right-handed: counter-clockwise when looking down the axis toward the origin.
glm::mat4 rotationX(float angle);
glm::mat4 rotationY(float angle);
glm::mat4 rotationZ(float angle);
// Rodrigues' rotation formula; the axis is normalised here and must be non-zero.
glm::mat4 rotationAxis(glm::vec3 axis, float angle);
// T(p) R T(-p): rotates about the line through `point` along `axis`.
glm::mat4 rotationAboutPoint(glm::vec3 point, glm::vec3 axis, float angle);
glm::mat4 scaling(glm::vec3 factors);

// Shear: x' = x + xy*y + xz*z, y' = y + yx*x + yz*z, z' = z + zx*x + zy*y
struct Shear {
  float xy = 0, xz = 0, yx = 0, yz = 0, zx = 0, zy = 0;
};
glm::mat4 shearing(const Shear& s);

// Whether `transform` mirrors: its 3x3 part's determinant is negative (a
// scale of -1 along one axis, or three). Worked in double, so scales far
// from 1 (1e-20 or 1e20 per axis) keep the sign a float product would lose.
// A mirroring object draws a mesh wound for it (reverseWinding, mesh.h).
bool mirrors(const glm::mat4& transform);

// Inverses written from the formulas: T(d)^-1 = T(-d), R^-1 = R^T, S(s)^-1 = S(1/s).
glm::mat4 translationInverse(glm::vec3 offset);
// Transpose of the upper 3x3; any translation in `rotation` is ignored.
glm::mat4 rotationInverse(const glm::mat4& rotation);
glm::mat4 scalingInverse(glm::vec3 factors);

// Viewing transform: world -> right-handed eye space (camera at origin looking down -z).
glm::mat4 lookAt(glm::vec3 eye, glm::vec3 at, glm::vec3 up);

// Projections as the OpenGL red book writes them: clip space y up, NDC z in [-1, 1].
glm::mat4 frustumGL(float left, float right, float bottom, float top, float zNear, float zFar);
glm::mat4 perspectiveGL(float fovy, float aspect, float zNear, float zFar);
glm::mat4 orthographicGL(float left, float right, float bottom, float top, float zNear, float zFar);

// The ONE place the Vulkan clip-space convention is handled: Vulkan's clip space has y pointing
// down and depth in [0, 1]. Rows: [1,0,0,0], [0,-1,0,0], [0,0,0.5,0.5], [0,0,0,1], so
// P_vulkan = vulkanClipCorrection() * P_gl.
glm::mat4 vulkanClipCorrection();
glm::mat4 frustum(float left, float right, float bottom, float top, float zNear, float zFar);
glm::mat4 perspective(float fovy, float aspect, float zNear, float zFar);
glm::mat4 orthographic(float left, float right, float bottom, float top, float zNear, float zFar);

// Reversed-Z perspective for float depth buffers (near -> 1, far -> 0), Vulkan conventions,
// finite far plane.
glm::mat4 perspectiveReversedZ(float fovy, float aspect, float zNear, float zFar);
// Reverses depth after any Vulkan projection: rows [1,0,0,0], [0,1,0,0], [0,0,-1,1], [0,0,0,1],
// so z' = w - z and NDC depth d becomes 1 - d (near -> 1, far -> 0).
glm::mat4 reverseDepth();
glm::mat4 frustumReversedZ(float left, float right, float bottom, float top, float zNear,
                           float zFar);
glm::mat4 orthographicReversedZ(float left, float right, float bottom, float top, float zNear,
                                float zFar);

// Viewport mapping, Vulkan spec 'Coordinate Transformations': NDC -> framebuffer coordinates.
struct Viewport {
  float x = 0, y = 0, width = 1, height = 1, minDepth = 0, maxDepth = 1;
};
// xf = x + w/2 (xd + 1), yf = y + h/2 (yd + 1), zf = minDepth + zd (maxDepth - minDepth)
glm::vec3 viewportTransform(glm::vec3 ndc, const Viewport& vp);
// Clip -> NDC: (x/w, y/w, z/w); w must be non-zero.
glm::vec3 perspectiveDivide(glm::vec4 clip);

// Normals transform by the inverse transpose of the upper 3x3 of the model-view matrix.
glm::mat3 normalMatrix(const glm::mat4& modelView);

}  // namespace shadelab
