#include "core/trace/bvh.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>

namespace shadelab {
namespace {

constexpr uint32_t kBins = 12;
constexpr uint32_t kMaxLeafSize = 8;
// Below this depth SAH picks splits; beyond it, median splits (depth at most
// this + log2 n) keep the traversal stack bounded on degenerate input.
constexpr uint32_t kMaxSahDepth = 40;
constexpr uint32_t kStackSize = 96;
// Relative cost of visiting a node against intersecting one triangle.
constexpr float kTraversalCost = 1.0f;

Bounds emptyBounds() {
  constexpr float big = std::numeric_limits<float>::max();
  return {glm::vec3(big), glm::vec3(-big)};
}

void grow(Bounds& box, glm::vec3 point) {
  box.min = glm::min(box.min, point);
  box.max = glm::max(box.max, point);
}

void grow(Bounds& box, const Bounds& other) {
  box.min = glm::min(box.min, other.min);
  box.max = glm::max(box.max, other.max);
}

float surfaceArea(const Bounds& box) {
  const glm::vec3 d = glm::max(box.max - box.min, glm::vec3(0.0f));
  return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
}

// Moller-Trumbore with the squared lengths the parallel test needs passed in
// (the BVH precomputes |e1 x e2|^2 per triangle and |d|^2 per ray).
inline bool hitTriangle(const Ray& ray, float directionLength2, glm::vec3 v0, glm::vec3 edge1,
                        glm::vec3 edge2, float normalLength2, float tMin, float tMax,
                        TriangleHit& hit) {
  const glm::vec3 p = glm::cross(ray.direction, edge2);
  const float det = glm::dot(edge1, p);
  // det = -d.(e1 x e2): against |d| |e1 x e2| it is the sine of the angle
  // between the ray and the plane; NaN fails the test too.
  if (!(det * det > 1e-12f * directionLength2 * normalLength2)) return false;
  const float inverseDet = 1.0f / det;
  const glm::vec3 s = ray.origin - v0;
  const float u = glm::dot(s, p) * inverseDet;
  if (u < 0.0f || u > 1.0f) return false;
  const glm::vec3 q = glm::cross(s, edge1);
  const float v = glm::dot(ray.direction, q) * inverseDet;
  if (v < 0.0f || u + v > 1.0f) return false;
  const float t = glm::dot(edge2, q) * inverseDet;
  if (!(t > tMin && t < tMax)) return false;
  hit.t = t;
  hit.u = u;
  hit.v = v;
  return true;
}

// fmin/fmax semantics (a NaN operand is ignored) without the libm calls.
inline float minIgnoringNan(float a, float b) {
  return a < b || b != b ? a : b;
}
inline float maxIgnoringNan(float a, float b) {
  return a > b || b != b ? a : b;
}

float squaredLength(glm::vec3 v) {
  return glm::dot(v, v);
}

struct SahSplit {
  int axis = -1;                                   // -1: no split separates anything
  uint32_t bin = 0;                                // the left side holds bins 0..bin
  float cost = std::numeric_limits<float>::max();  // sum of area * count over both sides
};

// Binned SAH (kBins bins per axis on the centroids' extent).
SahSplit bestSahSplit(const std::vector<uint32_t>& order, const std::vector<glm::vec3>& centroids,
                      const std::vector<Bounds>& boxes, uint32_t begin, uint32_t end,
                      const Bounds& centroidBox) {
  SahSplit best;
  const uint32_t count = end - begin;
  const glm::vec3 extent = centroidBox.max - centroidBox.min;
  for (int axis = 0; axis < 3; ++axis) {
    if (!(extent[axis] > 0.0f)) continue;
    std::array<Bounds, kBins> bins;
    bins.fill(emptyBounds());
    std::array<uint32_t, kBins> binCounts{};
    const float scale = float(kBins) / extent[axis];
    for (uint32_t i = begin; i < end; ++i) {
      const uint32_t index = order[i];
      const uint32_t bin =
          std::min(kBins - 1, uint32_t((centroids[index][axis] - centroidBox.min[axis]) * scale));
      ++binCounts[bin];
      grow(bins[bin], boxes[index]);
    }
    // Sweep from the right to get each split's right-hand side, then from the left.
    std::array<float, kBins> rightCost{};
    Bounds right = emptyBounds();
    uint32_t rightCount = 0;
    for (uint32_t b = kBins - 1; b > 0; --b) {
      grow(right, bins[b]);
      rightCount += binCounts[b];
      rightCost[b] = rightCount ? surfaceArea(right) * float(rightCount) : 0.0f;
    }
    Bounds left = emptyBounds();
    uint32_t leftCount = 0;
    for (uint32_t b = 0; b + 1 < kBins; ++b) {
      grow(left, bins[b]);
      leftCount += binCounts[b];
      if (leftCount == 0 || leftCount == count) continue;
      const float cost = surfaceArea(left) * float(leftCount) + rightCost[b + 1];
      if (cost < best.cost) best = {axis, b, cost};
    }
  }
  return best;
}

}  // namespace

bool intersectTriangle(const Ray& ray, glm::vec3 v0, glm::vec3 edge1, glm::vec3 edge2, float tMin,
                       float tMax, TriangleHit& hit) {
  return hitTriangle(ray, squaredLength(ray.direction), v0, edge1, edge2,
                     squaredLength(glm::cross(edge1, edge2)), tMin, tMax, hit);
}

bool intersectBounds(const Bounds& box, const Ray& ray, glm::vec3 inverseDirection, float tMin,
                     float tMax, float& tEntry) {
  for (int axis = 0; axis < 3; ++axis) {
    const float t0 = (box.min[axis] - ray.origin[axis]) * inverseDirection[axis];
    const float t1 = (box.max[axis] - ray.origin[axis]) * inverseDirection[axis];
    // The NaN of 0 * infinity (a ray in a slab's plane) is ignored, leaving
    // that axis unconstrained.
    tMin = maxIgnoringNan(tMin, minIgnoringNan(t0, t1));
    tMax = minIgnoringNan(tMax, maxIgnoringNan(t0, t1));
  }
  tEntry = tMin;
  return tMin <= tMax;
}

struct Bvh::BuildInput {
  std::vector<uint32_t> order;  // triangle indices, partitioned in place
  std::vector<glm::vec3> centroids;
  std::vector<Bounds> boxes;
};

Bvh::Bvh(const Mesh& mesh) {
  const uint32_t count = uint32_t(mesh.triangleCount());
  BuildInput input;
  input.order.resize(count);
  input.centroids.resize(count);
  input.boxes.resize(count);
  for (uint32_t i = 0; i < count; ++i) {
    input.order[i] = i;
    Bounds box = emptyBounds();
    for (int corner = 0; corner < 3; ++corner)
      grow(box, mesh.vertices[mesh.indices[3 * i + corner]].position);
    input.boxes[i] = box;
    input.centroids[i] = 0.5f * (box.min + box.max);
  }
  nodes_.reserve(count > 0 ? 2 * count : 1);
  nodes_.push_back({});
  build(0, input, 0, count, 1);
  triangles_.reserve(count);
  for (uint32_t index : input.order) {
    const glm::vec3 a = mesh.vertices[mesh.indices[3 * index]].position;
    const glm::vec3 b = mesh.vertices[mesh.indices[3 * index + 1]].position;
    const glm::vec3 c = mesh.vertices[mesh.indices[3 * index + 2]].position;
    triangles_.push_back({a, b - a, c - a, squaredLength(glm::cross(b - a, c - a)), index});
  }
}

// A node becomes a leaf when splitting costs more than intersecting its triangles, unless it
// holds more than kMaxLeafSize. Degenerate splits fall back to the median.
void Bvh::build(uint32_t node, BuildInput& input, uint32_t begin, uint32_t end, uint32_t level) {
  depth_ = std::max(depth_, level);
  Bounds box = emptyBounds(), centroidBox = emptyBounds();
  for (uint32_t i = begin; i < end; ++i) {
    grow(box, input.boxes[input.order[i]]);
    grow(centroidBox, input.centroids[input.order[i]]);
  }
  nodes_[node] = {box, begin, end - begin};
  const uint32_t count = end - begin;
  if (count <= 1) return;

  const glm::vec3 extent = centroidBox.max - centroidBox.min;
  const SahSplit best =
      bestSahSplit(input.order, input.centroids, input.boxes, begin, end, centroidBox);
  const float bestCost = best.cost;
  const int bestAxis = best.axis;
  const uint32_t bestBin = best.bin;
  const float parentArea = std::max(surfaceArea(box), 1e-30f);
  const float splitCost = kTraversalCost + bestCost / parentArea;
  if (count <= kMaxLeafSize && (bestAxis < 0 || splitCost >= float(count))) return;

  uint32_t middle = begin;
  if (bestAxis >= 0) {
    const float scale = float(kBins) / extent[bestAxis];
    auto* split =
        std::partition(input.order.data() + begin, input.order.data() + end, [&](uint32_t index) {
          float offset = (input.centroids[index][bestAxis] - centroidBox.min[bestAxis]) * scale;
          return std::min(kBins - 1, uint32_t(offset)) <= bestBin;
        });
    middle = uint32_t(split - input.order.data());
  }
  if (middle == begin || middle == end || level >= kMaxSahDepth) {
    // All centroids coincide (or binning failed): split the list in half.
    const int axis = int(std::max_element(&extent.x, &extent.x + 3) - &extent.x);
    middle = begin + count / 2;
    std::nth_element(input.order.begin() + begin, input.order.begin() + middle,
                     input.order.begin() + end, [&](uint32_t a, uint32_t b) {
                       float ca = input.centroids[a][axis], cb = input.centroids[b][axis];
                       return ca < cb || (ca == cb && a < b);
                     });
  }
  const uint32_t leftChild = uint32_t(nodes_.size());
  nodes_.push_back({});
  nodes_.push_back({});
  nodes_[node].first = leftChild;
  nodes_[node].count = 0;
  build(leftChild, input, begin, middle, level + 1);
  build(leftChild + 1, input, middle, end, level + 1);
}

Bounds Bvh::bounds() const {
  return triangles_.empty() ? Bounds{} : nodes_[0].box;
}

uint32_t Bvh::largestLeaf() const {
  uint32_t largest = 0;
  for (const Node& node : nodes_) largest = std::max(largest, node.count);
  return largest;
}

bool Bvh::intersect(const Ray& ray, float tMin, float tMax, TriangleHit& hit,
                    float cullFacing) const {
  if (triangles_.empty()) return false;
  const glm::vec3 inverse = 1.0f / ray.direction;
  const float directionLength2 = squaredLength(ray.direction);
  bool found = false;
  std::array<uint32_t, kStackSize> stack;
  uint32_t top = 0;
  stack[top++] = 0;
  float tEntry;
  if (!intersectBounds(nodes_[0].box, ray, inverse, tMin, tMax, tEntry)) return false;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (node.count > 0) {
      for (uint32_t i = node.first; i < node.first + node.count; ++i) {
        const Triangle& tri = triangles_[i];
        if (cullFacing != 0.0f &&
            cullFacing * glm::dot(ray.direction, glm::cross(tri.edge1, tri.edge2)) > 0.0f)
          continue;
        if (hitTriangle(ray, directionLength2, tri.v0, tri.edge1, tri.edge2, tri.normalLength2,
                        tMin, tMax, hit)) {
          hit.triangle = tri.index;
          tMax = hit.t;
          found = true;
        }
      }
      continue;
    }
    // Visit the nearer child first so tMax shrinks early; push it last.
    float tLeft, tRight;
    const bool left = intersectBounds(nodes_[node.first].box, ray, inverse, tMin, tMax, tLeft);
    const bool right =
        intersectBounds(nodes_[node.first + 1].box, ray, inverse, tMin, tMax, tRight);
    assert(top + 2 <= kStackSize);
    if (left && right) {
      const bool leftFirst = tLeft <= tRight;
      stack[top++] = leftFirst ? node.first + 1 : node.first;
      stack[top++] = leftFirst ? node.first : node.first + 1;
    } else if (left) {
      stack[top++] = node.first;
    } else if (right) {
      stack[top++] = node.first + 1;
    }
  }
  return found;
}

template <typename Visit>
void Bvh::visitHits(const Ray& ray, float tMin, float tMax, Visit&& visit) const {
  if (triangles_.empty()) return;
  const glm::vec3 inverse = 1.0f / ray.direction;
  const float directionLength2 = squaredLength(ray.direction);
  std::array<uint32_t, kStackSize> stack;
  uint32_t top = 0;
  stack[top++] = 0;
  TriangleHit scratch;
  float tEntry;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!intersectBounds(node.box, ray, inverse, tMin, tMax, tEntry)) continue;
    if (node.count > 0) {
      for (uint32_t i = node.first; i < node.first + node.count; ++i) {
        const Triangle& tri = triangles_[i];
        if (hitTriangle(ray, directionLength2, tri.v0, tri.edge1, tri.edge2, tri.normalLength2,
                        tMin, tMax, scratch))
          visit(tri);
      }
      continue;
    }
    assert(top + 2 <= kStackSize);
    stack[top++] = node.first;
    stack[top++] = node.first + 1;
  }
}

uint32_t Bvh::countHits(const Ray& ray, float tMin, float tMax) const {
  uint32_t hits = 0;
  visitHits(ray, tMin, tMax, [&](const Triangle&) { ++hits; });
  return hits;
}

void Bvh::forEachHitNormal(const Ray& ray, float tMin, float tMax,
                           const std::function<void(glm::vec3)>& visit) const {
  visitHits(ray, tMin, tMax, [&](const Triangle& tri) { visit(glm::cross(tri.edge1, tri.edge2)); });
}

}  // namespace shadelab
