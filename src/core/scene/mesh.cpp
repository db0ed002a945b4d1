#include "core/scene/mesh.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <span>

namespace shadelab {

namespace {

const glm::vec3 kFallbackNormal{0.0f, 1.0f, 0.0f};

// Scaling by the largest component first keeps tiny non-zero vectors from underflowing to NaN.
glm::vec3 safeNormalize(glm::vec3 v, glm::vec3 fallback) {
  const float largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  if (!(largest > 0.0f) || !std::isfinite(largest)) {
    return fallback;
  }
  v /= largest;
  return v / std::sqrt(glm::dot(v, v));
}

glm::vec3 anyPerpendicular(glm::vec3 n) {
  const glm::vec3 axis =
      std::abs(n.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 0.0f, 1.0f);
  return glm::normalize(axis - n * glm::dot(n, axis));
}

struct TangentSums {
  std::vector<glm::vec3> alongU;
  std::vector<glm::vec3> alongV;
};

// Lengyel, "Computing Tangent Space Basis Vectors for an Arbitrary Mesh" (2001): solve
// [e1 e2] = [dP/du dP/dv] * [[s1 s2] [t1 t2]] for the two surface derivatives of each triangle.
TangentSums accumulateTriangleTangents(const Mesh& mesh) {
  TangentSums sums{std::vector<glm::vec3>(mesh.vertices.size(), glm::vec3(0.0f)),
                   std::vector<glm::vec3>(mesh.vertices.size(), glm::vec3(0.0f))};
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const uint32_t ia = mesh.indices[i];
    const uint32_t ib = mesh.indices[i + 1];
    const uint32_t ic = mesh.indices[i + 2];
    assert(ia < mesh.vertices.size() && ib < mesh.vertices.size() && ic < mesh.vertices.size());
    const Vertex& a = mesh.vertices[ia];
    const Vertex& b = mesh.vertices[ib];
    const Vertex& c = mesh.vertices[ic];

    const glm::vec3 e1 = b.position - a.position;
    const glm::vec3 e2 = c.position - a.position;
    const glm::vec2 d1 = b.uv - a.uv;
    const glm::vec2 d2 = c.uv - a.uv;
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (det == 0.0f) {
      continue;
    }
    const float r = 1.0f / det;
    const glm::vec3 dpdu = (e1 * d2.y - e2 * d1.y) * r;
    const glm::vec3 dpdv = (e2 * d1.x - e1 * d2.x) * r;
    if (!std::isfinite(glm::dot(dpdu, dpdu)) || !std::isfinite(glm::dot(dpdv, dpdv))) {
      continue;
    }
    for (const uint32_t index : {ia, ib, ic}) {
      sums.alongU[index] += dpdu;
      sums.alongV[index] += dpdv;
    }
  }
  return sums;
}

}  // namespace

void computeNormals(Mesh& mesh) {
  assert(mesh.indices.size() % 3 == 0);
  std::vector<glm::vec3> sums(mesh.vertices.size(), glm::vec3(0.0f));
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const uint32_t ia = mesh.indices[i];
    const uint32_t ib = mesh.indices[i + 1];
    const uint32_t ic = mesh.indices[i + 2];
    assert(ia < sums.size() && ib < sums.size() && ic < sums.size());
    const glm::vec3 a = mesh.vertices[ia].position;
    // The unnormalised cross product has length 2 * area, which is what weights by area.
    const glm::vec3 face =
        glm::cross(mesh.vertices[ib].position - a, mesh.vertices[ic].position - a);
    sums[ia] += face;
    sums[ib] += face;
    sums[ic] += face;
  }
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    mesh.vertices[v].normal = safeNormalize(sums[v], kFallbackNormal);
  }
}

void computeTangents(Mesh& mesh) {
  assert(mesh.indices.size() % 3 == 0);
  const TangentSums sums = accumulateTriangleTangents(mesh);
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    Vertex& vertex = mesh.vertices[v];
    const glm::vec3 n = safeNormalize(vertex.normal, kFallbackNormal);
    const glm::vec3 projected = sums.alongU[v] - n * glm::dot(n, sums.alongU[v]);
    glm::vec3 t = safeNormalize(projected, glm::vec3(0.0f));
    if (t == glm::vec3(0.0f)) {
      t = anyPerpendicular(n);
    }
    // Mirrored UVs make dP/dv point against cross(n, t); the shader flips the bitangent by w.
    const float w = glm::dot(glm::cross(n, t), sums.alongV[v]) < 0.0f ? -1.0f : 1.0f;
    vertex.tangent = glm::vec4(t, w);
  }
}

namespace {

// Faces within this much of the crease angle still count as within it, so the two triangles of a
// planar quad, whose normals differ only by rounding, stay one smooth group even at crease 0.
constexpr float kCreaseSlackRadians = 1e-3f;

struct FaceNormals {
  std::vector<glm::vec3> weighted;  // cross product: length 2 * area, the area weight
  std::vector<glm::vec3> unit;      // zero for zero-area (degenerate) triangles
};

FaceNormals faceNormals(const Mesh& mesh) {
  FaceNormals faces;
  faces.weighted.reserve(mesh.triangleCount());
  faces.unit.reserve(mesh.triangleCount());
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const glm::vec3 a = mesh.vertices[mesh.indices[i]].position;
    const glm::vec3 b = mesh.vertices[mesh.indices[i + 1]].position;
    const glm::vec3 c = mesh.vertices[mesh.indices[i + 2]].position;
    const glm::vec3 face = glm::cross(b - a, c - a);
    faces.weighted.push_back(face);
    faces.unit.push_back(safeNormalize(face, glm::vec3(0.0f)));
  }
  return faces;
}

// Bit patterns give a strict order even for NaN; adding +0 first turns -0 into +0 so the two
// zeros, which compare equal, land in one group.
std::array<uint32_t, 3> positionKey(glm::vec3 p) {
  return {std::bit_cast<uint32_t>(p.x + 0.0f), std::bit_cast<uint32_t>(p.y + 0.0f),
          std::bit_cast<uint32_t>(p.z + 0.0f)};
}

// Triangle corners (3 * triangle + k) listed per distinct vertex position, in triangle order.
struct PositionGroups {
  std::vector<uint32_t> offsets;  // group g owns corners[offsets[g] .. offsets[g + 1])
  std::vector<uint32_t> corners;
};

PositionGroups groupCornersByPosition(const Mesh& mesh) {
  std::vector<uint32_t> order(mesh.vertices.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    return positionKey(mesh.vertices[a].position) < positionKey(mesh.vertices[b].position);
  });
  std::vector<uint32_t> groupOf(mesh.vertices.size());
  uint32_t groupCount = 0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const bool samePosition = i > 0 && positionKey(mesh.vertices[order[i]].position) ==
                                           positionKey(mesh.vertices[order[i - 1]].position);
    groupCount += samePosition ? 0 : 1;
    groupOf[order[i]] = groupCount - 1;
  }
  // Counting sort of the corners by group keeps each group's corners in triangle order.
  PositionGroups groups{std::vector<uint32_t>(groupCount + 1, 0u),
                        std::vector<uint32_t>(mesh.indices.size())};
  for (const uint32_t index : mesh.indices) {
    ++groups.offsets[groupOf[index] + 1];
  }
  std::partial_sum(groups.offsets.begin(), groups.offsets.end(), groups.offsets.begin());
  std::vector<uint32_t> next(groups.offsets.begin(), groups.offsets.end() - 1);
  for (std::size_t corner = 0; corner < mesh.indices.size(); ++corner) {
    groups.corners[next[groupOf[mesh.indices[corner]]]++] = static_cast<uint32_t>(corner);
  }
  return groups;
}

// One vertex's normal for one smooth group: the vertex itself, or a copy appended for the split.
struct Claim {
  uint32_t original;
  glm::vec3 normal;
  uint32_t index;
};

class CreaseSplitter {
 public:
  CreaseSplitter(Mesh& mesh, const FaceNormals& faces, float cosLimit)
      : mesh_(mesh), faces_(faces), cosLimit_(cosLimit), claimed_(mesh.vertices.size(), false) {}

  void splitGroup(std::span<const uint32_t> corners) {
    claims_.clear();
    groupFaces_.clear();
    for (const uint32_t corner : corners) {
      if (groupFaces_.empty() || groupFaces_.back() != corner / 3) {
        groupFaces_.push_back(corner / 3);
      }
    }
    for (const uint32_t corner : corners) {
      if (!isDegenerate(corner / 3)) {
        mesh_.indices[corner] = claim(mesh_.indices[corner], smoothNormal(corner / 3));
      }
    }
    // Zero-area triangles have no normal to compare, so they join a group already made.
    for (const uint32_t corner : corners) {
      if (isDegenerate(corner / 3)) {
        mesh_.indices[corner] = claimAny(mesh_.indices[corner]);
      }
    }
  }

 private:
  bool isDegenerate(uint32_t face) const { return faces_.unit[face] == glm::vec3(0.0f); }

  // Area-weighted sum of the faces at this position whose normals lie within the crease angle.
  glm::vec3 smoothNormal(uint32_t face) const {
    glm::vec3 sum(0.0f);
    for (const uint32_t other : groupFaces_) {
      if (glm::dot(faces_.unit[face], faces_.unit[other]) >= cosLimit_) {
        sum += faces_.weighted[other];
      }
    }
    return safeNormalize(sum, kFallbackNormal);
  }

  uint32_t claim(uint32_t original, glm::vec3 normal) {
    for (const Claim& existing : claims_) {
      if (existing.original == original && existing.normal == normal) {
        return existing.index;
      }
    }
    uint32_t index = original;
    if (claimed_[original]) {
      assert(mesh_.vertices.size() < std::numeric_limits<uint32_t>::max());
      const Vertex copy = mesh_.vertices[original];
      index = static_cast<uint32_t>(mesh_.vertices.size());
      mesh_.vertices.push_back(copy);
    }
    claimed_[original] = true;
    mesh_.vertices[index].normal = normal;
    claims_.push_back({original, normal, index});
    return index;
  }

  // A vertex touched only by zero-area triangles takes the normal of every face at its position.
  uint32_t claimAny(uint32_t original) {
    for (const Claim& existing : claims_) {
      if (existing.original == original) {
        return existing.index;
      }
    }
    glm::vec3 sum(0.0f);
    for (const uint32_t face : groupFaces_) {
      sum += faces_.weighted[face];
    }
    return claim(original, safeNormalize(sum, kFallbackNormal));
  }

  Mesh& mesh_;
  const FaceNormals& faces_;
  float cosLimit_;
  std::vector<bool> claimed_;
  std::vector<Claim> claims_;
  std::vector<uint32_t> groupFaces_;
};

}  // namespace

void computeCreaseNormals(Mesh& mesh, float creaseAngleDegrees) {
  assert(mesh.indices.size() % 3 == 0);
  assert(!std::isnan(creaseAngleDegrees));
  const bool hadTangents =
      std::any_of(mesh.vertices.begin(), mesh.vertices.end(),
                  [](const Vertex& v) { return v.tangent != glm::vec4(0.0f); });
  const float limit =
      std::clamp(creaseAngleDegrees, 0.0f, 180.0f) * std::numbers::pi_v<float> / 180.0f +
      kCreaseSlackRadians;
  // At 180 degrees even exactly opposite faces (cosine -1 give or take rounding) are smoothed.
  const float cosLimit = limit >= std::numbers::pi_v<float> ? -2.0f : std::cos(limit);

  for (Vertex& vertex : mesh.vertices) {
    vertex.normal = kFallbackNormal;  // what unreferenced vertices keep, as in computeNormals
  }
  const FaceNormals faces = faceNormals(mesh);
  const PositionGroups groups = groupCornersByPosition(mesh);
  CreaseSplitter splitter(mesh, faces, cosLimit);
  for (std::size_t g = 0; g + 1 < groups.offsets.size(); ++g) {
    splitter.splitGroup(std::span(groups.corners)
                            .subspan(groups.offsets[g], groups.offsets[g + 1] - groups.offsets[g]));
  }
  if (hadTangents) {
    computeTangents(mesh);
  }
}

Bounds computeBounds(const Mesh& mesh) {
  if (mesh.vertices.empty()) {
    return Bounds{};
  }
  Bounds bounds{mesh.vertices.front().position, mesh.vertices.front().position};
  for (const Vertex& vertex : mesh.vertices) {
    bounds.min = glm::min(bounds.min, vertex.position);
    bounds.max = glm::max(bounds.max, vertex.position);
  }
  return bounds;
}

void reverseWinding(Mesh& mesh) {
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
}

void appendMesh(Mesh& mesh, const Mesh& other) {
  if (&mesh == &other) {
    const Mesh copy = other;  // inserting a vector's own range into itself is undefined
    appendMesh(mesh, copy);
    return;
  }
  assert(mesh.vertices.size() + other.vertices.size() <= std::numeric_limits<uint32_t>::max());
  const auto offset = static_cast<uint32_t>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), other.vertices.begin(), other.vertices.end());
  mesh.indices.reserve(mesh.indices.size() + other.indices.size());
  for (const uint32_t index : other.indices) {
    mesh.indices.push_back(index + offset);
  }
}

}  // namespace shadelab
