#pragma once
// A bounding volume hierarchy over one mesh's triangles, built once with the
// surface area heuristic, for the CPU ray tracer: closest hit (Moller-Trumbore
// barycentrics) and a count of every hit along a segment (shadow rays).
#include <cstdint>
#include <functional>
#include <vector>

#include "core/scene/mesh.h"
#include "core/trace/ray.h"

namespace shadelab {

struct TriangleHit {
  float t = 0.0f;
  float u = 0.0f, v = 0.0f;  // barycentrics of vertices 1 and 2; vertex 0 has 1 - u - v
  uint32_t triangle = 0;     // index into the mesh's triangles (indices / 3)
};

// Moller-Trumbore for the triangle (v0, v0 + edge1, v0 + edge2), both sides.
// A ray within 1e-6 radians of the triangle's plane (parallel, or lying in
// it) misses: there the determinant is rounding noise. Hits need
// tMin < t < tMax.
bool intersectTriangle(const Ray& ray, glm::vec3 v0, glm::vec3 edge1, glm::vec3 edge2, float tMin,
                       float tMax, TriangleHit& hit);

// Slab test; `inverseDirection` is 1 / direction per component (infinite
// for zero components). Returns whether [tMin, tMax] overlaps the box.
bool intersectBounds(const Bounds& box, const Ray& ray, glm::vec3 inverseDirection, float tMin,
                     float tMax, float& tEntry);

class Bvh {
 public:
  explicit Bvh(const Mesh& mesh);

  // Closest hit with tMin < t < tMax. With `cullFacing` +1, triangles whose
  // face normal edge1 x edge2 points along the ray (back faces) are passed;
  // -1 passes those facing the ray instead (a mirrored mesh, wound the
  // other way); 0 culls nothing.
  bool intersect(const Ray& ray, float tMin, float tMax, TriangleHit& hit,
                 float cullFacing = 0.0f) const;
  // Number of triangles hit with tMin < t < tMax.
  uint32_t countHits(const Ray& ray, float tMin, float tMax) const;
  // Calls visit(n) for each triangle hit with tMin < t < tMax, n its face
  // normal edge1 x edge2 (not normalised), in no particular order.
  void forEachHitNormal(const Ray& ray, float tMin, float tMax,
                        const std::function<void(glm::vec3)>& visit) const;

  Bounds bounds() const;
  uint32_t depth() const { return depth_; }
  uint32_t largestLeaf() const;

 private:
  struct Node {
    Bounds box;
    uint32_t first = 0;  // leaf: first entry of triangles_; inner: index of the left child
    uint32_t count = 0;  // leaf: triangle count; inner: 0 (the right child is first + 1)
  };
  struct Triangle {
    glm::vec3 v0, edge1, edge2;
    float normalLength2;  // |edge1 x edge2|^2, for the parallel test
    uint32_t index;
  };

  template <typename Visit>
  void visitHits(const Ray& ray, float tMin, float tMax, Visit&& visit) const;
  struct BuildInput;
  void build(uint32_t node, BuildInput& input, uint32_t begin, uint32_t end, uint32_t level);

  std::vector<Node> nodes_;
  std::vector<Triangle> triangles_;  // in leaf order
  uint32_t depth_ = 0;
};

}  // namespace shadelab
