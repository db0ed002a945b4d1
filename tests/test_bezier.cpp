#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "core/scene/bezier.h"

namespace shadelab {
namespace {

constexpr std::array<float, 7> kSampleParams = {0.0f, 0.1f, 0.25f, 0.5f, 0.7f, 0.9f, 1.0f};

void expectVecNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

bool sameVec(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-5f) {
  return glm::length(a - b) <= tolerance;
}

// Bernstein polynomial C(3, k) u^k (1-u)^(3-k), written independently of the code under test.
double bernsteinReference(int k, double u) {
  constexpr std::array<double, 4> kBinomial = {1.0, 3.0, 3.0, 1.0};
  return kBinomial[k] * std::pow(u, k) * std::pow(1.0 - u, 3 - k);
}

const std::array<glm::vec3, 4> kCurve = {glm::vec3(0.0f, 0.0f, 0.0f), glm::vec3(1.0f, 2.0f, 0.5f),
                                         glm::vec3(3.0f, 2.5f, -1.0f), glm::vec3(4.0f, 0.0f, 2.0f)};

TEST(BezierCurve, BasisMatrixTimesPowerBasisIsBernstein) {
  const glm::mat4 mb = bezierBasisMatrix();
  for (float u : kSampleParams) {
    const glm::vec4 power(u * u * u, u * u, u, 1.0f);
    const glm::vec4 viaMatrix = power * mb;
    const glm::vec4 direct = bezierBlending(u);
    for (int k = 0; k < 4; ++k) {
      EXPECT_NEAR(viaMatrix[k], bernsteinReference(k, u), 1e-6) << "u=" << u << " k=" << k;
      EXPECT_NEAR(direct[k], bernsteinReference(k, u), 1e-6) << "u=" << u << " k=" << k;
    }
  }
}

TEST(BezierCurve, BlendingIsPartitionOfUnity) {
  for (int step = 0; step <= 20; ++step) {
    const float u = static_cast<float>(step) / 20.0f;
    const glm::vec4 b = bezierBlending(u);
    const glm::vec4 db = bezierBlendingDerivative(u);
    EXPECT_NEAR(b.x + b.y + b.z + b.w, 1.0f, 1e-6f) << "u=" << u;
    EXPECT_NEAR(db.x + db.y + db.z + db.w, 0.0f, 1e-5f) << "u=" << u;
    for (int k = 0; k < 4; ++k) {
      EXPECT_GE(b[k], 0.0f);
      EXPECT_LE(b[k], 1.0f);
    }
  }
}

TEST(BezierCurve, BlendingDerivativeMatchesFiniteDifference) {
  constexpr float h = 1e-3f;
  for (float u : {0.1f, 0.3f, 0.5f, 0.8f}) {
    const glm::vec4 fd = (bezierBlending(u + h) - bezierBlending(u - h)) / (2.0f * h);
    const glm::vec4 db = bezierBlendingDerivative(u);
    for (int k = 0; k < 4; ++k) {
      EXPECT_NEAR(db[k], fd[k], 1e-3f) << "u=" << u << " k=" << k;
    }
  }
}

TEST(BezierCurve, InterpolatesEndPointsAndMatchesMatrixForm) {
  expectVecNear(evalBezierCurve(kCurve, 0.0f), kCurve[0], 1e-6f);
  expectVecNear(evalBezierCurve(kCurve, 1.0f), kCurve[3], 1e-6f);
  // The control points in between are only approached, not interpolated.
  EXPECT_GT(glm::length(evalBezierCurve(kCurve, 1.0f / 3.0f) - kCurve[1]), 0.1f);
  for (float u : kSampleParams) {
    expectVecNear(evalCubic(bezierBasisMatrix(), kCurve, u), evalBezierCurve(kCurve, u), 1e-5f);
  }
}

TEST(BezierCurve, EndTangentsAreThreeTimesTheControlLegs) {
  expectVecNear(evalBezierCurveDerivative(kCurve, 0.0f), 3.0f * (kCurve[1] - kCurve[0]), 1e-5f);
  expectVecNear(evalBezierCurveDerivative(kCurve, 1.0f), 3.0f * (kCurve[3] - kCurve[2]), 1e-5f);
  constexpr float h = 1e-3f;
  const glm::vec3 forward = (evalBezierCurve(kCurve, h) - evalBezierCurve(kCurve, 0.0f)) / h;
  const glm::vec3 backward =
      (evalBezierCurve(kCurve, 1.0f) - evalBezierCurve(kCurve, 1.0f - h)) / h;
  expectVecNear(forward, 3.0f * (kCurve[1] - kCurve[0]), 2e-2f);
  expectVecNear(backward, 3.0f * (kCurve[3] - kCurve[2]), 2e-2f);
  for (float u : {0.2f, 0.5f, 0.75f}) {
    const glm::vec3 central =
        (evalBezierCurve(kCurve, u + h) - evalBezierCurve(kCurve, u - h)) / (2.0f * h);
    expectVecNear(evalBezierCurveDerivative(kCurve, u), central, 1e-2f);
  }
}

TEST(BezierCurve, InterpolatingBasisPassesThroughItsFourPoints) {
  const glm::mat4 mi = interpolatingBasisMatrix();
  const std::array<float, 4> knots = {0.0f, 1.0f / 3.0f, 2.0f / 3.0f, 1.0f};
  for (int k = 0; k < 4; ++k) {
    expectVecNear(evalCubic(mi, kCurve, knots[k]), kCurve[k], 1e-5f);
  }
  // M_I must be the inverse of the sampling matrix S (rows = power basis at the knots).
  glm::mat4 sampling(0.0f);
  for (int row = 0; row < 4; ++row) {
    const float u = knots[row];
    const glm::vec4 power(u * u * u, u * u, u, 1.0f);
    for (int col = 0; col < 4; ++col) {
      sampling[col][row] = power[col];
    }
  }
  const glm::mat4 product = sampling * mi;
  for (int col = 0; col < 4; ++col) {
    for (int row = 0; row < 4; ++row) {
      EXPECT_NEAR(product[col][row], col == row ? 1.0f : 0.0f, 1e-5f) << row << "," << col;
    }
  }
}

TEST(BezierPatchEval, CornersDerivativesAndIsoCurves) {
  const BezierPatch& patch = utahTeapotPatches()[4];
  expectVecNear(evalBezierPatch(patch, 0.0f, 0.0f).position, patch.control[0], 1e-5f);
  expectVecNear(evalBezierPatch(patch, 1.0f, 1.0f).position, patch.control[15], 1e-5f);
  const std::array<glm::vec3, 4> row0 = {patch.control[0], patch.control[1], patch.control[2],
                                         patch.control[3]};
  constexpr float h = 1e-3f;
  for (float t : {0.2f, 0.6f}) {
    expectVecNear(evalBezierPatch(patch, 0.0f, t).position, evalBezierCurve(row0, t), 1e-5f);
    const PatchSample s = evalBezierPatch(patch, t, 0.4f);
    const glm::vec3 du = (evalBezierPatch(patch, t + h, 0.4f).position -
                          evalBezierPatch(patch, t - h, 0.4f).position) /
                         (2.0f * h);
    const glm::vec3 dv = (evalBezierPatch(patch, t, 0.4f + h).position -
                          evalBezierPatch(patch, t, 0.4f - h).position) /
                         (2.0f * h);
    expectVecNear(s.dPdu, du, 1e-2f);
    expectVecNear(s.dPdv, dv, 1e-2f);
    expectVecNear(s.normal, glm::normalize(glm::cross(du, dv)), 1e-3f);
  }
}

// ---- Utah teapot data ------------------------------------------------------------------

std::vector<glm::vec3> controlPoints(std::size_t first, std::size_t last) {
  std::vector<glm::vec3> points;
  for (std::size_t p = first; p <= last; ++p) {
    const auto& control = utahTeapotPatches()[p].control;
    points.insert(points.end(), control.begin(), control.end());
  }
  return points;
}

bool containsPoint(const std::vector<glm::vec3>& points, const glm::vec3& q) {
  for (const glm::vec3& p : points) {
    if (sameVec(p, q)) {
      return true;
    }
  }
  return false;
}

TEST(UtahTeapot, HasThirtyTwoPatchesStandingOnYZeroWithSpoutAlongX) {
  const auto& patches = utahTeapotPatches();
  ASSERT_EQ(patches.size(), 32u);
  float minY = 1e9f;
  for (const glm::vec3& p : controlPoints(0, 31)) {
    minY = std::min(minY, p.y);
  }
  EXPECT_FLOAT_EQ(minY, 0.0f);
  for (const glm::vec3& p : controlPoints(12, 15)) {
    EXPECT_LT(p.x, -1.4f) << "handle on -x";
  }
  for (const glm::vec3& p : controlPoints(16, 19)) {
    EXPECT_GT(p.x, 1.6f) << "spout on +x";
  }
  EXPECT_FLOAT_EQ(evalBezierPatch(patches[20], 0.0f, 0.3f).position.y, 3.15f) << "lid knob apex";
}

// A typo in the 306-point table would almost surely break one of these symmetries.
TEST(UtahTeapot, DataIsMirrorSymmetricAndRotationallySymmetric) {
  const std::vector<glm::vec3> all = controlPoints(0, 31);
  for (const glm::vec3& p : all) {
    EXPECT_TRUE(containsPoint(all, {p.x, p.y, -p.z})) << p.x << " " << p.y << " " << p.z;
  }
  // Rim, body, lid and bottom are surfaces of revolution built from four quarter patches.
  const std::array<std::array<std::size_t, 2>, 4> groups = {{{0, 3}, {4, 11}, {20, 27}, {28, 31}}};
  for (const auto& group : groups) {
    const std::vector<glm::vec3> points = controlPoints(group[0], group[1]);
    for (const glm::vec3& p : points) {
      EXPECT_TRUE(containsPoint(points, {p.z, p.y, -p.x})) << p.x << " " << p.y << " " << p.z;
    }
  }
}

// ---- Seams between patches --------------------------------------------------------------

// Patch edges: 0 is u = 0 (row 0), 1 is u = 1 (row 3), 2 is v = 0 (column 0), 3 is v = 1 (column
// 3).
glm::vec3 edgeControl(const BezierPatch& patch, int side, int k, int depth) {
  switch (side) {
    case 0:
      return patch.control[4 * depth + k];
    case 1:
      return patch.control[4 * (3 - depth) + k];
    case 2:
      return patch.control[4 * k + depth];
    default:
      return patch.control[4 * k + 3 - depth];
  }
}

PatchSample sampleEdge(const BezierPatch& patch, int side, float t) {
  switch (side) {
    case 0:
      return evalBezierPatch(patch, 0.0f, t);
    case 1:
      return evalBezierPatch(patch, 1.0f, t);
    case 2:
      return evalBezierPatch(patch, t, 0.0f);
    default:
      return evalBezierPatch(patch, t, 1.0f);
  }
}

// Derivative across the edge, taken in the direction leaving the patch.
glm::vec3 leavingDerivative(const PatchSample& s, int side) {
  switch (side) {
    case 0:
      return -s.dPdu;
    case 1:
      return s.dPdu;
    case 2:
      return -s.dPdv;
    default:
      return s.dPdv;
  }
}

enum class Continuity { C0, G1, C1 };

struct Seam {
  std::size_t patchA = 0;
  int sideA = 0;
  std::size_t patchB = 0;
  int sideB = 0;
  bool reversed = false;  // B's edge runs the other way
  Continuity continuity = Continuity::C0;
  float ratio = 0.0f;  // |B's cross-seam leg| / |A's| when G1 or C1
};

// Classifies a seam from its control points: the legs s_k - a_k (A's side) and b_k - s_k
// (B's side) must be parallel with one common ratio for G1, and equal for C1.
void classify(Seam& seam, const BezierPatch& a, const BezierPatch& b) {
  std::array<glm::vec3, 4> legA{};
  std::array<glm::vec3, 4> legB{};
  float ratio = -1.0f;
  for (int k = 0; k < 4; ++k) {
    const int kb = seam.reversed ? 3 - k : k;
    legA[k] = edgeControl(a, seam.sideA, k, 0) - edgeControl(a, seam.sideA, k, 1);
    legB[k] = edgeControl(b, seam.sideB, kb, 1) - edgeControl(b, seam.sideB, kb, 0);
    if (ratio < 0.0f && glm::length(legA[k]) > 1e-6f) {
      ratio = glm::length(legB[k]) / glm::length(legA[k]);
    }
  }
  bool parallel = ratio > 0.0f;
  for (int k = 0; k < 4 && parallel; ++k) {
    parallel = sameVec(legB[k], ratio * legA[k]);
  }
  seam.ratio = ratio;
  seam.continuity = !parallel ? Continuity::C0
                              : (std::abs(ratio - 1.0f) < 1e-5f ? Continuity::C1 : Continuity::G1);
}

bool edgesMatch(const BezierPatch& a, int sideA, const BezierPatch& b, int sideB, bool reversed) {
  for (int k = 0; k < 4; ++k) {
    if (!sameVec(edgeControl(a, sideA, k, 0), edgeControl(b, sideB, reversed ? 3 - k : k, 0))) {
      return false;
    }
  }
  return true;
}

bool collapsed(const BezierPatch& patch, int side) {
  for (int k = 1; k < 4; ++k) {
    if (!sameVec(edgeControl(patch, side, k, 0), edgeControl(patch, side, 0, 0))) {
      return false;
    }
  }
  return true;
}

// Edges whose four control points coincide between two patches (collapsed edges excluded:
// the lid apex and base centre are points, not seams).
std::vector<Seam> findSeams(const std::vector<BezierPatch>& patches) {
  std::vector<Seam> seams;
  for (std::size_t a = 0; a < patches.size(); ++a) {
    for (std::size_t b = a + 1; b < patches.size(); ++b) {
      for (int sideA = 0; sideA < 4; ++sideA) {
        for (int sideB = 0; sideB < 4; ++sideB) {
          if (collapsed(patches[a], sideA)) {
            continue;
          }
          for (bool reversed : {false, true}) {
            if (edgesMatch(patches[a], sideA, patches[b], sideB, reversed)) {
              Seam seam;
              seam.patchA = a;
              seam.sideA = sideA;
              seam.patchB = b;
              seam.sideB = sideB;
              seam.reversed = reversed;
              classify(seam, patches[a], patches[b]);
              seams.push_back(seam);
            }
          }
        }
      }
    }
  }
  return seams;
}

// 52 shared edges: the four quarter seams of each surface of revolution (rim, upper body,
// lower body, bottom, lid knob, lid: 24), the rings joining them (rim/body at y = 2.4,
// upper/lower body at y = 0.9, body/bottom at y = 0.15, knob/lid at y = 2.7: 16), and six
// each inside the handle and the spout.
TEST(UtahTeapotSeams, FindsEverySharedEdge) {
  EXPECT_EQ(findSeams(utahTeapotPatches()).size(), 52u);
}

TEST(UtahTeapotSeams, SurfaceIsContinuousAcrossEverySeam) {
  const auto& patches = utahTeapotPatches();
  for (const Seam& seam : findSeams(patches)) {
    for (int step = 0; step <= 8; ++step) {
      const float t = static_cast<float>(step) / 8.0f;
      const glm::vec3 pa = sampleEdge(patches[seam.patchA], seam.sideA, t).position;
      const glm::vec3 pb =
          sampleEdge(patches[seam.patchB], seam.sideB, seam.reversed ? 1.0f - t : t).position;
      EXPECT_LT(glm::length(pa - pb), 1e-5f)
          << "patches " << seam.patchA << "/" << seam.patchB << " t=" << t;
    }
  }
}

// Detected from the data: 46 seams are C1 (legs equal on both sides): all quarter seams,
// upper/lower body, body/bottom, knob/lid, and every seam inside the handle and inside
// the spout except where the spout meets its tip. The 6 others are only G1 (collinear legs,
// unequal spacing): the rim/body ring (4), where the body's legs are 4x the rim's, and the
// spout/spout-tip ring (2), where the tip's legs are 1/4 of the spout's.
TEST(UtahTeapotSeams, ClassifiesC1AndG1SeamsFromTheData) {
  std::size_t c1 = 0;
  std::size_t g1 = 0;
  for (const Seam& seam : findSeams(utahTeapotPatches())) {
    if (seam.continuity == Continuity::C1) {
      ++c1;
    } else if (seam.continuity == Continuity::G1) {
      ++g1;
      const bool rimBody = seam.patchA <= 3 && seam.patchB >= 4 && seam.patchB <= 7;
      const bool spoutTip =
          seam.patchA >= 16 && seam.patchA <= 17 && seam.patchB >= 18 && seam.patchB <= 19;
      EXPECT_TRUE(rimBody || spoutTip) << "patches " << seam.patchA << "/" << seam.patchB;
      EXPECT_NEAR(seam.ratio, rimBody ? 4.0f : 0.25f, 1e-5f)
          << "patches " << seam.patchA << "/" << seam.patchB;
    }
  }
  EXPECT_EQ(c1, 46u);
  EXPECT_EQ(g1, 6u);
}

TEST(UtahTeapotSeams, CrossSeamDerivativesMatchWhereTheDataIsSmooth) {
  const auto& patches = utahTeapotPatches();
  for (const Seam& seam : findSeams(patches)) {
    if (seam.continuity == Continuity::C0) {
      continue;
    }
    for (int step = 1; step < 8; ++step) {
      const float t = static_cast<float>(step) / 8.0f;
      const PatchSample sa = sampleEdge(patches[seam.patchA], seam.sideA, t);
      const PatchSample sb =
          sampleEdge(patches[seam.patchB], seam.sideB, seam.reversed ? 1.0f - t : t);
      const glm::vec3 leaveA = leavingDerivative(sa, seam.sideA);
      const glm::vec3 enterB = -leavingDerivative(sb, seam.sideB);
      ASSERT_GT(glm::length(leaveA), 1e-4f);
      EXPECT_GT(glm::dot(glm::normalize(leaveA), glm::normalize(enterB)), 0.99999f)
          << "patches " << seam.patchA << "/" << seam.patchB << " t=" << t;
      EXPECT_NEAR(glm::length(enterB) / glm::length(leaveA), seam.ratio, 1e-4f);
      if (seam.continuity == Continuity::C1) {
        EXPECT_LT(glm::length(leaveA - enterB), 1e-4f)
            << "patches " << seam.patchA << "/" << seam.patchB;
      }
    }
  }
}

// ---- Tessellation ------------------------------------------------------------------------

TEST(Tessellation, CountsAndIndicesForSeveralLevels) {
  const auto& patches = utahTeapotPatches();
  for (uint32_t level : {1u, 3u, 8u}) {
    const Mesh mesh = tessellatePatches(patches, level);
    EXPECT_EQ(mesh.triangleCount(), 32u * level * level * 2u);
    EXPECT_EQ(mesh.vertices.size(), 32u * (level + 1) * (level + 1));
    for (uint32_t index : mesh.indices) {
      ASSERT_LT(index, mesh.vertices.size());
    }
  }
  EXPECT_EQ(tessellatePatches(patches, 0).triangleCount(), 64u) << "level 0 is treated as 1";
}

TEST(Tessellation, NormalsAndTangentsAreFiniteUnitAndOrthogonal) {
  const Mesh mesh = tessellatePatches(utahTeapotPatches(), 6);
  for (const Vertex& v : mesh.vertices) {
    ASSERT_TRUE(std::isfinite(v.normal.x) && std::isfinite(v.normal.y) &&
                std::isfinite(v.normal.z));
    ASSERT_TRUE(std::isfinite(v.tangent.x) && std::isfinite(v.tangent.y) &&
                std::isfinite(v.tangent.z));
    EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(v.normal, glm::vec3(v.tangent)), 0.0f, 1e-4f);
    EXPECT_FLOAT_EQ(v.tangent.w, 1.0f) << "(u, v) runs along (T, N x T) on every patch";
    EXPECT_GE(v.uv.x, 0.0f);
    EXPECT_LE(v.uv.x, 1.0f);
    EXPECT_GE(v.uv.y, 0.0f);
    EXPECT_LE(v.uv.y, 1.0f);
    EXPECT_GE(v.position.y, -1e-6f);
  }
}

// The lid apex (patches 20-23) and base centre (28-31) are edges collapsed to a point:
// cross(dP/du, dP/dv) vanishes there, yet the normal must be the limit, straight up or down.
TEST(Tessellation, DegenerateCornersGetLimitNormals) {
  const auto& patches = utahTeapotPatches();
  for (std::size_t p : {20u, 21u, 22u, 23u, 28u, 29u, 30u, 31u}) {
    const float expectedY = p < 24 ? 1.0f : -1.0f;
    for (float v : {0.0f, 0.3f, 1.0f}) {
      const PatchSample s = evalBezierPatch(patches[p], 0.0f, v);
      EXPECT_LT(glm::length(glm::cross(s.dPdu, s.dPdv)), 1e-5f)
          << "patch " << p << " should be degenerate";
      EXPECT_GT(s.normal.y * expectedY, 0.999f) << "patch " << p << " v=" << v;
    }
  }
}

TEST(Tessellation, TrianglesAreCounterClockwiseSeenFromTheNormalSide) {
  const Mesh mesh = tessellatePatches(utahTeapotPatches(), 8);
  std::size_t checked = 0;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const Vertex& a = mesh.vertices[mesh.indices[3 * t]];
    const Vertex& b = mesh.vertices[mesh.indices[3 * t + 1]];
    const Vertex& c = mesh.vertices[mesh.indices[3 * t + 2]];
    const glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
    if (glm::length(face) < 1e-7f) {
      continue;  // the zero-area half of a quad at a collapsed edge
    }
    ++checked;
    EXPECT_GT(glm::dot(face, a.normal + b.normal + c.normal), 0.0f) << "triangle " << t;
  }
  EXPECT_GT(checked, mesh.triangleCount() * 9 / 10);
}

// Orientation, patch by patch: each connected group has an anchor whose outside is known,
// and the seam test below carries that orientation to every other patch in the group.
TEST(TeapotOrientation, AnchorsPointOutward) {
  const auto& patches = utahTeapotPatches();
  for (float u : kSampleParams) {
    for (float v : kSampleParams) {
      for (std::size_t p = 4; p < 12; ++p) {
        const PatchSample s = evalBezierPatch(patches[p], u, v);
        EXPECT_GT(glm::dot(s.normal, glm::vec3(s.position.x, 0.0f, s.position.z)), 0.0f)
            << "body " << p;
      }
      for (std::size_t p = 24; p < 32 && u <= 0.5f; ++p) {
        const float up = p < 28 ? 1.0f : -1.0f;  // lid faces up, bottom faces down
        EXPECT_GT(evalBezierPatch(patches[p], u, v).normal.y * up, 0.5f) << "patch " << p;
      }
    }
    // Handle and spout are tubes; the axis point is midway between the two edges lying in
    // the mirror plane z = 0, and the normal halfway round must point away from it. The
    // spout tip (18, 19) is a tube only up to u = 0.5: then its lip curls over into the
    // opening, like the pot's rim, and its outside faces the axis.
    for (std::size_t p = 12; p < 20 && (p < 18 || u <= 0.5f); ++p) {
      const glm::vec3 axis = 0.5f * (evalBezierPatch(patches[p], u, 0.0f).position +
                                     evalBezierPatch(patches[p], u, 1.0f).position);
      const PatchSample side = evalBezierPatch(patches[p], u, 0.5f);
      EXPECT_GT(glm::dot(side.normal, side.position - axis), 0.0f)
          << "tube patch " << p << " u=" << u;
    }
  }
}

TEST(TeapotOrientation, NormalsAgreeAcrossEverySeam) {
  const auto& patches = utahTeapotPatches();
  for (const Seam& seam : findSeams(patches)) {
    for (int step = 0; step <= 8; ++step) {
      const float t = static_cast<float>(step) / 8.0f;
      const glm::vec3 na = sampleEdge(patches[seam.patchA], seam.sideA, t).normal;
      const glm::vec3 nb =
          sampleEdge(patches[seam.patchB], seam.sideB, seam.reversed ? 1.0f - t : t).normal;
      EXPECT_GT(glm::dot(na, nb), 0.99f)
          << "patches " << seam.patchA << "/" << seam.patchB << " t=" << t;
    }
  }
}

}  // namespace
}  // namespace shadelab
