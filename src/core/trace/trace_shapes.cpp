#include "core/trace/trace_shapes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/scene/mesh.h"

namespace shadelab {
namespace {

// Face frames as makeBox lays them out (+u to the right seen from outside,
// y up), so a box hit has the uv its mesh would interpolate there.
struct BoxFace {
  glm::vec3 normal, tangent;
};
constexpr BoxFace kBoxFaces[6] = {{{1, 0, 0}, {0, 0, -1}}, {{-1, 0, 0}, {0, 0, 1}},
                                  {{0, 1, 0}, {1, 0, 0}},  {{0, -1, 0}, {1, 0, 0}},
                                  {{0, 0, 1}, {1, 0, 0}},  {{0, 0, -1}, {-1, 0, 0}}};

// The outward normal of the box face a point lies on: the axis where it is
// relatively closest to the face.
int boxFaceAt(glm::vec3 point, glm::vec3 halfExtents) {
  const glm::vec3 relative = glm::abs(point) / halfExtents;
  int axis = 0;
  if (relative.y > relative[axis]) axis = 1;
  if (relative.z > relative[axis]) axis = 2;
  return 2 * axis + (point[axis] < 0.0f ? 1 : 0);
}

bool firstInRange(const Crossings& crossings, float tMin, float tMax, float& t) {
  for (int i = 0; i < crossings.count; ++i) {
    if (crossings.t[i] > tMin && crossings.t[i] < tMax) {
      t = crossings.t[i];
      return true;
    }
  }
  return false;
}

}  // namespace

Crossings sphereCrossings(const Ray& ray, float radius) {
  Crossings result;
  const float a = glm::dot(ray.direction, ray.direction);
  const float b = glm::dot(ray.origin, ray.direction);
  const float c = glm::dot(ray.origin, ray.origin) - radius * radius;
  const float discriminant = b * b - a * c;
  if (!(a > 0.0f) || !(discriminant >= 0.0f)) return result;
  const float q = -(b + std::copysign(std::sqrt(discriminant), b));
  if (q == 0.0f) {  // b = c = 0: an origin on the sphere moving along it, the double root 0
    result.t[0] = 0.0f;
    result.count = 1;
    return result;
  }
  const float t0 = q / a, t1 = c / q;
  result.t[0] = std::min(t0, t1);
  result.t[1] = std::max(t0, t1);
  result.count = 2;
  return result;
}

Crossings planeCrossings(const Ray& ray, float size) {
  Crossings result;
  const float length = glm::length(ray.direction);
  if (!(std::abs(ray.direction.y) > 1e-7f * length)) return result;
  const float t = -ray.origin.y / ray.direction.y;
  const glm::vec3 point = ray.at(t);
  const float half = 0.5f * size;
  if (std::abs(point.x) <= half && std::abs(point.z) <= half) {
    result.t[0] = t;
    result.count = 1;
  }
  return result;
}

Crossings boxCrossings(const Ray& ray, glm::vec3 halfExtents) {
  Crossings result;
  float tNear = -std::numeric_limits<float>::infinity();
  float tFar = std::numeric_limits<float>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    const float inverse = 1.0f / ray.direction[axis];
    const float t0 = (-halfExtents[axis] - ray.origin[axis]) * inverse;
    const float t1 = (halfExtents[axis] - ray.origin[axis]) * inverse;
    // fmin/fmax ignore the NaN of a ray lying in a face's plane.
    tNear = std::fmax(tNear, std::fmin(t0, t1));
    tFar = std::fmin(tFar, std::fmax(t0, t1));
  }
  if (!(tNear <= tFar) || !std::isfinite(tNear) || !std::isfinite(tFar)) return result;
  result.t[0] = tNear;
  result.t[1] = tFar;
  result.count = 2;
  return result;
}

uint32_t countInRange(const Crossings& crossings, float tMin, float tMax) {
  uint32_t count = 0;
  for (int i = 0; i < crossings.count; ++i) count += crossings.t[i] > tMin && crossings.t[i] < tMax;
  return count;
}

bool intersectSphere(const Ray& ray, float radius, float tMin, float tMax, LocalHit& hit) {
  float t;
  if (!firstInRange(sphereCrossings(ray, radius), tMin, tMax, t)) return false;
  hit.t = t;
  hit.normal = ray.at(t) / radius;
  // Renormalise: |p| is r only up to rounding, and the uv wants a unit vector.
  hit.normal /= glm::length(hit.normal);
  hit.uv = sphericalUv(hit.normal);
  return true;
}

bool intersectPlane(const Ray& ray, float size, float tMin, float tMax, LocalHit& hit) {
  float t;
  if (!firstInRange(planeCrossings(ray, size), tMin, tMax, t)) return false;
  const glm::vec3 point = ray.at(t);
  hit.t = t;
  hit.normal = {0.0f, 1.0f, 0.0f};
  hit.uv = planeUv(point, size);
  return true;
}

bool intersectBox(const Ray& ray, glm::vec3 halfExtents, float tMin, float tMax, LocalHit& hit) {
  float t;
  if (!firstInRange(boxCrossings(ray, halfExtents), tMin, tMax, t)) return false;
  const glm::vec3 point = ray.at(t);
  hit.t = t;
  hit.normal = kBoxFaces[boxFaceAt(point, halfExtents)].normal;
  hit.uv = boxFaceUv(point, halfExtents, hit.normal);
  return true;
}

glm::vec2 planeUv(glm::vec3 point, float size) {
  return {point.x / size + 0.5f, 0.5f - point.z / size};  // as makePlane
}

glm::vec2 triangleUv(glm::vec3 point, const Vertex& a, const Vertex& b, const Vertex& c) {
  const glm::vec3 e0 = b.position - a.position, e1 = c.position - a.position;
  const glm::vec3 d = point - a.position;
  const float d00 = glm::dot(e0, e0), d01 = glm::dot(e0, e1), d11 = glm::dot(e1, e1);
  const float denominator = d00 * d11 - d01 * d01;
  if (!(std::abs(denominator) > 0.0f)) return a.uv;
  const float v = (d11 * glm::dot(d, e0) - d01 * glm::dot(d, e1)) / denominator;
  const float w = (d00 * glm::dot(d, e1) - d01 * glm::dot(d, e0)) / denominator;
  return (1.0f - v - w) * a.uv + v * b.uv + w * c.uv;
}

glm::vec2 boxFaceUv(glm::vec3 point, glm::vec3 halfExtents, glm::vec3 faceNormal) {
  const BoxFace* face = &kBoxFaces[0];
  for (const BoxFace& candidate : kBoxFaces)
    if (candidate.normal == faceNormal) face = &candidate;
  const glm::vec3 bitangent = glm::cross(face->normal, face->tangent);
  const glm::vec3 unit = point / halfExtents;
  return (glm::vec2(glm::dot(unit, face->tangent), glm::dot(unit, bitangent)) + 1.0f) * 0.5f;
}

}  // namespace shadelab
