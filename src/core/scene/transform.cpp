#include "core/scene/transform.h"

#include <cassert>
#include <cmath>

namespace shadelab {

namespace {

// Lets each matrix below be written row by row as in the textbook; GLM stores m[col][row].
glm::mat4 fromRows(glm::vec4 r0, glm::vec4 r1, glm::vec4 r2, glm::vec4 r3) {
  const glm::vec4 rows[4] = {r0, r1, r2, r3};
  glm::mat4 m(0.0f);
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 4; ++col) {
      m[col][row] = rows[row][col];
    }
  }
  return m;
}

}  // namespace

glm::mat4 translation(glm::vec3 offset) {
  return fromRows({1, 0, 0, offset.x}, {0, 1, 0, offset.y}, {0, 0, 1, offset.z}, {0, 0, 0, 1});
}

glm::mat4 rotationX(float angle) {
  const float c = std::cos(angle);
  const float s = std::sin(angle);
  return fromRows({1, 0, 0, 0}, {0, c, -s, 0}, {0, s, c, 0}, {0, 0, 0, 1});
}

glm::mat4 rotationY(float angle) {
  const float c = std::cos(angle);
  const float s = std::sin(angle);
  // The signs of s are swapped relative to X and Z because z x x = y (cyclic order z, x).
  return fromRows({c, 0, s, 0}, {0, 1, 0, 0}, {-s, 0, c, 0}, {0, 0, 0, 1});
}

glm::mat4 rotationZ(float angle) {
  const float c = std::cos(angle);
  const float s = std::sin(angle);
  return fromRows({c, -s, 0, 0}, {s, c, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1});
}

glm::mat4 rotationAxis(glm::vec3 axis, float angle) {
  assert(glm::dot(axis, axis) > 0.0f && "rotation axis must be non-zero");
  const glm::vec3 k = axis / std::sqrt(glm::dot(axis, axis));
  const float c = std::cos(angle);
  const float s = std::sin(angle);
  const float t = 1.0f - c;
  // Rodrigues: R = c I + (1 - c) k k^T + s [k]x, with [k]x the cross-product matrix of k.
  return fromRows({c + t * k.x * k.x, t * k.x * k.y - s * k.z, t * k.x * k.z + s * k.y, 0},
                  {t * k.y * k.x + s * k.z, c + t * k.y * k.y, t * k.y * k.z - s * k.x, 0},
                  {t * k.z * k.x - s * k.y, t * k.z * k.y + s * k.x, c + t * k.z * k.z, 0},
                  {0, 0, 0, 1});
}

glm::mat4 rotationAboutPoint(glm::vec3 point, glm::vec3 axis, float angle) {
  return translation(point) * rotationAxis(axis, angle) * translation(-point);
}

glm::mat4 scaling(glm::vec3 factors) {
  return fromRows({factors.x, 0, 0, 0}, {0, factors.y, 0, 0}, {0, 0, factors.z, 0}, {0, 0, 0, 1});
}

glm::mat4 shearing(const Shear& s) {
  return fromRows({1, s.xy, s.xz, 0}, {s.yx, 1, s.yz, 0}, {s.zx, s.zy, 1, 0}, {0, 0, 0, 1});
}

glm::mat4 translationInverse(glm::vec3 offset) {
  return translation(-offset);
}

glm::mat4 rotationInverse(const glm::mat4& rotation) {
  glm::mat4 inverse(1.0f);
  for (int col = 0; col < 3; ++col) {
    for (int row = 0; row < 3; ++row) {
      inverse[col][row] = rotation[row][col];
    }
  }
  return inverse;
}

glm::mat4 scalingInverse(glm::vec3 factors) {
  assert(factors.x != 0.0f && factors.y != 0.0f && factors.z != 0.0f);
  return scaling(glm::vec3(1.0f) / factors);
}

glm::mat4 lookAt(glm::vec3 eye, glm::vec3 at, glm::vec3 up) {
  const glm::vec3 forward = at - eye;
  assert(glm::dot(forward, forward) > 0.0f && "eye and at must differ");
  const glm::vec3 f = glm::normalize(forward);
  const glm::vec3 side = glm::cross(f, up);
  assert(glm::dot(side, side) > 0.0f && "up must not be parallel to the view direction");
  const glm::vec3 s = glm::normalize(side);
  const glm::vec3 u = glm::cross(s, f);
  // Rows are the camera basis (s, u, -f); the last column -R * eye moves the eye to the origin.
  return fromRows({s.x, s.y, s.z, -glm::dot(s, eye)}, {u.x, u.y, u.z, -glm::dot(u, eye)},
                  {-f.x, -f.y, -f.z, glm::dot(f, eye)}, {0, 0, 0, 1});
}

glm::mat4 frustumGL(float left, float right, float bottom, float top, float zNear, float zFar) {
  assert(right != left && top != bottom);
  assert(zNear > 0.0f && zFar > zNear);
  const float w = right - left;
  const float h = top - bottom;
  const float d = zFar - zNear;
  // glFrustum as printed in the OpenGL Programming Guide (red book).
  return fromRows({2 * zNear / w, 0, (right + left) / w, 0},
                  {0, 2 * zNear / h, (top + bottom) / h, 0},
                  {0, 0, -(zFar + zNear) / d, -2 * zFar * zNear / d}, {0, 0, -1, 0});
}

glm::mat4 perspectiveGL(float fovy, float aspect, float zNear, float zFar) {
  assert(fovy > 0.0f && aspect > 0.0f);
  assert(zNear > 0.0f && zFar > zNear);
  // gluPerspective: f = cot(fovy / 2), the symmetric special case of glFrustum.
  const float f = 1.0f / std::tan(fovy / 2);
  const float d = zNear - zFar;
  return fromRows({f / aspect, 0, 0, 0}, {0, f, 0, 0},
                  {0, 0, (zFar + zNear) / d, 2 * zFar * zNear / d}, {0, 0, -1, 0});
}

glm::mat4 orthographicGL(float left, float right, float bottom, float top, float zNear,
                         float zFar) {
  assert(right != left && top != bottom && zFar != zNear);
  const float w = right - left;
  const float h = top - bottom;
  const float d = zFar - zNear;
  return fromRows({2 / w, 0, 0, -(right + left) / w}, {0, 2 / h, 0, -(top + bottom) / h},
                  {0, 0, -2 / d, -(zFar + zNear) / d}, {0, 0, 0, 1});
}

glm::mat4 vulkanClipCorrection() {
  // y' = -y flips the vertical axis; z' = (z + w) / 2 maps NDC depth [-1, 1] to [0, 1].
  return fromRows({1, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, 0.5f, 0.5f}, {0, 0, 0, 1});
}

glm::mat4 frustum(float left, float right, float bottom, float top, float zNear, float zFar) {
  return vulkanClipCorrection() * frustumGL(left, right, bottom, top, zNear, zFar);
}

glm::mat4 perspective(float fovy, float aspect, float zNear, float zFar) {
  return vulkanClipCorrection() * perspectiveGL(fovy, aspect, zNear, zFar);
}

glm::mat4 orthographic(float left, float right, float bottom, float top, float zNear, float zFar) {
  return vulkanClipCorrection() * orthographicGL(left, right, bottom, top, zNear, zFar);
}

glm::mat4 perspectiveReversedZ(float fovy, float aspect, float zNear, float zFar) {
  assert(fovy > 0.0f && aspect > 0.0f);
  assert(zNear > 0.0f && zFar > zNear);
  const float f = 1.0f / std::tan(fovy / 2);
  const float d = zFar - zNear;
  // Depth row (A, B) solves (A z + B) / -z = 1 at z = -near and 0 at z = -far:
  // A = n / (f - n), B = f n / (f - n). The y row is negated for Vulkan's downward y.
  return fromRows({f / aspect, 0, 0, 0}, {0, -f, 0, 0}, {0, 0, zNear / d, zFar * zNear / d},
                  {0, 0, -1, 0});
}

glm::mat4 reverseDepth() {
  return fromRows({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, -1, 1}, {0, 0, 0, 1});
}

glm::mat4 frustumReversedZ(float left, float right, float bottom, float top, float zNear,
                           float zFar) {
  return reverseDepth() * frustum(left, right, bottom, top, zNear, zFar);
}

glm::mat4 orthographicReversedZ(float left, float right, float bottom, float top, float zNear,
                                float zFar) {
  return reverseDepth() * orthographic(left, right, bottom, top, zNear, zFar);
}

glm::vec3 viewportTransform(glm::vec3 ndc, const Viewport& vp) {
  return {vp.x + vp.width / 2 * (ndc.x + 1), vp.y + vp.height / 2 * (ndc.y + 1),
          vp.minDepth + ndc.z * (vp.maxDepth - vp.minDepth)};
}

glm::vec3 perspectiveDivide(glm::vec4 clip) {
  assert(clip.w != 0.0f && "cannot divide by w = 0 (point at infinity)");
  return {clip.x / clip.w, clip.y / clip.w, clip.z / clip.w};
}

glm::mat3 normalMatrix(const glm::mat4& modelView) {
  const glm::vec3 a(modelView[0]);
  const glm::vec3 b(modelView[1]);
  const glm::vec3 c(modelView[2]);
  // For M = [a b c] (columns), M^-1 has rows (b x c, c x a, a x b) / det with
  // det = a . (b x c), so M^-T has those cross products as its columns.
  const glm::vec3 bc = glm::cross(b, c);
  const float det = glm::dot(a, bc);
  assert(det != 0.0f && "model-view matrix must be invertible");
  return glm::mat3(bc / det, glm::cross(c, a) / det, glm::cross(a, b) / det);
}

bool mirrors(const glm::mat4& transform) {
  return glm::determinant(glm::dmat3(glm::mat3(transform))) < 0.0;
}

}  // namespace shadelab
