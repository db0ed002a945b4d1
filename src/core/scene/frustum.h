#pragma once
// View-frustum culling, the course's "easy filtering first": an object whose
// bounding box lies wholly outside one of the six clip planes cannot cover a
// pixel, so it is not drawn. Also the bounding-box helpers culling, camera
// framing and level-of-detail selection share.
#include <array>
#include <glm/glm.hpp>

#include "core/scene/mesh.h"

namespace shadelab {

// Plane n.x + d = 0 with the normal pointing into the visible half-space.
struct Plane {
  glm::vec3 normal{0.0f};
  float d = 0.0f;
  float signedDistance(glm::vec3 point) const { return glm::dot(normal, point) + d; }
};

struct Frustum {
  std::array<Plane, 6> planes;  // left, right, bottom, top, near, far
};

// The planes of a Vulkan view-projection matrix (clip space -w <= x, y <= w,
// 0 <= z <= w), by Gribb and Hartmann's row combinations, in the space the
// matrix maps from (world space for projection * view).
Frustum frustumFromMatrix(const glm::mat4& viewProjection);

// Axis-aligned box of `box` after an affine transform (Arvo's method: each
// output extent sums the absolute matrix entries times the input extents),
// so it contains every transformed corner.
Bounds transformBounds(const Bounds& box, const glm::mat4& transform);

// False when the box lies entirely on the outer side of some plane (then it
// is certainly invisible). True may still be invisible (near a corner of the
// frustum): the test is conservative, never culls what is seen.
bool boxIntersectsFrustum(const Bounds& box, const Frustum& frustum);

// The same test for a sphere: false when it lies wholly outside some plane.
bool sphereIntersectsFrustum(glm::vec3 centre, float radius, const Frustum& frustum);

Bounds unite(const Bounds& a, const Bounds& b);
inline glm::vec3 centre(const Bounds& box) {
  return 0.5f * (box.min + box.max);
}
inline float boundingRadius(const Bounds& box) {
  return 0.5f * glm::length(box.max - box.min);
}

}  // namespace shadelab
