#include "core/scene/billboard_quad.h"

namespace shadelab {

namespace {

// A unit vector perpendicular to `axis`, for a view along it (degenerate).
glm::vec3 anyPerpendicular(glm::vec3 axis) {
  glm::vec3 r = glm::cross(axis, glm::vec3(0.0f, 0.0f, 1.0f));
  if (glm::dot(r, r) < 1e-12f) r = glm::cross(axis, glm::vec3(1.0f, 0.0f, 0.0f));
  return glm::normalize(r);
}

}  // namespace

BillboardPlacement billboardPlacement(const Billboard& billboard, const glm::mat4& instance) {
  return {glm::vec3(instance[3]), billboard.size * glm::vec2(glm::length(glm::vec3(instance[0])),
                                                             glm::length(glm::vec3(instance[1])))};
}

float anchorHeight(BillboardAnchor anchor) {
  return anchor == BillboardAnchor::Bottom ? 0.0f : 0.5f;
}

BillboardAxes billboardAxes(BillboardKind kind, glm::vec3 anchor, glm::vec3 up) {
  if (kind == BillboardKind::Screen) return {};
  if (kind == BillboardKind::Spherical) {
    const float length = glm::length(anchor);
    // The eye at the anchor: face the image plane.
    const glm::vec3 normal = length > 0.0f ? -anchor / length : glm::vec3(0.0f, 0.0f, 1.0f);
    const glm::vec3 r = glm::cross(up, normal);
    const glm::vec3 right = glm::dot(r, r) > 1e-12f ? glm::normalize(r) : anyPerpendicular(normal);
    return {right, glm::cross(normal, right)};
  }
  const glm::vec3 r = glm::cross(up, -anchor);
  return {glm::dot(r, r) > 1e-12f ? glm::normalize(r) : anyPerpendicular(up), up};
}

Mesh billboardQuads(const Billboard& billboard, const glm::mat4& view) {
  const glm::mat4 toWorld = glm::inverse(view);
  const glm::mat3 rotation(view), rotationBack(toWorld);
  const glm::vec3 up = glm::normalize(rotation * billboard.axis);
  const float anchor = anchorHeight(billboard.anchor);
  Mesh mesh;
  mesh.vertices.reserve(4 * billboard.instances.size());
  mesh.indices.reserve(6 * billboard.instances.size());
  for (const glm::mat4& instance : billboard.instances) {
    const BillboardPlacement placement = billboardPlacement(billboard, instance);
    const glm::vec3 anchorEye(view * glm::vec4(placement.position, 1.0f));
    const BillboardAxes axes = billboardAxes(billboard.kind, anchorEye, up);
    const glm::vec3 normal = rotationBack * glm::cross(axes.right, axes.up);
    const glm::vec4 tangent(rotationBack * axes.right, 1.0f);
    const auto first = uint32_t(mesh.vertices.size());
    for (const glm::vec2 corner :
         {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)}) {
      const glm::vec3 eye = anchorEye + axes.right * ((corner.x - 0.5f) * placement.size.x) +
                            axes.up * ((corner.y - anchor) * placement.size.y);
      mesh.vertices.push_back({glm::vec3(toWorld * glm::vec4(eye, 1.0f)), normal, corner, tangent});
    }
    for (const uint32_t corner : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(first + corner);
  }
  return mesh;
}

}  // namespace shadelab
