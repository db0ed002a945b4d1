#include "core/scene/frustum.h"

#include <algorithm>
#include <cmath>

namespace shadelab {
namespace {

glm::vec4 row(const glm::mat4& m, int index) {
  return glm::vec4(m[0][index], m[1][index], m[2][index], m[3][index]);
}

Plane normalised(glm::vec4 coefficients) {
  float length = glm::length(glm::vec3(coefficients));
  if (length == 0.0f) return Plane{glm::vec3(0.0f), 1.0f};  // degenerate: culls nothing
  return Plane{glm::vec3(coefficients) / length, coefficients.w / length};
}

}  // namespace

Frustum frustumFromMatrix(const glm::mat4& m) {
  glm::vec4 x = row(m, 0), y = row(m, 1), z = row(m, 2), w = row(m, 3);
  // A clip-space point is inside when -w <= x <= w, -w <= y <= w and
  // 0 <= z <= w (Vulkan depth); each inequality is a plane in the source space.
  return Frustum{{normalised(w + x), normalised(w - x), normalised(w + y), normalised(w - y),
                  normalised(z), normalised(w - z)}};
}

Bounds transformBounds(const Bounds& box, const glm::mat4& transform) {
  glm::vec3 centreIn = centre(box);
  glm::vec3 extentIn = 0.5f * (box.max - box.min);
  glm::vec3 centreOut = glm::vec3(transform * glm::vec4(centreIn, 1.0f));
  glm::vec3 extentOut(0.0f);
  for (int out = 0; out < 3; ++out)
    for (int in = 0; in < 3; ++in) extentOut[out] += std::abs(transform[in][out]) * extentIn[in];
  return Bounds{centreOut - extentOut, centreOut + extentOut};
}

bool boxIntersectsFrustum(const Bounds& box, const Frustum& frustum) {
  for (const Plane& plane : frustum.planes) {
    // The corner furthest along the plane's inward normal: if even it is
    // outside, the whole box is.
    glm::vec3 positive(plane.normal.x >= 0.0f ? box.max.x : box.min.x,
                       plane.normal.y >= 0.0f ? box.max.y : box.min.y,
                       plane.normal.z >= 0.0f ? box.max.z : box.min.z);
    if (plane.signedDistance(positive) < 0.0f) return false;
  }
  return true;
}

bool sphereIntersectsFrustum(glm::vec3 centre, float radius, const Frustum& frustum) {
  for (const Plane& plane : frustum.planes)
    if (plane.signedDistance(centre) < -radius * glm::length(plane.normal)) return false;
  return true;
}

Bounds unite(const Bounds& a, const Bounds& b) {
  return Bounds{glm::min(a.min, b.min), glm::max(a.max, b.max)};
}

}  // namespace shadelab
