#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "core/scene/mesh.h"

namespace shadelab {

namespace {

constexpr float kPi = 3.14159265358979323846f;
constexpr float kTwoPi = 2.0f * kPi;

uint32_t checkedVertexCount(uint64_t count) {
  assert(count <= std::numeric_limits<uint32_t>::max());
  return static_cast<uint32_t>(count);
}

float ratio(uint32_t numerator, uint32_t denominator) {
  return static_cast<float>(numerator) / static_cast<float>(denominator);
}

// Reusing angle 0 exactly (not 2*pi) for the last column keeps seam duplicates bit-identical: no
// cracks.
float wrappedAngle(uint32_t step, uint32_t steps) {
  return kTwoPi * ratio(step % steps, steps);
}

// Rows of (columns + 1) vertices, u along a row, v with the row: a,b,c,d is CCW in UV space, hence
// CCW from outside, because every shape keeps (tangent, +v, normal) right-handed.
void appendGridTriangles(std::vector<uint32_t>& indices, uint32_t first, uint32_t columns,
                         uint32_t rows) {
  const uint32_t stride = columns + 1;
  for (uint32_t row = 0; row < rows; ++row) {
    for (uint32_t column = 0; column < columns; ++column) {
      const uint32_t a = first + row * stride + column;
      const uint32_t b = a + 1;
      const uint32_t c = b + stride;
      const uint32_t d = a + stride;
      indices.insert(indices.end(), {a, b, c, a, c, d});
    }
  }
}

// Polar angle theta = pi * (1 - v) from +Y and azimuth phi with phi = 0 facing -Z, so the UV seam
// sits at the back and the middle of a texture faces a camera on +Z.
glm::vec3 sphereDirection(float v, float phi) {
  const float theta = kPi * (1.0f - v);
  return {-std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

// d(direction)/d(phi), normalised; it does not depend on theta, so it is also valid at the poles.
glm::vec4 sphereTangent(float phi) {
  return {-std::cos(phi), 0.0f, std::sin(phi), 1.0f};
}

void appendPoleVertices(Mesh& mesh, float radius, uint32_t slices, bool north) {
  const glm::vec3 normal{0.0f, north ? 1.0f : -1.0f, 0.0f};
  for (uint32_t slice = 0; slice < slices; ++slice) {
    // One pole vertex per slice, so caps are single triangles instead of quads with a zero-length
    // edge.
    const float u = (static_cast<float>(slice) + 0.5f) / static_cast<float>(slices);
    mesh.vertices.push_back(
        {normal * radius, normal, {u, north ? 1.0f : 0.0f}, sphereTangent(kTwoPi * u)});
  }
}

std::vector<glm::vec3> icosahedronCorners() {
  const float golden = (1.0f + std::sqrt(5.0f)) * 0.5f;
  std::vector<glm::vec3> corners;
  // The cyclic permutations of (+-1, +-golden, 0) are the 12 corners, with edge length 2.
  for (const float a : {-1.0f, 1.0f}) {
    for (const float b : {-golden, golden}) {
      corners.emplace_back(a, b, 0.0f);
      corners.emplace_back(0.0f, a, b);
      corners.emplace_back(b, 0.0f, a);
    }
  }
  return corners;
}

// Faces are the triples of mutually adjacent corners (distance 2; the next distance is 2 * golden).
std::vector<uint32_t> icosahedronFaces(const std::vector<glm::vec3>& corners) {
  const auto adjacent = [&](uint32_t i, uint32_t j) {
    const glm::vec3 d = corners[i] - corners[j];
    return glm::dot(d, d) < 4.5f;
  };
  std::vector<uint32_t> faces;
  const auto count = static_cast<uint32_t>(corners.size());
  for (uint32_t i = 0; i < count; ++i) {
    for (uint32_t j = i + 1; j < count; ++j) {
      for (uint32_t k = j + 1; k < count; ++k) {
        if (!adjacent(i, j) || !adjacent(j, k) || !adjacent(i, k)) {
          continue;
        }
        const glm::vec3 a = corners[i];
        const bool outward = glm::dot(glm::cross(corners[j] - a, corners[k] - a), a) > 0.0f;
        faces.insert(faces.end(), {i, outward ? j : k, outward ? k : j});
      }
    }
  }
  assert(faces.size() == 60);
  return faces;
}

uint32_t edgeMidpoint(std::vector<glm::vec3>& points, std::unordered_map<uint64_t, uint32_t>& cache,
                      uint32_t a, uint32_t b) {
  const uint64_t key = (static_cast<uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
  const auto found = cache.find(key);
  if (found != cache.end()) {
    return found->second;
  }
  const auto index = static_cast<uint32_t>(points.size());
  points.push_back(glm::normalize(points[a] + points[b]));
  cache.emplace(key, index);
  return index;
}

// 1-to-4 midpoint split; the edge cache is what keeps vertices shared between neighbours.
std::vector<uint32_t> subdivideOnSphere(std::vector<glm::vec3>& points,
                                        const std::vector<uint32_t>& faces) {
  std::unordered_map<uint64_t, uint32_t> cache;
  std::vector<uint32_t> result;
  result.reserve(faces.size() * 4);
  for (std::size_t f = 0; f + 2 < faces.size(); f += 3) {
    const uint32_t a = faces[f];
    const uint32_t b = faces[f + 1];
    const uint32_t c = faces[f + 2];
    const uint32_t ab = edgeMidpoint(points, cache, a, b);
    const uint32_t bc = edgeMidpoint(points, cache, b, c);
    const uint32_t ca = edgeMidpoint(points, cache, c, a);
    result.insert(result.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
  }
  return result;
}

}  // namespace

glm::vec2 sphericalUv(glm::vec3 direction) {
  float phi = std::atan2(-direction.x, -direction.z);
  if (phi < 0.0f) {
    phi += kTwoPi;
  }
  const float u = std::min(phi / kTwoPi, 1.0f);
  const float v = 1.0f - std::acos(std::clamp(direction.y, -1.0f, 1.0f)) / kPi;
  return {u, v};
}

Mesh makePlane(float size, uint32_t subdivisions) {
  assert(size > 0.0f);
  assert(subdivisions >= 1);
  const uint32_t side = subdivisions + 1;
  Mesh mesh;
  mesh.vertices.reserve(checkedVertexCount(static_cast<uint64_t>(side) * side));
  for (uint32_t row = 0; row < side; ++row) {
    const float v = ratio(row, subdivisions);
    for (uint32_t column = 0; column < side; ++column) {
      const float u = ratio(column, subdivisions);
      // v grows towards -Z so that cross(normal, +u) = -Z is the +v direction (w = +1).
      const glm::vec3 position{(u - 0.5f) * size, 0.0f, (0.5f - v) * size};
      mesh.vertices.push_back({position, {0.0f, 1.0f, 0.0f}, {u, v}, {1.0f, 0.0f, 0.0f, 1.0f}});
    }
  }
  appendGridTriangles(mesh.indices, 0, subdivisions, subdivisions);
  return mesh;
}

Mesh makeBox(glm::vec3 halfExtents) {
  assert(halfExtents.x > 0.0f && halfExtents.y > 0.0f && halfExtents.z > 0.0f);
  struct FaceAxes {
    glm::vec3 normal;
    glm::vec3 tangent;
  };
  // +u runs to the right when each side face is viewed from outside with y up.
  const std::array<FaceAxes, 6> faces{{{{1, 0, 0}, {0, 0, -1}},
                                       {{-1, 0, 0}, {0, 0, 1}},
                                       {{0, 1, 0}, {1, 0, 0}},
                                       {{0, -1, 0}, {1, 0, 0}},
                                       {{0, 0, 1}, {1, 0, 0}},
                                       {{0, 0, -1}, {-1, 0, 0}}}};
  const std::array<glm::vec2, 4> corners{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
  Mesh mesh;
  mesh.vertices.reserve(24);
  mesh.indices.reserve(36);
  for (const FaceAxes& face : faces) {
    const glm::vec3 bitangent = glm::cross(face.normal, face.tangent);
    const auto first = static_cast<uint32_t>(mesh.vertices.size());
    for (const glm::vec2 corner : corners) {
      const glm::vec3 position =
          (face.normal + corner.x * face.tangent + corner.y * bitangent) * halfExtents;
      const glm::vec2 uv = (corner + 1.0f) * 0.5f;
      mesh.vertices.push_back({position, face.normal, uv, glm::vec4(face.tangent, 1.0f)});
    }
    mesh.indices.insert(mesh.indices.end(),
                        {first, first + 1, first + 2, first, first + 2, first + 3});
  }
  return mesh;
}

Mesh makeUvSphere(float radius, uint32_t slices, uint32_t stacks) {
  assert(radius > 0.0f);
  assert(slices >= 3 && stacks >= 2);
  const uint32_t rings = stacks - 1;
  const uint32_t ringStride = slices + 1;
  Mesh mesh;
  mesh.vertices.reserve(
      checkedVertexCount(2ull * slices + static_cast<uint64_t>(rings) * ringStride));

  appendPoleVertices(mesh, radius, slices, false);
  const auto firstRing = static_cast<uint32_t>(mesh.vertices.size());
  for (uint32_t ring = 0; ring < rings; ++ring) {
    const float v = ratio(ring + 1, stacks);
    for (uint32_t slice = 0; slice <= slices; ++slice) {
      const float phi = wrappedAngle(slice, slices);
      const glm::vec3 normal = sphereDirection(v, phi);
      mesh.vertices.push_back(
          {normal * radius, normal, {ratio(slice, slices), v}, sphereTangent(phi)});
    }
  }
  const auto firstNorthPole = static_cast<uint32_t>(mesh.vertices.size());
  appendPoleVertices(mesh, radius, slices, true);

  const uint32_t lastRing = firstRing + (rings - 1) * ringStride;
  for (uint32_t slice = 0; slice < slices; ++slice) {
    mesh.indices.insert(mesh.indices.end(), {slice, firstRing + slice + 1, firstRing + slice});
  }
  appendGridTriangles(mesh.indices, firstRing, slices, rings - 1);
  for (uint32_t slice = 0; slice < slices; ++slice) {
    mesh.indices.insert(mesh.indices.end(),
                        {lastRing + slice, lastRing + slice + 1, firstNorthPole + slice});
  }
  return mesh;
}

Mesh makeIcosphere(float radius, uint32_t subdivisions) {
  assert(radius > 0.0f);
  assert(subdivisions <= 10);
  std::vector<glm::vec3> points = icosahedronCorners();
  std::vector<uint32_t> faces = icosahedronFaces(points);
  for (glm::vec3& point : points) {
    point = glm::normalize(point);
  }
  for (uint32_t level = 0; level < subdivisions; ++level) {
    faces = subdivideOnSphere(points, faces);
  }

  Mesh mesh;
  mesh.vertices.reserve(points.size());
  for (const glm::vec3 point : points) {
    const glm::vec3 normal = glm::normalize(point);
    mesh.vertices.push_back({normal * radius, normal, sphericalUv(normal), glm::vec4(0.0f)});
  }
  mesh.indices = std::move(faces);
  computeTangents(mesh);
  return mesh;
}

Mesh makeTorus(float majorRadius, float minorRadius, uint32_t majorSegments,
               uint32_t minorSegments) {
  assert(minorRadius > 0.0f && majorRadius > minorRadius);
  assert(majorSegments >= 3 && minorSegments >= 3);
  Mesh mesh;
  mesh.vertices.reserve(
      checkedVertexCount(static_cast<uint64_t>(majorSegments + 1) * (minorSegments + 1)));
  for (uint32_t ring = 0; ring <= minorSegments; ++ring) {
    const float psi = wrappedAngle(ring, minorSegments);
    for (uint32_t segment = 0; segment <= majorSegments; ++segment) {
      const float phi = wrappedAngle(segment, majorSegments);
      const glm::vec3 radial{-std::sin(phi), 0.0f, -std::cos(phi)};
      const glm::vec3 normal = std::cos(psi) * radial + glm::vec3(0.0f, std::sin(psi), 0.0f);
      const glm::vec3 position = majorRadius * radial + minorRadius * normal;
      const glm::vec2 uv{ratio(segment, majorSegments), ratio(ring, minorSegments)};
      mesh.vertices.push_back({position, normal, uv, sphereTangent(phi)});
    }
  }
  appendGridTriangles(mesh.indices, 0, majorSegments, minorSegments);
  return mesh;
}

}  // namespace shadelab
