// computeCreaseNormals: smoothing across soft edges, splitting vertices at hard ones.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

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

glm::vec3 faceNormal(const Mesh& mesh, std::size_t triangle) {
  const glm::vec3 a = mesh.vertices[mesh.indices[3 * triangle]].position;
  const glm::vec3 b = mesh.vertices[mesh.indices[3 * triangle + 1]].position;
  const glm::vec3 c = mesh.vertices[mesh.indices[3 * triangle + 2]].position;
  return glm::normalize(glm::cross(b - a, c - a));
}

// Normals zeroed first, so every normal checked afterwards was computed.
Mesh creased(Mesh mesh, float creaseAngleDegrees) {
  for (Vertex& v : mesh.vertices) {
    v.normal = glm::vec3(0.0f);
  }
  computeCreaseNormals(mesh, creaseAngleDegrees);
  return mesh;
}

// Splitting may renumber corners but must keep every triangle's positions and UVs, and every
// normal must be unit length.
void expectSameSurfaceWithUnitNormals(const Mesh& before, const Mesh& after) {
  ASSERT_EQ(after.indices.size(), before.indices.size());
  for (std::size_t i = 0; i < after.indices.size(); ++i) {
    ASSERT_LT(after.indices[i], after.vertices.size());
    const Vertex& was = before.vertices[before.indices[i]];
    const Vertex& is = after.vertices[after.indices[i]];
    EXPECT_EQ(is.position, was.position) << "corner " << i;
    EXPECT_EQ(is.uv, was.uv) << "corner " << i;
  }
  for (std::size_t v = 0; v < after.vertices.size(); ++v) {
    const glm::vec3 n = after.vertices[v].normal;
    EXPECT_TRUE(isFinite(n) && std::abs(glm::length(n) - 1.0f) < kTolerance)
        << "vertex " << v << " " << describe(n);
  }
}

// Every corner carries its own triangle's normal: flat shading.
void expectFlatFacets(const Mesh& mesh) {
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const glm::vec3 face = faceNormal(mesh, t);
    for (std::size_t k = 0; k < 3; ++k) {
      const glm::vec3 n = mesh.vertices[mesh.indices[3 * t + k]].normal;
      ASSERT_TRUE(nearlyEqual(n, face, 1e-4f)) << "triangle " << t << " " << describe(n);
    }
  }
}

// Two unit quads sharing the edge from (0,0,0) to (1,0,0): a floor (normal +Y) and a wall
// (normal +Z), i.e. a 90 degree fold. Each fold vertex touches as many floor as wall triangles
// (v0 one of each, v1 two of each), so smoothing gives exactly (0,1,1)/sqrt2 there.
Mesh foldedQuads() {
  Mesh mesh;
  const glm::vec3 positions[] = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 0}, {1, 1, 0}};
  for (const glm::vec3 p : positions) {
    mesh.vertices.push_back(Vertex{p, glm::vec3(0.0f), glm::vec2(p.x, p.y + p.z), glm::vec4(0.0f)});
  }
  mesh.indices = {0, 2, 1, 1, 2, 3, 0, 1, 4, 1, 5, 4};
  return mesh;
}

// A closed cylinder of `segments` sides around Y, radius 1, y in [-1, 1], whose side quads and
// caps share the rim vertices (2 * segments rim vertices and two cap centres).
Mesh sharedRimCylinder(uint32_t segments) {
  Mesh mesh;
  for (const float y : {-1.0f, 1.0f}) {
    for (uint32_t i = 0; i < segments; ++i) {
      const float theta = 2.0f * std::numbers::pi_v<float> * float(i) / float(segments);
      const glm::vec3 p{std::cos(theta), y, -std::sin(theta)};
      mesh.vertices.push_back(Vertex{p, glm::vec3(0.0f), glm::vec2(0.0f), glm::vec4(0.0f)});
    }
  }
  const uint32_t bottomCentre = 2 * segments;
  const uint32_t topCentre = bottomCentre + 1;
  mesh.vertices.push_back(Vertex{{0, -1, 0}, glm::vec3(0.0f), glm::vec2(0.0f), glm::vec4(0.0f)});
  mesh.vertices.push_back(Vertex{{0, 1, 0}, glm::vec3(0.0f), glm::vec2(0.0f), glm::vec4(0.0f)});
  for (uint32_t i = 0; i < segments; ++i) {
    const uint32_t b0 = i;
    const uint32_t b1 = (i + 1) % segments;
    const uint32_t t0 = b0 + segments;
    const uint32_t t1 = b1 + segments;
    mesh.indices.insert(mesh.indices.end(), {b0, b1, t1, b0, t1, t0});
    mesh.indices.insert(mesh.indices.end(), {bottomCentre, b1, b0, topCentre, t0, t1});
  }
  return mesh;
}

TEST(CreaseNormals, BoxAt30KeepsItsFaceNormalsAndVertices) {
  const Mesh box = makeBox(glm::vec3(0.5f, 1.0f, 2.0f));
  const Mesh result = creased(box, 30.0f);
  EXPECT_EQ(result.vertices.size(), 24u);
  expectSameSurfaceWithUnitNormals(box, result);
  for (std::size_t i = 0; i < box.vertices.size(); ++i) {
    EXPECT_TRUE(nearlyEqual(result.vertices[i].normal, box.vertices[i].normal)) << "vertex " << i;
    EXPECT_TRUE(
        nearlyEqual(glm::vec3(result.vertices[i].tangent), glm::vec3(box.vertices[i].tangent)));
  }
}

TEST(CreaseNormals, BoxAt100SmoothsEachCornerTowardItsDiagonal) {
  const Mesh box = makeBox(glm::vec3(1.0f));
  const Mesh result = creased(box, 100.0f);
  EXPECT_EQ(result.vertices.size(), 24u);
  expectSameSurfaceWithUnitNormals(box, result);
  for (const Vertex& v : result.vertices) {
    // Area weights: a face counts twice where its quad's diagonal ends at the corner, so the
    // normals are (2,2,1)/3 or (1,1,2)/sqrt6 with signs, 15.8 or 19.5 degrees off the diagonal.
    const glm::vec3 diagonal = v.position / std::sqrt(3.0f);
    EXPECT_GT(glm::dot(v.normal, diagonal), 0.94f)
        << describe(v.position) << " " << describe(v.normal);
    // All three vertices at a corner share one normal, so the corner is smooth.
    for (const Vertex& other : result.vertices) {
      if (other.position == v.position) {
        EXPECT_EQ(other.normal, v.normal);
      }
    }
    EXPECT_NEAR(glm::dot(glm::vec3(v.tangent), v.normal), 0.0f, kTolerance);
    EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, kTolerance);
  }
}

TEST(CreaseNormals, EqualAreaCornerSmoothsAlongTheDiagonal) {
  // Three right triangles of equal area meeting at (1,1,1), with normals +X, +Y and +Z and no
  // shared indices: smoothed, every copy of the corner gets (1,1,1)/sqrt3.
  Mesh corner;
  const glm::vec3 c{1.0f};
  const glm::vec3 triangles[3][3] = {
      {c, {1, 0, 1}, {1, 1, 0}}, {c, {1, 1, 0}, {0, 1, 1}}, {c, {0, 1, 1}, {1, 0, 1}}};
  for (const auto& triangle : triangles) {
    for (const glm::vec3 p : triangle) {
      corner.indices.push_back(static_cast<uint32_t>(corner.vertices.size()));
      corner.vertices.push_back(Vertex{p, glm::vec3(0.0f), glm::vec2(0.0f), glm::vec4(0.0f)});
    }
  }
  const Mesh smooth = creased(corner, 100.0f);
  ASSERT_EQ(smooth.vertices.size(), 9u);
  for (const std::size_t i : {0u, 3u, 6u}) {
    EXPECT_TRUE(nearlyEqual(smooth.vertices[i].normal, glm::vec3(1.0f) / std::sqrt(3.0f)));
  }
  expectFlatFacets(creased(corner, 89.0f));
}

TEST(CreaseNormals, UvSphereAt30StaysSmooth) {
  const Mesh sphere = makeUvSphere(1.0f, 32, 16);
  const Mesh result = creased(sphere, 30.0f);
  EXPECT_EQ(result.vertices.size(), sphere.vertices.size());
  expectSameSurfaceWithUnitNormals(sphere, result);
  for (const Vertex& v : result.vertices) {
    // Area weighting is not exactly radial on a UV sphere: within 3 degrees at 32 x 16.
    EXPECT_GT(glm::dot(v.normal, glm::normalize(v.position)), std::cos(glm::radians(3.0f)))
        << describe(v.position) << " " << describe(v.normal);
    // Welding by position makes the seam and the per-slice pole vertices agree.
    for (const Vertex& other : result.vertices) {
      if (other.position == v.position) {
        EXPECT_EQ(other.normal, v.normal);
      }
    }
    if (std::abs(v.position.y) == 1.0f) {
      EXPECT_TRUE(nearlyEqual(v.normal, glm::vec3(0.0f, v.position.y, 0.0f)));
    }
  }
}

TEST(CreaseNormals, FoldedQuadsSplitExactlyAtTheFold) {
  const Mesh quads = foldedQuads();
  const Mesh hard = creased(quads, 30.0f);
  // Only the two fold vertices split: 6 + 2.
  EXPECT_EQ(hard.vertices.size(), 8u);
  expectSameSurfaceWithUnitNormals(quads, hard);
  expectFlatFacets(hard);
  for (std::size_t i = 6; i < 8; ++i) {
    EXPECT_EQ(hard.vertices[i].position.y, 0.0f);
    EXPECT_EQ(hard.vertices[i].position.z, 0.0f);
  }

  const Mesh soft = creased(quads, 100.0f);
  ASSERT_EQ(soft.vertices.size(), 6u);
  expectSameSurfaceWithUnitNormals(quads, soft);
  const glm::vec3 bisector = glm::normalize(glm::vec3(0.0f, 1.0f, 1.0f));
  EXPECT_TRUE(nearlyEqual(soft.vertices[0].normal, bisector));
  EXPECT_TRUE(nearlyEqual(soft.vertices[1].normal, bisector));
  EXPECT_TRUE(nearlyEqual(soft.vertices[2].normal, glm::vec3(0, 1, 0)));
  EXPECT_TRUE(nearlyEqual(soft.vertices[5].normal, glm::vec3(0, 0, 1)));
}

TEST(CreaseNormals, CylinderRimSplitsBetweenSideAndCaps) {
  constexpr uint32_t kSegments = 16;  // 22.5 degrees between neighbouring sides
  const Mesh cylinder = sharedRimCylinder(kSegments);
  const Mesh result = creased(cylinder, 30.0f);
  // Each rim vertex becomes a side vertex and a cap vertex; the centres stay single.
  EXPECT_EQ(result.vertices.size(), 4u * kSegments + 2u);
  expectSameSurfaceWithUnitNormals(cylinder, result);
  for (std::size_t t = 0; t < result.triangleCount(); ++t) {
    const glm::vec3 face = faceNormal(result, t);
    for (std::size_t k = 0; k < 3; ++k) {
      const Vertex& v = result.vertices[result.indices[3 * t + k]];
      if (std::abs(face.y) > 0.5f) {
        EXPECT_EQ(v.normal, glm::vec3(0.0f, face.y > 0.0f ? 1.0f : -1.0f, 0.0f));
      } else {
        // Side normals stay horizontal and within half a segment of the radial direction.
        EXPECT_NEAR(v.normal.y, 0.0f, kTolerance);
        const glm::vec3 radial = glm::normalize(glm::vec3(v.position.x, 0.0f, v.position.z));
        EXPECT_GT(glm::dot(v.normal, radial), std::cos(glm::radians(11.25f)));
      }
    }
  }
}

TEST(CreaseNormals, VertexCountsFollowTheAngle) {
  constexpr uint32_t kSegments = 16;
  const Mesh cylinder = sharedRimCylinder(kSegments);
  // 0: a rim vertex touches two side planes and a cap, so it splits in three.
  EXPECT_EQ(creased(cylinder, 0.0f).vertices.size(), 6u * kSegments + 2u);
  EXPECT_EQ(creased(cylinder, -10.0f).vertices.size(), 6u * kSegments + 2u);
  expectFlatFacets(creased(cylinder, 0.0f));
  // Just under the 22.5 degrees between sides they split; just over, only the caps do.
  EXPECT_EQ(creased(cylinder, 22.0f).vertices.size(), 6u * kSegments + 2u);
  EXPECT_EQ(creased(cylinder, 23.0f).vertices.size(), 4u * kSegments + 2u);
  EXPECT_EQ(creased(cylinder, 180.0f).vertices.size(), 2u * kSegments + 2u);
  EXPECT_EQ(creased(cylinder, 360.0f).vertices.size(), 2u * kSegments + 2u);
}

TEST(CreaseNormals, At180MatchesComputeNormals) {
  for (const Mesh& mesh : {sharedRimCylinder(12), makeIcosphere(1.0f, 2), foldedQuads()}) {
    Mesh expected = mesh;
    computeNormals(expected);
    const Mesh result = creased(mesh, 180.0f);
    ASSERT_EQ(result.vertices.size(), mesh.vertices.size());
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      EXPECT_TRUE(nearlyEqual(result.vertices[i].normal, expected.vertices[i].normal))
          << "vertex " << i;
    }
  }
}

TEST(CreaseNormals, At0GivesFlatFacets) {
  const Mesh icosphere = makeIcosphere(1.0f, 1);
  const Mesh result = creased(icosphere, 0.0f);
  // No two icosphere triangles are coplanar, so every corner gets its own vertex.
  EXPECT_EQ(result.vertices.size(), 3 * icosphere.triangleCount());
  expectSameSurfaceWithUnitNormals(icosphere, result);
  expectFlatFacets(result);
}

TEST(CreaseNormals, DegenerateTrianglesGiveNoNanAndNoSplit) {
  Mesh mesh = foldedQuads();
  // A repeated index and a collinear triple on the fold; vertex 6 used only by that zero-area
  // triangle; vertex 7 used by no triangle; vertex 8 a copy of the wall's top corner 4 used only
  // by a zero-area triangle, which takes the normal of the faces at its position.
  for (const glm::vec3 p : {glm::vec3(0.5f, 0, 0), glm::vec3(9, 9, 9), glm::vec3(0, 1, 0)}) {
    mesh.vertices.push_back(Vertex{p, glm::vec3(0.0f), glm::vec2(0.0f), glm::vec4(0.0f)});
  }
  mesh.indices.insert(mesh.indices.end(), {0, 0, 1, 0, 6, 1, 4, 8, 5});
  for (const float angle : {0.0f, 30.0f, 100.0f, 180.0f}) {
    const Mesh result = creased(mesh, angle);
    SCOPED_TRACE("crease " + std::to_string(angle));
    // Only the fold splits, and only below 90 degrees.
    EXPECT_EQ(result.vertices.size(), angle < 90.0f ? 11u : 9u);
    expectSameSurfaceWithUnitNormals(mesh, result);
    EXPECT_EQ(result.vertices[6].normal, glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_EQ(result.vertices[7].normal, glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_TRUE(nearlyEqual(result.vertices[8].normal, glm::vec3(0.0f, 0.0f, 1.0f)));
  }
}

TEST(CreaseNormals, NeighboursWithinTheAngleDoNotChain) {
  // Three pages of a book on a shared spine (vertices 0 and 1), opened 0, 25 and 50 degrees
  // about X. At crease 30 the outer pages are 50 degrees apart, so each page's corner averages
  // only itself and its neighbours: three normals per spine vertex, 0, 25 and 50 degrees up.
  Mesh book;
  book.vertices.push_back(Vertex{{0, 0, 0}, glm::vec3(0.0f), glm::vec2(0.0f), glm::vec4(0.0f)});
  book.vertices.push_back(Vertex{{1, 0, 0}, glm::vec3(0.0f), glm::vec2(0.0f), glm::vec4(0.0f)});
  for (uint32_t page = 0; page < 3; ++page) {
    const float angle = glm::radians(25.0f * float(page));
    const glm::vec3 tip{0.0f, -std::sin(angle), std::cos(angle)};
    book.vertices.push_back(Vertex{tip, glm::vec3(0.0f), glm::vec2(0.0f), glm::vec4(0.0f)});
    book.indices.insert(book.indices.end(), {0, page + 2, 1});
  }
  const Mesh result = creased(book, 30.0f);
  EXPECT_EQ(result.vertices.size(), 9u);
  expectSameSurfaceWithUnitNormals(book, result);
  const float rad25 = glm::radians(25.0f);
  const glm::vec3 expected[] = {glm::normalize(faceNormal(book, 0) + faceNormal(book, 1)),
                                glm::vec3(0.0f, std::cos(rad25), std::sin(rad25)),
                                glm::normalize(faceNormal(book, 1) + faceNormal(book, 2))};
  for (std::size_t page = 0; page < 3; ++page) {
    const uint32_t spine = result.indices[3 * page];
    EXPECT_TRUE(nearlyEqual(result.vertices[spine].normal, expected[page]))
        << "page " << page << " " << describe(result.vertices[spine].normal);
  }
  EXPECT_EQ(creased(book, 60.0f).vertices.size(), 5u);
}

TEST(CreaseNormals, TangentsOnlyWhereTheMeshHadThem) {
  const Mesh bare = creased(foldedQuads(), 30.0f);
  for (const Vertex& v : bare.vertices) {
    EXPECT_EQ(v.tangent, glm::vec4(0.0f));
  }
  const Mesh torus = creased(makeTorus(1.0f, 0.25f, 24, 12), 30.0f);
  for (const Vertex& v : torus.vertices) {
    EXPECT_NEAR(glm::dot(glm::vec3(v.tangent), v.normal), 0.0f, kTolerance);
    EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, kTolerance);
    EXPECT_EQ(std::abs(v.tangent.w), 1.0f);
  }
}

}  // namespace
}  // namespace shadelab
