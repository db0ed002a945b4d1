#pragma once
// Exact ray intersections with the procedural shapes, in object space (the
// shape as shape.h builds it, centred on the origin): the true surfaces the
// reference traces instead of their tessellations.
#include <cstdint>
#include <glm/glm.hpp>

#include "core/scene/mesh.h"
#include "core/trace/ray.h"

namespace shadelab {

// An object-space hit: the outward normal (unit) and the texture coordinates
// the shape's mesh gives that point.
struct LocalHit {
  float t = 0.0f;
  glm::vec3 normal{0.0f};
  glm::vec2 uv{0.0f};
  uint32_t triangle = 0;  // meshes: which triangle
};

// Up to two crossings of the ray's line with the surface, in increasing t
// (entry, exit); what the closest-hit and shadow-count queries share.
struct Crossings {
  float t[2] = {0.0f, 0.0f};
  int count = 0;
};

// Sphere |p| = radius: the roots of |o + t d|^2 = r^2, in the cancellation-free
// form q = -(b + sign(b) sqrt(b^2 - ac)), t = q / a and c / q.
Crossings sphereCrossings(const Ray& ray, float radius);
// The square |x|, |z| <= size / 2 in the plane y = 0 (ShapeKind::Plane). A ray
// within 1e-7 of parallel to it (including one lying in it) has no crossing.
Crossings planeCrossings(const Ray& ray, float size);
// The box |x| <= h.x, |y| <= h.y, |z| <= h.z by slabs.
Crossings boxCrossings(const Ray& ray, glm::vec3 halfExtents);

// The first crossing with tMin < t < tMax, with its normal and uv.
bool intersectSphere(const Ray& ray, float radius, float tMin, float tMax, LocalHit& hit);
bool intersectPlane(const Ray& ray, float size, float tMin, float tMax, LocalHit& hit);
bool intersectBox(const Ray& ray, glm::vec3 halfExtents, float tMin, float tMax, LocalHit& hit);

// The uv the shape's mesh gives a point of the plane (y = 0) or of the box
// face with outward normal `faceNormal`; linear in the point, so points off
// the surface (a ray footprint's corners) get the uv extended.
glm::vec2 planeUv(glm::vec3 point, float size);
glm::vec2 boxFaceUv(glm::vec3 point, glm::vec3 halfExtents, glm::vec3 faceNormal);
// The uv interpolated at the barycentric coordinates of `point` projected
// onto the plane of triangle abc (extrapolated outside it).
glm::vec2 triangleUv(glm::vec3 point, const Vertex& a, const Vertex& b, const Vertex& c);

// How many crossings lie in tMin < t < tMax.
uint32_t countInRange(const Crossings& crossings, float tMin, float tMax);

}  // namespace shadelab
