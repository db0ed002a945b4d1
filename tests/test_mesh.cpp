#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "core/scene/mesh.h"

namespace shadelab {
namespace {

constexpr float kTolerance = 1e-5f;

bool isFinite(glm::vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool nearlyEqual(glm::vec3 a, glm::vec3 b, float tolerance = kTolerance) {
  return glm::length(a - b) <= tolerance;
}

std::string describe(glm::vec3 v) {
  std::string text = "(";  // not "(" + std::string: GCC 12's false -Wrestrict
  text += std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
  return text;
}

Vertex vertexAt(glm::vec3 position, glm::vec2 uv = glm::vec2(0.0f)) {
  return Vertex{position, glm::vec3(0.0f), uv, glm::vec4(0.0f)};
}

::testing::AssertionResult indicesInRange(const Mesh& mesh) {
  if (mesh.indices.empty() || mesh.indices.size() % 3 != 0) {
    return ::testing::AssertionFailure()
           << "index count " << mesh.indices.size() << " is not a non-empty triangle list";
  }
  for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
    if (mesh.indices[i] >= mesh.vertices.size()) {
      return ::testing::AssertionFailure()
             << "index " << i << " = " << mesh.indices[i] << " out of range";
    }
  }
  return ::testing::AssertionSuccess();
}

::testing::AssertionResult normalsAreUnit(const Mesh& mesh) {
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const glm::vec3 n = mesh.vertices[i].normal;
    if (!isFinite(n) || std::abs(glm::length(n) - 1.0f) > kTolerance) {
      return ::testing::AssertionFailure() << "vertex " << i << " normal " << describe(n);
    }
  }
  return ::testing::AssertionSuccess();
}

::testing::AssertionResult tangentsAreValid(const Mesh& mesh) {
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const glm::vec3 t{mesh.vertices[i].tangent};
    const float w = mesh.vertices[i].tangent.w;
    const float alongNormal = glm::dot(t, mesh.vertices[i].normal);
    if (!isFinite(t) || std::abs(glm::length(t) - 1.0f) > kTolerance ||
        std::abs(alongNormal) > kTolerance || std::abs(w) != 1.0f) {
      return ::testing::AssertionFailure() << "vertex " << i << " tangent " << describe(t) << " w "
                                           << w << " dot(n, t) " << alongNormal;
    }
  }
  return ::testing::AssertionSuccess();
}

::testing::AssertionResult uvsInUnitSquare(const Mesh& mesh) {
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const glm::vec2 uv = mesh.vertices[i].uv;
    if (!(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f)) {
      return ::testing::AssertionFailure() << "vertex " << i << " uv " << uv.x << ", " << uv.y;
    }
  }
  return ::testing::AssertionSuccess();
}

// Outward CCW winding and non-zero area, both judged per triangle against the mesh's own normals.
::testing::AssertionResult trianglesOutwardAndNonDegenerate(const Mesh& mesh) {
  const Bounds bounds = computeBounds(mesh);
  const float extent = glm::length(bounds.max - bounds.min);
  const float minTwiceArea = 1e-6f * extent * extent;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const Vertex& a = mesh.vertices[mesh.indices[3 * t]];
    const Vertex& b = mesh.vertices[mesh.indices[3 * t + 1]];
    const Vertex& c = mesh.vertices[mesh.indices[3 * t + 2]];
    const glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
    if (!(glm::length(face) > minTwiceArea)) {
      return ::testing::AssertionFailure() << "triangle " << t << " is degenerate";
    }
    const glm::vec3 averageNormal = (a.normal + b.normal + c.normal) / 3.0f;
    if (!(glm::dot(face, averageNormal) > 0.0f)) {
      return ::testing::AssertionFailure()
             << "triangle " << t << " winds inward, face " << describe(face);
    }
  }
  return ::testing::AssertionSuccess();
}

void expectWellFormed(const Mesh& mesh) {
  ASSERT_TRUE(indicesInRange(mesh));
  EXPECT_TRUE(normalsAreUnit(mesh));
  EXPECT_TRUE(tangentsAreValid(mesh));
  EXPECT_TRUE(uvsInUnitSquare(mesh));
  EXPECT_TRUE(trianglesOutwardAndNonDegenerate(mesh));
}

// Sphere and icosphere normals must be the exact radial direction, and every vertex on the surface.
void expectOnSphere(const Mesh& mesh, float radius) {
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vertex& v = mesh.vertices[i];
    ASSERT_NEAR(glm::length(v.position), radius, kTolerance * radius) << "vertex " << i;
    ASSERT_TRUE(nearlyEqual(v.normal, glm::normalize(v.position)))
        << "vertex " << i << " " << describe(v.normal);
  }
}

// Analytic tangents must agree with what Lengyel's method derives from the same UVs; this pins the
// handedness convention (w) of the generators to the one computeTangents produces.
void expectTangentsMatchComputed(const Mesh& mesh, float minCosine) {
  Mesh recomputed = mesh;
  computeTangents(recomputed);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const glm::vec4 analytic = mesh.vertices[i].tangent;
    const glm::vec4 computed = recomputed.vertices[i].tangent;
    ASSERT_GT(glm::dot(glm::vec3(analytic), glm::vec3(computed)), minCosine) << "vertex " << i;
    ASSERT_EQ(analytic.w, computed.w) << "vertex " << i;
  }
}

TEST(MeshPlane, CountsMatchSubdivisions) {
  const Mesh one = makePlane(1.0f, 1);
  EXPECT_EQ(one.vertices.size(), 4u);
  EXPECT_EQ(one.triangleCount(), 2u);
  const Mesh four = makePlane(2.0f, 4);
  EXPECT_EQ(four.vertices.size(), 25u);
  EXPECT_EQ(four.triangleCount(), 32u);
}

TEST(MeshPlane, IsWellFormed) {
  expectWellFormed(makePlane(3.0f, 5));
}

TEST(MeshPlane, LiesInXzFacingUpWithTangentAlongU) {
  const float size = 4.0f;
  const Mesh mesh = makePlane(size, 3);
  for (const Vertex& v : mesh.vertices) {
    EXPECT_EQ(v.position.y, 0.0f);
    EXPECT_EQ(v.normal, glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_EQ(v.tangent, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    // u grows along +X (the tangent) and v along cross(normal, tangent) = -Z, matching w = +1.
    EXPECT_NEAR(v.uv.x, v.position.x / size + 0.5f, kTolerance);
    EXPECT_NEAR(v.uv.y, 0.5f - v.position.z / size, kTolerance);
  }
  const Bounds bounds = computeBounds(mesh);
  EXPECT_TRUE(nearlyEqual(bounds.min, glm::vec3(-2.0f, 0.0f, -2.0f)));
  EXPECT_TRUE(nearlyEqual(bounds.max, glm::vec3(2.0f, 0.0f, 2.0f)));
}

TEST(MeshPlane, TangentsMatchComputeTangents) {
  expectTangentsMatchComputed(makePlane(1.0f, 2), 1.0f - kTolerance);
}

TEST(MeshBox, HasHardEdgedCounts) {
  const Mesh mesh = makeBox(glm::vec3(1.0f));
  EXPECT_EQ(mesh.vertices.size(), 24u);
  EXPECT_EQ(mesh.triangleCount(), 12u);
}

TEST(MeshBox, IsWellFormed) {
  expectWellFormed(makeBox(glm::vec3(0.5f, 1.0f, 2.0f)));
}

TEST(MeshBox, BoundsEqualHalfExtents) {
  const glm::vec3 half{0.5f, 1.5f, 3.0f};
  const Bounds bounds = computeBounds(makeBox(half));
  EXPECT_EQ(bounds.min, -half);
  EXPECT_EQ(bounds.max, half);
}

TEST(MeshBox, EachAxisFaceHasFourVerticesOnItsPlane) {
  const glm::vec3 half{0.5f, 1.5f, 3.0f};
  const Mesh mesh = makeBox(half);
  std::map<std::pair<int, int>, int> verticesPerFace;
  for (const Vertex& v : mesh.vertices) {
    int axis = 0;
    for (int candidate = 1; candidate < 3; ++candidate) {
      if (std::abs(v.normal[candidate]) > std::abs(v.normal[axis])) {
        axis = candidate;
      }
    }
    const float sign = v.normal[axis] > 0.0f ? 1.0f : -1.0f;
    EXPECT_EQ(glm::length(v.normal), 1.0f);
    EXPECT_EQ(std::abs(v.normal[axis]), 1.0f);
    EXPECT_EQ(v.position[axis], sign * half[axis]);
    ++verticesPerFace[{axis, static_cast<int>(sign)}];
  }
  EXPECT_EQ(verticesPerFace.size(), 6u);
  for (const auto& [face, count] : verticesPerFace) {
    EXPECT_EQ(count, 4) << "axis " << face.first << " sign " << face.second;
  }
}

TEST(MeshBox, ComputeNormalsReproducesFaceNormals) {
  const Mesh box = makeBox(glm::vec3(0.5f, 1.0f, 2.0f));
  Mesh stripped = box;
  for (Vertex& v : stripped.vertices) {
    v.normal = glm::vec3(0.0f);
  }
  computeNormals(stripped);
  for (std::size_t i = 0; i < box.vertices.size(); ++i) {
    EXPECT_TRUE(nearlyEqual(stripped.vertices[i].normal, box.vertices[i].normal))
        << "vertex " << i << " " << describe(stripped.vertices[i].normal);
  }
}

TEST(MeshBox, TangentsMatchComputeTangents) {
  expectTangentsMatchComputed(makeBox(glm::vec3(1.0f, 2.0f, 3.0f)), 1.0f - kTolerance);
}

TEST(MeshUvSphere, CountsIncludeSeamAndPerSlicePoles) {
  // 2 * slices pole vertices + (stacks - 1) rings of (slices + 1); 2 * slices * (stacks - 1)
  // triangles.
  const Mesh minimal = makeUvSphere(1.0f, 3, 2);
  EXPECT_EQ(minimal.vertices.size(), 10u);
  EXPECT_EQ(minimal.triangleCount(), 6u);
  const Mesh mesh = makeUvSphere(1.0f, 16, 8);
  EXPECT_EQ(mesh.vertices.size(), 151u);
  EXPECT_EQ(mesh.triangleCount(), 224u);
}

TEST(MeshUvSphere, IsWellFormedAcrossResolutions) {
  for (const auto& [slices, stacks] : {std::pair{3u, 2u}, {4u, 3u}, {16u, 8u}, {33u, 17u}}) {
    SCOPED_TRACE("slices " + std::to_string(slices) + " stacks " + std::to_string(stacks));
    expectWellFormed(makeUvSphere(2.0f, slices, stacks));
  }
}

TEST(MeshUvSphere, VerticesLieOnSphereWithRadialNormals) {
  expectOnSphere(makeUvSphere(2.5f, 24, 12), 2.5f);
}

TEST(MeshUvSphere, SeamVerticesShareExactPositions) {
  const Mesh mesh = makeUvSphere(1.0f, 8, 4);
  std::map<float, glm::vec3> startOfRing;
  for (const Vertex& v : mesh.vertices) {
    if (v.uv.x == 0.0f) {
      startOfRing[v.uv.y] = v.position;
    }
  }
  ASSERT_EQ(startOfRing.size(), 3u);
  int seamVertices = 0;
  for (const Vertex& v : mesh.vertices) {
    if (v.uv.x == 1.0f) {
      EXPECT_EQ(v.position, startOfRing.at(v.uv.y));
      ++seamVertices;
    }
  }
  EXPECT_EQ(seamVertices, 3);
}

TEST(MeshUvSphere, TangentsMatchComputeTangents) {
  expectTangentsMatchComputed(makeUvSphere(1.0f, 32, 16), 0.99f);
}

TEST(MeshIcosphere, CountsQuadruplePerLevel) {
  uint32_t expectedTriangles = 20;
  for (uint32_t level = 0; level <= 3; ++level) {
    const Mesh mesh = makeIcosphere(1.0f, level);
    EXPECT_EQ(mesh.triangleCount(), expectedTriangles) << "level " << level;
    // Euler's formula for a closed triangulated sphere: V = T / 2 + 2.
    EXPECT_EQ(mesh.vertices.size(), expectedTriangles / 2 + 2) << "level " << level;
    expectedTriangles *= 4;
  }
}

TEST(MeshIcosphere, IsWellFormedAndOnSphere) {
  for (uint32_t level = 0; level <= 3; ++level) {
    SCOPED_TRACE("level " + std::to_string(level));
    const Mesh mesh = makeIcosphere(1.5f, level);
    expectWellFormed(mesh);
    expectOnSphere(mesh, 1.5f);
  }
}

TEST(MeshIcosphere, SharesVerticesAndIsClosed) {
  const Mesh mesh = makeIcosphere(1.0f, 2);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    for (std::size_t j = i + 1; j < mesh.vertices.size(); ++j) {
      ASSERT_FALSE(nearlyEqual(mesh.vertices[i].position, mesh.vertices[j].position, 1e-4f))
          << "vertices " << i << " and " << j << " are duplicates";
    }
  }
  // In a closed, consistently wound mesh every directed edge occurs once and its reverse once.
  std::map<std::pair<uint32_t, uint32_t>, int> directedEdges;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    for (int corner = 0; corner < 3; ++corner) {
      ++directedEdges[{mesh.indices[3 * t + corner], mesh.indices[3 * t + (corner + 1) % 3]}];
    }
  }
  for (const auto& [edge, count] : directedEdges) {
    ASSERT_EQ(count, 1) << "edge " << edge.first << "->" << edge.second;
    ASSERT_EQ(directedEdges.count({edge.second, edge.first}), 1u)
        << "edge " << edge.first << "->" << edge.second;
  }
}

TEST(MeshTorus, CountsMatchSegments) {
  const Mesh mesh = makeTorus(2.0f, 0.5f, 12, 6);
  EXPECT_EQ(mesh.vertices.size(), 13u * 7u);
  EXPECT_EQ(mesh.triangleCount(), 2u * 12u * 6u);
}

TEST(MeshTorus, IsWellFormed) {
  expectWellFormed(makeTorus(2.0f, 0.5f, 3, 3));
  expectWellFormed(makeTorus(2.0f, 0.5f, 24, 12));
}

TEST(MeshTorus, VerticesLieOnTubeAroundYAxis) {
  const float major = 2.0f;
  const float minor = 0.5f;
  const Mesh mesh = makeTorus(major, minor, 24, 12);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vertex& v = mesh.vertices[i];
    const glm::vec2 xz{v.position.x, v.position.z};
    const glm::vec3 nearestOnMajorCircle = glm::vec3(xz.x, 0.0f, xz.y) * (major / glm::length(xz));
    const glm::vec3 offset = v.position - nearestOnMajorCircle;
    ASSERT_NEAR(glm::length(offset), minor, kTolerance) << "vertex " << i;
    ASSERT_TRUE(nearlyEqual(v.normal, offset / minor))
        << "vertex " << i << " " << describe(v.normal);
  }
  const Bounds bounds = computeBounds(mesh);
  EXPECT_NEAR(bounds.max.y, minor, kTolerance);
  EXPECT_NEAR(bounds.min.y, -minor, kTolerance);
  EXPECT_NEAR(bounds.max.x, major + minor, kTolerance);
  EXPECT_NEAR(bounds.min.z, -(major + minor), kTolerance);
}

TEST(MeshTorus, TangentsMatchComputeTangents) {
  expectTangentsMatchComputed(makeTorus(2.0f, 0.5f, 48, 24), 0.99f);
}

TEST(ComputeNormals, WeightsSharedVertexByTriangleArea) {
  Mesh mesh;
  // A big triangle facing +Z (twice-area 4) and a small one facing +Y (twice-area 1) share vertex
  // 0.
  mesh.vertices = {vertexAt({0, 0, 0}), vertexAt({2, 0, 0}), vertexAt({0, 2, 0}),
                   vertexAt({0, 0, 1}), vertexAt({1, 0, 0})};
  mesh.indices = {0, 1, 2, 0, 3, 4};
  computeNormals(mesh);
  const float norm = std::sqrt(17.0f);
  EXPECT_TRUE(nearlyEqual(mesh.vertices[0].normal, glm::vec3(0.0f, 1.0f / norm, 4.0f / norm)))
      << describe(mesh.vertices[0].normal);
  EXPECT_TRUE(nearlyEqual(mesh.vertices[1].normal, glm::vec3(0.0f, 0.0f, 1.0f)));
  EXPECT_TRUE(nearlyEqual(mesh.vertices[3].normal, glm::vec3(0.0f, 1.0f, 0.0f)));
}

TEST(ComputeNormals, DegenerateAndIsolatedVerticesFallBackToUp) {
  Mesh mesh;
  // Collinear and coincident triangles have exactly zero cross product; vertex 5 is unused.
  mesh.vertices = {vertexAt({0, 0, 0}), vertexAt({1, 1, 1}), vertexAt({2, 2, 2}),
                   vertexAt({3, 0, 0}), vertexAt({3, 0, 0}), vertexAt({7, 7, 7})};
  mesh.indices = {0, 1, 2, 3, 4, 3};
  computeNormals(mesh);
  for (const Vertex& v : mesh.vertices) {
    EXPECT_TRUE(isFinite(v.normal));
    EXPECT_EQ(v.normal, glm::vec3(0.0f, 1.0f, 0.0f));
  }
}

Mesh singleTriangle(glm::vec2 uvA, glm::vec2 uvB, glm::vec2 uvC) {
  Mesh mesh;
  mesh.vertices = {vertexAt({0, 0, 0}, uvA), vertexAt({1, 0, 0}, uvB), vertexAt({0, 1, 0}, uvC)};
  mesh.indices = {0, 1, 2};
  computeNormals(mesh);
  computeTangents(mesh);
  return mesh;
}

TEST(ComputeTangents, HandednessFollowsUvOrientation) {
  const Mesh regular = singleTriangle({0, 0}, {1, 0}, {0, 1});
  const Mesh mirrored = singleTriangle({1, 0}, {0, 0}, {1, 1});
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(regular.vertices[i].normal, glm::vec3(0.0f, 0.0f, 1.0f));
    EXPECT_TRUE(nearlyEqual(glm::vec3(regular.vertices[i].tangent), glm::vec3(1.0f, 0.0f, 0.0f)));
    EXPECT_EQ(regular.vertices[i].tangent.w, 1.0f);
    // u now decreases along +X: tangent flips, v still runs along +Y, so the frame is mirrored.
    EXPECT_TRUE(nearlyEqual(glm::vec3(mirrored.vertices[i].tangent), glm::vec3(-1.0f, 0.0f, 0.0f)));
    EXPECT_EQ(mirrored.vertices[i].tangent.w, -1.0f);
  }
}

TEST(ComputeTangents, SkewedUvsFollowSurfaceDerivative) {
  // Solving e1 = dP/du + dP/dv, e2 = dP/du + 2 dP/dv gives dP/du = (2, -1, 0), dP/dv = (-1, 1, 0).
  const Mesh mesh = singleTriangle({0, 0}, {1, 1}, {1, 2});
  for (const Vertex& v : mesh.vertices) {
    EXPECT_TRUE(nearlyEqual(glm::vec3(v.tangent), glm::normalize(glm::vec3(2.0f, -1.0f, 0.0f))))
        << describe(glm::vec3(v.tangent));
    EXPECT_EQ(v.tangent.w, 1.0f);
  }
}

TEST(ComputeTangents, TangentIsOrthogonalisedAgainstVertexNormal) {
  Mesh mesh;
  mesh.vertices = {vertexAt({0, 0, 0}, {0, 0}), vertexAt({1, 0, 0}, {1, 0}),
                   vertexAt({0, 1, 0}, {0, 1})};
  mesh.indices = {0, 1, 2};
  const glm::vec3 smoothNormal = glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f));
  for (Vertex& v : mesh.vertices) {
    v.normal = smoothNormal;
  }
  computeTangents(mesh);
  // Gram-Schmidt: (1,0,0) - n * dot(n, (1,0,0)) = (0.5, 0, -0.5).
  const glm::vec3 expected = glm::normalize(glm::vec3(1.0f, 0.0f, -1.0f));
  for (const Vertex& v : mesh.vertices) {
    EXPECT_TRUE(nearlyEqual(glm::vec3(v.tangent), expected)) << describe(glm::vec3(v.tangent));
  }
  EXPECT_TRUE(tangentsAreValid(mesh));
}

TEST(ComputeTangents, DegenerateUvsStillGivePerpendicularUnitTangent) {
  const Mesh sameUv = singleTriangle({0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f});
  const Mesh collinearUv = singleTriangle({0, 0}, {0.5f, 0.5f}, {1, 1});
  EXPECT_TRUE(tangentsAreValid(sameUv));
  EXPECT_TRUE(tangentsAreValid(collinearUv));

  Mesh tilted;
  tilted.vertices = {vertexAt({0, 0, 0}), vertexAt({1, 0, 1}), vertexAt({0, 1, 0})};
  tilted.indices = {0, 1, 2};
  computeNormals(tilted);
  computeTangents(tilted);
  EXPECT_TRUE(tangentsAreValid(tilted));
}

TEST(ComputeBounds, EmptyMeshIsZero) {
  const Bounds bounds = computeBounds(Mesh{});
  EXPECT_EQ(bounds.min, glm::vec3(0.0f));
  EXPECT_EQ(bounds.max, glm::vec3(0.0f));
}

TEST(AppendMesh, OffsetsIndicesAndKeepsVertices) {
  Mesh scene = makeBox(glm::vec3(1.0f));
  Mesh plane = makePlane(10.0f, 1);
  for (Vertex& v : plane.vertices) {
    v.position.y -= 1.0f;
  }
  appendMesh(scene, plane);
  ASSERT_EQ(scene.vertices.size(), 28u);
  ASSERT_EQ(scene.triangleCount(), 14u);
  for (std::size_t i = 0; i < plane.indices.size(); ++i) {
    EXPECT_EQ(scene.indices[36 + i], plane.indices[i] + 24u);
  }
  EXPECT_EQ(scene.vertices[24].position, plane.vertices[0].position);
  const Bounds bounds = computeBounds(scene);
  EXPECT_EQ(bounds.min, glm::vec3(-5.0f, -1.0f, -5.0f));
  EXPECT_EQ(bounds.max, glm::vec3(5.0f, 1.0f, 5.0f));

  appendMesh(scene, scene);
  EXPECT_EQ(scene.vertices.size(), 56u);
  EXPECT_EQ(scene.indices.back(), scene.indices[41] + 28u);
}

#ifndef NDEBUG
TEST(MeshDeathTest, InvalidParametersAssert) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH(makePlane(1.0f, 0), "");
  EXPECT_DEATH(makePlane(0.0f, 1), "");
  EXPECT_DEATH(makeBox(glm::vec3(1.0f, -1.0f, 1.0f)), "");
  EXPECT_DEATH(makeUvSphere(1.0f, 2, 4), "");
  EXPECT_DEATH(makeUvSphere(1.0f, 8, 1), "");
  EXPECT_DEATH(makeIcosphere(-1.0f, 1), "");
  EXPECT_DEATH(makeTorus(1.0f, 1.0f, 8, 8), "");
  EXPECT_DEATH(makeTorus(2.0f, 0.5f, 8, 2), "");
}
#endif

}  // namespace
}  // namespace shadelab
