#include "core/scene/uv_mapping.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace shadelab {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

float fitted(float value, float low, float high) {
  return high > low ? (value - low) / (high - low) : 0.5f;
}

glm::vec2 boxUv(glm::vec3 p, glm::vec3 n, const Bounds& b) {
  glm::vec3 a = glm::abs(n);
  if (a.x >= a.y && a.x >= a.z)  // +x faces look along -x: u runs toward -z
    return {n.x >= 0.0f ? fitted(-p.z, -b.max.z, -b.min.z) : fitted(p.z, b.min.z, b.max.z),
            fitted(p.y, b.min.y, b.max.y)};
  if (a.y >= a.z)  // +y seen from above: u along +x, v along -z
    return {fitted(p.x, b.min.x, b.max.x),
            n.y >= 0.0f ? fitted(-p.z, -b.max.z, -b.min.z) : fitted(p.z, b.min.z, b.max.z)};
  return {n.z >= 0.0f ? fitted(p.x, b.min.x, b.max.x) : fitted(-p.x, -b.max.x, -b.min.x),
          fitted(p.y, b.min.y, b.max.y)};
}

}  // namespace

glm::vec2 projectUv(UvProjection projection, glm::vec3 p, glm::vec3 normal, const Bounds& b) {
  glm::vec3 c = 0.5f * (b.min + b.max);
  switch (projection) {
    case UvProjection::Mesh:
      return {0.0f, 0.0f};
    case UvProjection::Planar:
      return {fitted(p.x, b.min.x, b.max.x), fitted(p.y, b.min.y, b.max.y)};
    case UvProjection::Cylindrical:
      return {0.5f + std::atan2(p.x - c.x, p.z - c.z) / (2.0f * kPi),
              fitted(p.y, b.min.y, b.max.y)};
    case UvProjection::Spherical: {
      glm::vec3 d = p - c;
      float length = glm::length(d);
      float latitude = length > 0.0f ? std::asin(std::clamp(d.y / length, -1.0f, 1.0f)) : 0.0f;
      return {0.5f + std::atan2(d.x, d.z) / (2.0f * kPi), 0.5f + latitude / kPi};
    }
    case UvProjection::Box:
      return boxUv(p, normal, b);
  }
  return {0.0f, 0.0f};
}

void applyUvProjection(Mesh& mesh, UvProjection projection) {
  if (mesh.vertices.empty()) return;
  applyUvProjection(mesh, projection, computeBounds(mesh));
}

void applyUvProjection(Mesh& mesh, UvProjection projection, const Bounds& bounds) {
  if (projection == UvProjection::Mesh || mesh.vertices.empty()) return;
  for (Vertex& vertex : mesh.vertices)
    vertex.uv = projectUv(projection, vertex.position, vertex.normal, bounds);
  computeTangents(mesh);
}

}  // namespace shadelab
