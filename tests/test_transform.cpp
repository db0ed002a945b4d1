// Each function is checked against hand-computed course formulas and cross-checked against GLM.

#define GLM_ENABLE_EXPERIMENTAL  // the glm/gtx headers (shear, to_string) are "experimental"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/string_cast.hpp>
#include <glm/gtx/transform2.hpp>
#include <numbers>
#include <string>

#include "core/scene/transform.h"

namespace shadelab {
namespace {

// Float products of a handful of terms of magnitude <= ~10 stay well inside this bound.
constexpr float kTolerance = 1e-5f;
constexpr float kPi = std::numbers::pi_v<float>;

const glm::mat4 kIdentity(1.0f);

// Expected matrices are written in the textbook's row layout; GLM stores them column-major.
glm::mat4 rows(glm::vec4 r0, glm::vec4 r1, glm::vec4 r2, glm::vec4 r3) {
  return glm::transpose(glm::mat4(r0, r1, r2, r3));
}

template <glm::length_t C, glm::length_t R>
testing::AssertionResult matricesNear(const glm::mat<C, R, float>& actual,
                                      const glm::mat<C, R, float>& expected,
                                      float tolerance = kTolerance) {
  for (glm::length_t c = 0; c < C; ++c) {
    for (glm::length_t r = 0; r < R; ++r) {
      if (std::abs(actual[c][r] - expected[c][r]) > tolerance) {
        return testing::AssertionFailure()
               << "row " << r << ", column " << c << ": " << actual[c][r] << " vs "
               << expected[c][r] << " (tolerance " << tolerance
               << ")\nactual rows: " << glm::to_string(glm::transpose(actual))
               << "\nexpected rows: " << glm::to_string(glm::transpose(expected));
      }
    }
  }
  return testing::AssertionSuccess();
}

template <glm::length_t L>
testing::AssertionResult vectorsNear(const glm::vec<L, float>& actual,
                                     const glm::vec<L, float>& expected,
                                     float tolerance = kTolerance) {
  for (glm::length_t i = 0; i < L; ++i) {
    if (std::abs(actual[i] - expected[i]) > tolerance) {
      return testing::AssertionFailure()
             << "component " << i << ": " << glm::to_string(actual) << " vs "
             << glm::to_string(expected) << " (tolerance " << tolerance << ")";
    }
  }
  return testing::AssertionSuccess();
}

glm::vec3 transformPoint(const glm::mat4& m, glm::vec3 p) {
  return glm::vec3(m * glm::vec4(p, 1.0f));
}

glm::vec3 transformDirection(const glm::mat4& m, glm::vec3 v) {
  return glm::vec3(m * glm::vec4(v, 0.0f));
}

// Divides by hand so projection tests do not depend on perspectiveDivide().
glm::vec3 project(const glm::mat4& projection, glm::vec3 p) {
  const glm::vec4 clip = projection * glm::vec4(p, 1.0f);
  return glm::vec3(clip) / clip.w;
}

// GLM's *_ZO projections keep clip y up; Vulkan's y points down, so negate the y row.
glm::mat4 flipY(glm::mat4 m) {
  for (int c = 0; c < 4; ++c) {
    m[c][1] = -m[c][1];
  }
  return m;
}

float radians(float degrees) {
  return degrees * kPi / 180.0f;
}

const float kAngles[] = {-2.5f, -0.4f, 0.0f, 0.3f, 1.0f, kPi / 2, 2.8f};

// An odd number of negative scale factors mirrors, whatever the rotation;
// the sign survives scales whose float determinant would be 0 or infinite.
TEST(Mirrors, OddNumberOfNegativeScalesMirrors) {
  glm::mat4 turned = rotationAxis(glm::vec3(1.0f, 2.0f, 3.0f), 0.7f);
  EXPECT_FALSE(mirrors(turned));
  EXPECT_TRUE(mirrors(turned * scaling(glm::vec3(-1.0f, 1.0f, 1.0f))));
  EXPECT_FALSE(mirrors(scaling(glm::vec3(-1.0f, -1.0f, 1.0f)) * turned));
  EXPECT_TRUE(mirrors(scaling(glm::vec3(-2.0f, -3.0f, -0.5f))));
  EXPECT_TRUE(mirrors(scaling(glm::vec3(-1e-20f, 1e-20f, 1e-20f))));
  EXPECT_TRUE(mirrors(scaling(glm::vec3(1e20f, -1e20f, 1e20f))));
  EXPECT_FALSE(mirrors(scaling(glm::vec3(0.0f, -1.0f, 1.0f))));  // collapsed, not mirrored
}

TEST(Translation, OffsetIsInTheLastColumn) {
  const glm::mat4 m = translation({2.0f, -3.0f, 4.0f});
  EXPECT_TRUE(matricesNear(m, rows({1, 0, 0, 2}, {0, 1, 0, -3}, {0, 0, 1, 4}, {0, 0, 0, 1})));
  EXPECT_TRUE(vectorsNear(m[3], glm::vec4(2.0f, -3.0f, 4.0f, 1.0f)));
  EXPECT_TRUE(vectorsNear(transformPoint(m, {1, 1, 1}), glm::vec3(3.0f, -2.0f, 5.0f)));
  EXPECT_TRUE(vectorsNear(transformDirection(m, {1, 1, 1}), glm::vec3(1.0f, 1.0f, 1.0f)));
}

TEST(Translation, MatchesGlm) {
  const glm::vec3 d(-1.5f, 0.25f, 7.0f);
  EXPECT_TRUE(matricesNear(translation(d), glm::translate(kIdentity, d)));
}

TEST(RotationAxes, QuarterTurnsAreCounterClockwise) {
  const glm::mat4 x = rotationX(kPi / 2);
  EXPECT_TRUE(vectorsNear(transformPoint(x, {0, 1, 0}), glm::vec3(0, 0, 1)));
  EXPECT_TRUE(vectorsNear(transformPoint(x, {0, 0, 1}), glm::vec3(0, -1, 0)));
  EXPECT_TRUE(vectorsNear(transformPoint(x, {1, 0, 0}), glm::vec3(1, 0, 0)));
  const glm::mat4 y = rotationY(kPi / 2);
  EXPECT_TRUE(vectorsNear(transformPoint(y, {0, 0, 1}), glm::vec3(1, 0, 0)));
  EXPECT_TRUE(vectorsNear(transformPoint(y, {1, 0, 0}), glm::vec3(0, 0, -1)));
  EXPECT_TRUE(vectorsNear(transformPoint(y, {0, 1, 0}), glm::vec3(0, 1, 0)));
  const glm::mat4 z = rotationZ(kPi / 2);
  EXPECT_TRUE(vectorsNear(transformPoint(z, {1, 0, 0}), glm::vec3(0, 1, 0)));
  EXPECT_TRUE(vectorsNear(transformPoint(z, {0, 1, 0}), glm::vec3(-1, 0, 0)));
  EXPECT_TRUE(vectorsNear(transformPoint(z, {0, 0, 1}), glm::vec3(0, 0, 1)));
}

TEST(RotationAxes, TextbookMatricesAt30Degrees) {
  const float c = std::sqrt(3.0f) / 2;  // cos 30
  const float s = 0.5f;                 // sin 30
  const float a = radians(30.0f);
  EXPECT_TRUE(
      matricesNear(rotationX(a), rows({1, 0, 0, 0}, {0, c, -s, 0}, {0, s, c, 0}, {0, 0, 0, 1})));
  EXPECT_TRUE(
      matricesNear(rotationY(a), rows({c, 0, s, 0}, {0, 1, 0, 0}, {-s, 0, c, 0}, {0, 0, 0, 1})));
  EXPECT_TRUE(
      matricesNear(rotationZ(a), rows({c, -s, 0, 0}, {s, c, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1})));
}

TEST(RotationAxes, MatchGlmRotate) {
  for (float a : kAngles) {
    SCOPED_TRACE(a);
    EXPECT_TRUE(matricesNear(rotationX(a), glm::rotate(kIdentity, a, glm::vec3(1, 0, 0))));
    EXPECT_TRUE(matricesNear(rotationY(a), glm::rotate(kIdentity, a, glm::vec3(0, 1, 0))));
    EXPECT_TRUE(matricesNear(rotationZ(a), glm::rotate(kIdentity, a, glm::vec3(0, 0, 1))));
  }
}

TEST(RotationAxis, NonUnitCoordinateAxesAndTheDiagonal) {
  const float a = 0.7f;
  EXPECT_TRUE(matricesNear(rotationAxis({3, 0, 0}, a), rotationX(a)));
  EXPECT_TRUE(matricesNear(rotationAxis({0, 0.5f, 0}, a), rotationY(a)));
  EXPECT_TRUE(matricesNear(rotationAxis({0, 0, 5}, a), rotationZ(a)));
  // The (1,1,1) axis is the symmetry axis of x -> y -> z -> x.
  const glm::mat4 m = rotationAxis({1, 1, 1}, 2 * kPi / 3);
  EXPECT_TRUE(matricesNear(m, rows({0, 0, 1, 0}, {1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 0, 1})));
}

TEST(RotationAxis, LeavesTheAxisFixedAndPreservesLengths) {
  const glm::vec3 axis(1.0f, -2.0f, 0.5f);
  const glm::mat4 m = rotationAxis(axis, 1.1f);
  EXPECT_TRUE(vectorsNear(transformDirection(m, axis), axis));
  const glm::vec3 v(0.3f, 4.0f, -1.0f);
  EXPECT_NEAR(glm::length(transformDirection(m, v)), glm::length(v), kTolerance);
  EXPECT_NEAR(glm::determinant(m), 1.0f, kTolerance);
}

TEST(RotationAxis, MatchesGlmRotate) {
  const glm::vec3 axes[] = {{1, -2, 0.5f}, {0, 3, 4}, {-1, -1, 1}};
  for (const glm::vec3& axis : axes) {
    for (float a : kAngles) {
      SCOPED_TRACE(a);
      EXPECT_TRUE(matricesNear(rotationAxis(axis, a), glm::rotate(kIdentity, a, axis)));
    }
  }
}

TEST(RotationAboutPoint, KeepsThePivotFixedAndMovesOtherPoints) {
  const glm::vec3 pivot(3.0f, -1.0f, 2.0f);
  const glm::mat4 tilted = rotationAboutPoint(pivot, {1, 2, -1}, 0.9f);
  EXPECT_TRUE(vectorsNear(transformPoint(tilted, pivot), pivot));
  const glm::mat4 quarterZ = rotationAboutPoint({1, 2, 0}, {0, 0, 1}, kPi / 2);
  EXPECT_TRUE(vectorsNear(transformPoint(quarterZ, {2, 2, 0}), glm::vec3(1, 3, 0)));
  EXPECT_TRUE(vectorsNear(transformPoint(quarterZ, {1, 3, 0}), glm::vec3(0, 2, 0)));
  EXPECT_TRUE(vectorsNear(transformPoint(quarterZ, {1, 2, 5}), glm::vec3(1, 2, 5)));
  const glm::mat4 halfY = rotationAboutPoint(pivot, {0, 1, 0}, kPi);
  EXPECT_TRUE(vectorsNear(transformPoint(halfY, {4, -1, 2}), glm::vec3(2, -1, 2)));
  EXPECT_TRUE(vectorsNear(transformPoint(halfY, {3, 7, 3}), glm::vec3(3, 7, 1)));
}

TEST(RotationAboutPoint, MatchesGlmComposition) {
  const glm::vec3 pivot(-2.0f, 0.5f, 4.0f);
  const glm::vec3 axis(0.0f, 1.0f, 1.0f);
  const float a = 1.3f;
  const glm::mat4 expected = glm::translate(kIdentity, pivot) * glm::rotate(kIdentity, a, axis) *
                             glm::translate(kIdentity, -pivot);
  EXPECT_TRUE(matricesNear(rotationAboutPoint(pivot, axis, a), expected));
}

TEST(Scaling, FactorsOnTheDiagonalAndMatchesGlm) {
  const glm::vec3 factors(2.0f, -3.0f, 0.5f);
  const glm::mat4 m = scaling(factors);
  EXPECT_TRUE(matricesNear(m, rows({2, 0, 0, 0}, {0, -3, 0, 0}, {0, 0, 0.5f, 0}, {0, 0, 0, 1})));
  EXPECT_TRUE(vectorsNear(transformPoint(m, {1, 2, 4}), glm::vec3(2, -6, 2)));
  EXPECT_TRUE(matricesNear(m, glm::scale(kIdentity, factors)));
}

TEST(Shearing, TextbookMatrix) {
  const glm::mat4 m = shearing({.xy = 1, .xz = 2, .yx = 3, .yz = 4, .zx = 5, .zy = 6});
  EXPECT_TRUE(matricesNear(m, rows({1, 1, 2, 0}, {3, 1, 4, 0}, {5, 6, 1, 0}, {0, 0, 0, 1})));
}

TEST(Shearing, EachCoefficientFollowsTheFormula) {
  const glm::mat4 m = shearing({.xy = 1, .xz = 2, .yx = 3, .yz = 4, .zx = 5, .zy = 6});
  // x' = 2 + 1*3 + 2*5, y' = 3 + 3*2 + 4*5, z' = 5 + 5*2 + 6*3
  EXPECT_TRUE(vectorsNear(transformPoint(m, {2, 3, 5}), glm::vec3(15, 29, 33)));
  const glm::mat4 onlyXY = shearing({.xy = 0.5f});
  EXPECT_TRUE(vectorsNear(transformPoint(onlyXY, {1, 4, 7}), glm::vec3(3, 4, 7)));
}

TEST(Shearing, SingleAxisShearsMatchGlm) {
  // glm::shearX3D shears y and z in proportion to x, and so on.
  EXPECT_TRUE(
      matricesNear(shearing({.yx = 0.5f, .zx = -2.0f}), glm::shearX3D(kIdentity, 0.5f, -2.0f)));
  EXPECT_TRUE(
      matricesNear(shearing({.xy = 1.5f, .zy = 3.0f}), glm::shearY3D(kIdentity, 1.5f, 3.0f)));
  EXPECT_TRUE(
      matricesNear(shearing({.xz = -0.25f, .yz = 2.0f}), glm::shearZ3D(kIdentity, -0.25f, 2.0f)));
}

TEST(Inverse, TranslationInverseIsNegatedOffset) {
  const glm::vec3 d(2.0f, -3.0f, 4.0f);
  const glm::mat4 inv = translationInverse(d);
  EXPECT_TRUE(matricesNear(inv, rows({1, 0, 0, -2}, {0, 1, 0, 3}, {0, 0, 1, -4}, {0, 0, 0, 1})));
  EXPECT_TRUE(matricesNear(inv * translation(d), kIdentity));
  EXPECT_TRUE(matricesNear(translation(d) * inv, kIdentity));
  EXPECT_TRUE(matricesNear(inv, glm::inverse(glm::translate(kIdentity, d))));
}

TEST(Inverse, RotationInverseIsTransposeAndUndoesRotations) {
  const float c = std::sqrt(3.0f) / 2;
  const float s = 0.5f;
  const glm::mat4 inv = rotationInverse(rotationZ(radians(30.0f)));
  EXPECT_TRUE(matricesNear(inv, rows({c, s, 0, 0}, {-s, c, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1})));
  EXPECT_TRUE(matricesNear(inv, rotationZ(radians(-30.0f))));
  for (float a : kAngles) {
    SCOPED_TRACE(a);
    const glm::mat4 r = rotationAxis({1, -2, 0.5f}, a);
    const glm::mat4 rInv = rotationInverse(r);
    EXPECT_TRUE(matricesNear(rInv * r, kIdentity));
    EXPECT_TRUE(matricesNear(r * rInv, kIdentity));
    EXPECT_TRUE(matricesNear(rInv, glm::inverse(glm::rotate(kIdentity, a, {1, -2, 0.5f}))));
  }
}

TEST(Inverse, ScalingInverseIsReciprocalFactors) {
  const glm::vec3 s(2.0f, -0.25f, 5.0f);
  const glm::mat4 inv = scalingInverse(s);
  EXPECT_TRUE(
      matricesNear(inv, rows({0.5f, 0, 0, 0}, {0, -4, 0, 0}, {0, 0, 0.2f, 0}, {0, 0, 0, 1})));
  EXPECT_TRUE(matricesNear(inv * scaling(s), kIdentity));
  EXPECT_TRUE(matricesNear(scaling(s) * inv, kIdentity));
  EXPECT_TRUE(matricesNear(inv, glm::inverse(glm::scale(kIdentity, s))));
}

TEST(Inverse, ShearInverse) {
  EXPECT_TRUE(matricesNear(shearing({.xy = -1.5f}) * shearing({.xy = 1.5f}), kIdentity));
  const glm::mat4 m = shearing({.xy = 1, .xz = 2, .yx = 3, .yz = 4, .zx = 5, .zy = 6});
  EXPECT_TRUE(matricesNear(glm::inverse(m) * m, kIdentity, 1e-4f));
  EXPECT_TRUE(matricesNear(m * glm::inverse(m), kIdentity, 1e-4f));
}

TEST(LookAt, MapsEyeToOriginAtToNegativeZAndUpToPlusY) {
  const glm::vec3 eye(3.0f, 4.0f, 5.0f);
  const glm::vec3 at(-1.0f, 2.0f, 0.0f);
  const glm::mat4 view = lookAt(eye, at, {0, 1, 0});
  EXPECT_TRUE(vectorsNear(transformPoint(view, eye), glm::vec3(0, 0, 0)));
  const float distance = glm::length(at - eye);
  EXPECT_TRUE(vectorsNear(transformPoint(view, at), glm::vec3(0, 0, -distance)));
  const glm::vec3 upInEye = transformPoint(view, eye + glm::vec3(0, 1, 0));
  EXPECT_NEAR(upInEye.x, 0.0f, kTolerance);
  EXPECT_GT(upInEye.y, 0.0f);
}

TEST(LookAt, TextbookCases) {
  // Camera on +z looking at the origin: the view transform is just a translation.
  EXPECT_TRUE(matricesNear(lookAt({0, 0, 5}, {0, 0, 0}, {0, 1, 0}),
                           rows({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, -5}, {0, 0, 0, 1})));
  // Camera on +x looking at the origin: world -x becomes eye -z, world z becomes eye -x.
  EXPECT_TRUE(matricesNear(lookAt({5, 0, 0}, {0, 0, 0}, {0, 1, 0}),
                           rows({0, 0, -1, 0}, {0, 1, 0, 0}, {1, 0, 0, -5}, {0, 0, 0, 1})));
}

TEST(LookAt, MatchesGlmLookAtRH) {
  struct Camera {
    glm::vec3 eye, at, up;
  };
  const Camera cameras[] = {{{3, 4, 5}, {-1, 2, 0}, {0, 1, 0}},
                            {{0, 10, 0.1f}, {0, 0, 0}, {0, 1, 0}},
                            {{-2, 1, -3}, {1, 1, 1}, {0.3f, 1, 0.2f}}};
  for (const Camera& c : cameras) {
    EXPECT_TRUE(matricesNear(lookAt(c.eye, c.at, c.up), glm::lookAtRH(c.eye, c.at, c.up)));
  }
}

TEST(FrustumGL, TextbookElements) {
  // l=-1 r=3 b=-2 t=6 n=1 f=3: 2n/(r-l)=0.5, (r+l)/(r-l)=0.5, 2n/(t-b)=0.25,
  // (t+b)/(t-b)=0.5, -(f+n)/(f-n)=-2, -2fn/(f-n)=-3
  const glm::mat4 m = frustumGL(-1, 3, -2, 6, 1, 3);
  EXPECT_TRUE(matricesNear(
      m, rows({0.5f, 0, 0.5f, 0}, {0, 0.25f, 0.5f, 0}, {0, 0, -2, -3}, {0, 0, -1, 0})));
}

TEST(FrustumGL, MapsTheViewVolumeToTheNdcCube) {
  const float l = -1, r = 3, b = -2, t = 6, n = 1, f = 3;
  const glm::mat4 m = frustumGL(l, r, b, t, n, f);
  EXPECT_TRUE(vectorsNear(project(m, {l, b, -n}), glm::vec3(-1, -1, -1)));
  EXPECT_TRUE(vectorsNear(project(m, {r, t, -n}), glm::vec3(1, 1, -1)));
  EXPECT_TRUE(vectorsNear(project(m, {r * f / n, t * f / n, -f}), glm::vec3(1, 1, 1)));
}

TEST(FrustumGL, MatchesGlm) {
  EXPECT_TRUE(matricesNear(frustumGL(-1, 3, -2, 6, 1, 3),
                           glm::frustumRH_NO(-1.0f, 3.0f, -2.0f, 6.0f, 1.0f, 3.0f)));
  EXPECT_TRUE(matricesNear(frustumGL(-0.4f, 0.4f, -0.3f, 0.3f, 0.5f, 50),
                           glm::frustumRH_NO(-0.4f, 0.4f, -0.3f, 0.3f, 0.5f, 50.0f)));
}

TEST(PerspectiveGL, TextbookElements) {
  // fovy=90 deg so cot(fovy/2)=1; aspect=2, n=1, f=3: (f+n)/(n-f)=-2, 2fn/(n-f)=-3
  const glm::mat4 m = perspectiveGL(radians(90.0f), 2, 1, 3);
  EXPECT_TRUE(matricesNear(m, rows({0.5f, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, -2, -3}, {0, 0, -1, 0})));
}

TEST(PerspectiveGL, IsTheSymmetricFrustum) {
  const float fovy = radians(60.0f), aspect = 1.5f, n = 0.5f, f = 40.0f;
  const float t = n * std::tan(fovy / 2);
  EXPECT_TRUE(matricesNear(perspectiveGL(fovy, aspect, n, f),
                           frustumGL(-aspect * t, aspect * t, -t, t, n, f)));
}

TEST(PerspectiveGL, NearToMinusOneFarToOneAndMatchesGlm) {
  const glm::mat4 m = perspectiveGL(radians(60.0f), 1.5f, 0.5f, 40.0f);
  EXPECT_NEAR(project(m, {0.1f, 0.2f, -0.5f}).z, -1.0f, kTolerance);
  EXPECT_NEAR(project(m, {3.0f, -2.0f, -40.0f}).z, 1.0f, kTolerance);
  EXPECT_TRUE(matricesNear(perspectiveGL(radians(60.0f), 1.5f, 0.5f, 40.0f),
                           glm::perspectiveRH_NO(radians(60.0f), 1.5f, 0.5f, 40.0f)));
}

TEST(OrthographicGL, TextbookElementsMapTheBoxToTheNdcCubeAndMatchGlm) {
  // l=-1 r=3 b=-2 t=6 n=1 f=3: 2/(r-l)=0.5, -(r+l)/(r-l)=-0.5, 2/(t-b)=0.25,
  // -(t+b)/(t-b)=-0.5, -2/(f-n)=-1, -(f+n)/(f-n)=-2
  const glm::mat4 m = orthographicGL(-1, 3, -2, 6, 1, 3);
  EXPECT_TRUE(matricesNear(
      m, rows({0.5f, 0, 0, -0.5f}, {0, 0.25f, 0, -0.5f}, {0, 0, -1, -2}, {0, 0, 0, 1})));
  EXPECT_TRUE(vectorsNear(project(m, {-1, -2, -1}), glm::vec3(-1, -1, -1)));
  EXPECT_TRUE(vectorsNear(project(m, {3, 6, -3}), glm::vec3(1, 1, 1)));
  EXPECT_TRUE(matricesNear(m, glm::orthoRH_NO(-1.0f, 3.0f, -2.0f, 6.0f, 1.0f, 3.0f)));
}

TEST(VulkanClipCorrection, TextbookRowsFlipYAndMapDepthToZeroOne) {
  const glm::mat4 m = vulkanClipCorrection();
  EXPECT_TRUE(matricesNear(m, rows({1, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, 0.5f, 0.5f}, {0, 0, 0, 1})));
  const glm::vec4 nearClip = m * glm::vec4(0.2f, 0.4f, -2.0f, 2.0f);  // GL NDC z = -1
  EXPECT_TRUE(vectorsNear(glm::vec3(nearClip) / nearClip.w, glm::vec3(0.1f, -0.2f, 0.0f)));
  const glm::vec4 farClip = m * glm::vec4(0.2f, 0.4f, 2.0f, 2.0f);  // GL NDC z = 1
  EXPECT_TRUE(vectorsNear(glm::vec3(farClip) / farClip.w, glm::vec3(0.1f, -0.2f, 1.0f)));
}

TEST(Frustum, TextbookElements) {
  // Same numbers as FrustumGL: y row negated, depth row f/(n-f)=-1.5, -fn/(f-n)=-1.5
  const glm::mat4 m = frustum(-1, 3, -2, 6, 1, 3);
  EXPECT_TRUE(matricesNear(
      m, rows({0.5f, 0, 0.5f, 0}, {0, -0.25f, -0.5f, 0}, {0, 0, -1.5f, -1.5f}, {0, 0, -1, 0})));
}

TEST(Frustum, NearToZeroFarToOneAndTopToMinusY) {
  const float l = -1, r = 3, b = -2, t = 6, n = 1, f = 3;
  const glm::mat4 m = frustum(l, r, b, t, n, f);
  EXPECT_TRUE(vectorsNear(project(m, {l, t, -n}), glm::vec3(-1, -1, 0)));
  EXPECT_TRUE(vectorsNear(project(m, {r * f / n, b * f / n, -f}), glm::vec3(1, 1, 1)));
}

TEST(Frustum, MatchesGlmZeroToOneWithYFlipped) {
  EXPECT_TRUE(matricesNear(frustum(-1, 3, -2, 6, 1, 3),
                           flipY(glm::frustumRH_ZO(-1.0f, 3.0f, -2.0f, 6.0f, 1.0f, 3.0f))));
  EXPECT_TRUE(matricesNear(frustum(-0.4f, 0.4f, -0.3f, 0.3f, 0.5f, 50),
                           flipY(glm::frustumRH_ZO(-0.4f, 0.4f, -0.3f, 0.3f, 0.5f, 50.0f))));
}

TEST(Perspective, TextbookElementsNearToZeroFarToOneUpToMinusY) {
  const glm::mat4 m = perspective(radians(90.0f), 2, 1, 3);
  EXPECT_TRUE(
      matricesNear(m, rows({0.5f, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, -1.5f, -1.5f}, {0, 0, -1, 0})));
  const glm::vec3 nearPoint = project(m, {0.1f, 0.2f, -1.0f});
  EXPECT_NEAR(nearPoint.z, 0.0f, kTolerance);
  EXPECT_LT(nearPoint.y, 0.0f);
  EXPECT_NEAR(project(m, {3.0f, -2.0f, -3.0f}).z, 1.0f, kTolerance);
}

TEST(Perspective, MatchesGlmZeroToOneWithYFlipped) {
  EXPECT_TRUE(matricesNear(perspective(radians(60.0f), 1.5f, 0.5f, 40.0f),
                           flipY(glm::perspectiveRH_ZO(radians(60.0f), 1.5f, 0.5f, 40.0f))));
}

TEST(Orthographic, NearToZeroFarToOneAndMatchesGlm) {
  const glm::mat4 m = orthographic(-1, 3, -2, 6, 1, 3);
  EXPECT_TRUE(vectorsNear(project(m, {-1, 6, -1}), glm::vec3(-1, -1, 0)));
  EXPECT_TRUE(vectorsNear(project(m, {3, -2, -3}), glm::vec3(1, 1, 1)));
  EXPECT_TRUE(matricesNear(m, flipY(glm::orthoRH_ZO(-1.0f, 3.0f, -2.0f, 6.0f, 1.0f, 3.0f))));
}

TEST(PerspectiveReversedZ, TextbookElementsNearToOneFarToZero) {
  // n=1 f=3: n/(f-n)=0.5, fn/(f-n)=1.5
  const glm::mat4 m = perspectiveReversedZ(radians(90.0f), 2, 1, 3);
  EXPECT_TRUE(
      matricesNear(m, rows({0.5f, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, 0.5f, 1.5f}, {0, 0, -1, 0})));
  EXPECT_NEAR(project(m, {0.1f, 0.2f, -1.0f}).z, 1.0f, kTolerance);
  EXPECT_NEAR(project(m, {3.0f, -2.0f, -3.0f}).z, 0.0f, kTolerance);
}

TEST(PerspectiveReversedZ, IsOneMinusStandardDepth) {
  const glm::mat4 standard = perspective(radians(60.0f), 1.5f, 0.5f, 40.0f);
  const glm::mat4 reversed = perspectiveReversedZ(radians(60.0f), 1.5f, 0.5f, 40.0f);
  for (float z : {-0.5f, -0.9f, -2.0f, -10.0f, -39.0f}) {
    SCOPED_TRACE(z);
    const glm::vec3 p(0.3f, -0.2f, z);
    const glm::vec3 s = project(standard, p);
    const glm::vec3 r = project(reversed, p);
    EXPECT_TRUE(vectorsNear(r, glm::vec3(s.x, s.y, 1.0f - s.z)));
  }
}

TEST(PerspectiveReversedZ, MatchesGlmWithNearAndFarSwapped) {
  EXPECT_TRUE(matricesNear(perspectiveReversedZ(radians(60.0f), 1.5f, 0.5f, 40.0f),
                           flipY(glm::perspectiveRH_ZO(radians(60.0f), 1.5f, 40.0f, 0.5f))));
}

TEST(ReverseDepth, TextbookRowsTurnDepthIntoOneMinusDepth) {
  EXPECT_TRUE(
      matricesNear(reverseDepth(), rows({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, -1, 1}, {0, 0, 0, 1})));
  // Written out as its own formula, the reversed perspective equals the standard one
  // with depth reversed afterwards.
  EXPECT_TRUE(matricesNear(perspectiveReversedZ(radians(60.0f), 1.5f, 0.5f, 40.0f),
                           reverseDepth() * perspective(radians(60.0f), 1.5f, 0.5f, 40.0f)));
}

TEST(FrustumReversedZ, NearToOneFarToZero) {
  const glm::mat4 m = frustumReversedZ(-1, 3, -2, 6, 1, 3);
  // The near-plane window's corners land at depth 1, points on the far plane at 0.
  EXPECT_TRUE(vectorsNear(project(m, {-1, 6, -1}), glm::vec3(-1, -1, 1)));
  EXPECT_TRUE(vectorsNear(project(m, {9, -6, -3}), glm::vec3(1, 1, 0)));
  EXPECT_NEAR(project(m, {0, 0, -1.5f}).z,
              1.0f - project(frustum(-1, 3, -2, 6, 1, 3), {0, 0, -1.5f}).z, kTolerance);
}

TEST(OrthographicReversedZ, NearToOneFarToZeroLinearInBetween) {
  const glm::mat4 m = orthographicReversedZ(-1, 3, -2, 6, 1, 3);
  EXPECT_TRUE(vectorsNear(project(m, {-1, 6, -1}), glm::vec3(-1, -1, 1)));
  EXPECT_TRUE(vectorsNear(project(m, {3, -2, -3}), glm::vec3(1, 1, 0)));
  // Orthographic depth is linear: halfway between the planes is 0.5 either way round.
  EXPECT_NEAR(project(m, {0, 0, -2}).z, 0.5f, kTolerance);
  EXPECT_TRUE(matricesNear(m, flipY(glm::orthoRH_ZO(-1.0f, 3.0f, -2.0f, 6.0f, 3.0f, 1.0f))));
}

TEST(ViewportTransform, NdcCornersMapToTheViewportRectangle) {
  const Viewport vp{
      .x = 10, .y = 20, .width = 640, .height = 480, .minDepth = 0.1f, .maxDepth = 0.9f};
  EXPECT_TRUE(vectorsNear(viewportTransform({-1, -1, 0}, vp), glm::vec3(10, 20, 0.1f)));
  EXPECT_TRUE(vectorsNear(viewportTransform({1, 1, 1}, vp), glm::vec3(650, 500, 0.9f)));
  EXPECT_TRUE(vectorsNear(viewportTransform({0, 0, 0.5f}, vp), glm::vec3(330, 260, 0.5f)));
  // xf = 10 + 320 * 1.5, yf = 20 + 240 * 0.5, zf = 0.1 + 0.25 * 0.8
  EXPECT_TRUE(
      vectorsNear(viewportTransform({0.5f, -0.5f, 0.25f}, vp), glm::vec3(490, 140, 0.3f), 1e-4f));
}

TEST(PerspectiveDivide, DividesByW) {
  EXPECT_TRUE(vectorsNear(perspectiveDivide({2, 4, -6, 2}), glm::vec3(1, 2, -3)));
  EXPECT_TRUE(vectorsNear(perspectiveDivide({1, 2, 3, -0.5f}), glm::vec3(-2, -4, -6)));
}

TEST(NormalMatrix, TextbookCases) {
  // Non-uniform scale: inverse transpose of diag(2, 4, 0.5) is diag(0.5, 0.25, 2).
  EXPECT_TRUE(
      matricesNear(normalMatrix(scaling({2, 4, 0.5f})),
                   glm::mat3(glm::vec3(0.5f, 0, 0), glm::vec3(0, 0.25f, 0), glm::vec3(0, 0, 2))));
  // Rigid motion: normals rotate with the object and ignore the translation.
  const float c = std::sqrt(3.0f) / 2;
  const float s = 0.5f;
  EXPECT_TRUE(matricesNear(normalMatrix(translation({5, 6, 7}) * rotationZ(radians(30.0f))),
                           glm::mat3(glm::vec3(c, s, 0), glm::vec3(-s, c, 0), glm::vec3(0, 0, 1))));
}

TEST(NormalMatrix, MatchesGlmInverseTranspose) {
  const glm::mat4 modelView = lookAt({3, 4, 5}, {0, 0, 0}, {0, 1, 0}) * translation({1, -2, 0.5f}) *
                              rotationAxis({1, 1, 0}, 0.8f) * scaling({2.0f, 0.5f, 3.0f}) *
                              shearing({.xy = 0.3f, .zx = -0.6f});
  EXPECT_TRUE(
      matricesNear(normalMatrix(modelView), glm::inverseTranspose(glm::mat3(modelView)), 1e-4f));
}

TEST(NormalMatrix, KeepsNormalsPerpendicularUnderNonUniformScale) {
  // The plane x + y = 0 has normal (1,1,0) and tangents (1,-1,0) and (0,0,1).
  const glm::vec3 normal(1, 1, 0);
  const glm::vec3 tangents[] = {{1, -1, 0}, {0, 0, 1}};
  const glm::mat4 model = rotationX(0.4f) * scaling({2.0f, 1.0f, 1.0f});

  const glm::vec3 goodNormal = normalMatrix(model) * normal;
  const glm::vec3 wrongNormal = glm::mat3(model) * normal;
  for (const glm::vec3& t : tangents) {
    const glm::vec3 movedTangent = transformDirection(model, t);
    EXPECT_NEAR(glm::dot(goodNormal, movedTangent), 0.0f, kTolerance);
  }
  // Transforming the normal like a tangent shears it off the surface: (2,1,0).(2,-1,0) = 3.
  const glm::vec3 movedTangent = transformDirection(model, tangents[0]);
  EXPECT_NEAR(glm::dot(wrongNormal, movedTangent), 3.0f, kTolerance);
}

}  // namespace
}  // namespace shadelab
