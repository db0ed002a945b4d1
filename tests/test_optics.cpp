// Reflection, refraction and Fresnel (core/trace/optics.h) against the formulas
// and angles they come from, and the environment's addressing conventions
// (core/scene/environment.h): Vulkan's cube face table, the panorama mapping, the sky.
#include <gtest/gtest.h>

#include <cmath>

#include "core/scene/environment.h"
#include "core/trace/optics.h"

namespace shadelab {
namespace {

constexpr float kPi = 3.14159265358979f;

// A unit vector at `degrees` from the normal +y, in the xy plane (x > 0).
glm::vec3 atAngle(float degrees) {
  float a = glm::radians(degrees);
  return {std::sin(a), std::cos(a), 0.0f};
}

float angleDegrees(glm::vec3 a, glm::vec3 b) {
  return glm::degrees(
      std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)));
}

TEST(Optics, ReflectionIsTwoNdotVNMinusV) {
  glm::vec3 N{0.0f, 1.0f, 0.0f};
  for (float degrees : {0.0f, 10.0f, 45.0f, 80.0f, 89.0f}) {
    glm::vec3 V = atAngle(degrees);
    glm::vec3 R = reflectionDirection(N, V);
    // Angle of reflection = angle of incidence, on the other side of N, in the plane of N and V.
    EXPECT_NEAR(angleDegrees(R, N), degrees, 1e-3f);
    EXPECT_NEAR(R.x, -V.x, 1e-6f);
    EXPECT_NEAR(R.z, 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(R), 1.0f, 1e-6f);
  }
  // An arbitrary tilted normal: the textbook formula written out.
  glm::vec3 tilted = glm::normalize(glm::vec3(0.3f, 0.8f, -0.5f));
  glm::vec3 V = glm::normalize(glm::vec3(-0.2f, 0.7f, 0.6f));
  glm::vec3 expected = 2.0f * glm::dot(tilted, V) * tilted - V;
  glm::vec3 R = reflectionDirection(tilted, V);
  EXPECT_NEAR(glm::length(R - expected), 0.0f, 1e-6f);
}

// Snell's law n1 sin(theta_i) = n2 sin(theta_t), measured on the returned direction.
TEST(Optics, RefractionObeysSnellsLaw) {
  glm::vec3 N{0.0f, 1.0f, 0.0f};
  for (float ior : {1.33f, 1.5f, 2.4f}) {
    for (float degrees : {0.0f, 15.0f, 30.0f, 60.0f, 85.0f}) {
      SCOPED_TRACE(testing::Message() << "ior " << ior << ", theta_i " << degrees);
      glm::vec3 V = atAngle(degrees);
      Refraction refraction = refractionDirection(N, V, 1.0f / ior);
      ASSERT_FALSE(refraction.totalInternalReflection);
      glm::vec3 T = refraction.direction;
      EXPECT_NEAR(glm::length(T), 1.0f, 1e-5f);
      float thetaT = glm::radians(angleDegrees(T, -N));
      EXPECT_NEAR(std::sin(thetaT) * ior, std::sin(glm::radians(degrees)), 1e-4f);
      EXPECT_NEAR(refraction.cosTransmitted, std::cos(thetaT), 1e-4f);
      // Into the surface, on the far side of N from the viewer, in the plane of incidence.
      EXPECT_LT(T.y, 0.0f);
      EXPECT_LE(T.x, 1e-6f);
      EXPECT_NEAR(T.z, 0.0f, 1e-6f);
    }
  }
}

// Leaving a denser medium (eta = n1 / n2 > 1) beyond the critical angle
// asin(n2 / n1), no light is transmitted: the helper returns R, never NaN.
TEST(Optics, TotalInternalReflectionReturnsTheReflection) {
  glm::vec3 N{0.0f, 1.0f, 0.0f};
  float eta = 1.5f;
  float critical = glm::degrees(std::asin(1.0f / eta));  // 41.8 degrees
  Refraction below = refractionDirection(N, atAngle(critical - 0.5f), eta);
  EXPECT_FALSE(below.totalInternalReflection);
  EXPECT_NEAR(angleDegrees(below.direction, -N), 90.0f, 10.0f);  // near grazing, still transmitted
  for (float degrees : {critical + 0.5f, 60.0f, 89.9f}) {
    glm::vec3 V = atAngle(degrees);
    Refraction refraction = refractionDirection(N, V, eta);
    EXPECT_TRUE(refraction.totalInternalReflection);
    EXPECT_FALSE(std::isnan(refraction.direction.x + refraction.direction.y));
    EXPECT_NEAR(glm::length(refraction.direction - reflectionDirection(N, V)), 0.0f, 1e-6f);
    EXPECT_FLOAT_EQ(schlickFresnel(glm::dot(N, V), eta, 1.0f), 1.0f);
  }
}

TEST(Optics, SchlickAtNormalAndGrazingIncidence) {
  // F0 = ((n1 - n2) / (n1 + n2))^2: 0.04 for glass in air.
  EXPECT_NEAR(schlickFresnel(std::cos(0.0f), 1.0f, 1.5f), 0.04f, 1e-6f);
  EXPECT_NEAR(schlickFresnel(std::cos(kPi / 2.0f), 1.0f, 1.5f), 1.0f, 1e-6f);
  EXPECT_NEAR(schlickFresnel(1.0f, 1.0f, 1.33f), std::pow(0.33f / 2.33f, 2.0f), 1e-6f);
  // In between: F0 + (1 - F0)(1 - cos 60)^5 and increasing with the angle.
  EXPECT_NEAR(schlickFresnel(0.5f, 1.0f, 1.5f), 0.04f + 0.96f * std::pow(0.5f, 5.0f), 1e-6f);
  float previous = 0.0f;
  for (float degrees = 0.0f; degrees <= 90.0f; degrees += 5.0f) {
    float f = schlickFresnel(std::cos(glm::radians(degrees)), 1.0f, 1.5f);
    EXPECT_GE(f, previous);
    previous = f;
  }
  // Equal media: F0 = 0, so only Schlick's (1 - cos)^5 term is left.
  EXPECT_NEAR(schlickFresnel(0.7f, 1.5f, 1.5f), std::pow(0.3f, 5.0f), 1e-6f);
}

TEST(Optics, EnvironmentContributionFormula) {
  EnvironmentSample sample{{1.0f, 0.5f, 0.0f}, {0.0f, 0.2f, 1.0f}};
  glm::vec3 c = environmentContribution(0.3f, 0.6f, 0.25f, sample);
  glm::vec3 expected =
      0.3f * sample.reflected + 0.6f * (0.25f * sample.reflected + 0.75f * sample.transmitted);
  EXPECT_NEAR(glm::length(c - expected), 0.0f, 1e-6f);
  // A constant environment returns (kr + kt) times it, whatever F is.
  EnvironmentSample constant{glm::vec3(0.4f), glm::vec3(0.4f)};
  for (float f : {0.0f, 0.3f, 1.0f})
    EXPECT_NEAR(environmentContribution(0.2f, 0.5f, f, constant).g, 0.7f * 0.4f, 1e-6f);
}

// Vulkan's cube face selection table (the spec's "Cube Map Face Selection"):
// major axis +X: sc = -rz, tc = -ry; -X: +rz, -ry; +Y: +rx, +rz; -Y: +rx, -rz;
// +Z: +rx, -ry; -Z: -rx, -ry; s = (sc / |ma| + 1) / 2, t likewise.
TEST(CubeMap, FaceDirectionsFollowVulkansTable) {
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  // Where (s, t) = (0, 0), the top-left texel of each face, points besides its axis.
  const glm::vec3 topLeft[6] = {{1, 1, 1},   {-1, 1, -1}, {-1, 1, -1},
                                {-1, -1, 1}, {-1, 1, 1},  {1, 1, -1}};
  for (uint32_t face = 0; face < 6; ++face) {
    SCOPED_TRACE(face);
    EXPECT_EQ(cubeFaceDirection(face, {0.5f, 0.5f}), axes[face]);
    EXPECT_EQ(cubeFaceDirection(face, {0.0f, 0.0f}), topLeft[face]);
    for (glm::vec2 st : {glm::vec2(0.1f, 0.2f), glm::vec2(0.9f, 0.6f), glm::vec2(0.5f, 0.99f)}) {
      CubeCoordinate back = cubeCoordinate(cubeFaceDirection(face, st) * 3.0f);
      EXPECT_EQ(back.face, face);
      EXPECT_NEAR(back.st.x, st.x, 1e-6f);
      EXPECT_NEAR(back.st.y, st.y, 1e-6f);
    }
  }
}

TEST(CubeMap, AutomaticResolution) {
  Environment sky;
  sky.kind = EnvironmentKind::Sky;
  EXPECT_EQ(cubeResolution(sky), 512u);
  sky.resolution = 64;
  EXPECT_EQ(cubeResolution(sky), 64u);
  Environment panorama;
  panorama.kind = EnvironmentKind::Panorama;
  panorama.panorama = std::make_shared<const ImageRgba>(1024, 512);
  EXPECT_EQ(cubeResolution(panorama), 256u);
  panorama.panorama = std::make_shared<const ImageRgba>(1000, 500);
  EXPECT_EQ(cubeResolution(panorama), 256u);  // 250 rounded up to a power of two
  panorama.panorama = std::make_shared<const ImageRgba>(64, 32);
  EXPECT_EQ(cubeResolution(panorama), 64u);
  Environment faces;
  faces.kind = EnvironmentKind::CubeFaces;
  faces.faces[0] = std::make_shared<const ImageRgba>(24, 24);
  faces.resolution = 64;  // faces are never resampled: their size wins
  EXPECT_EQ(cubeResolution(faces), 24u);
}

TEST(Panorama, CentreLooksAlongMinusZAndTopIsUp) {
  auto near = [](glm::vec3 a, glm::vec3 b) { return glm::length(a - b) < 1e-5f; };
  EXPECT_TRUE(near(equirectDirection({0.5f, 0.5f}), {0, 0, -1}));
  EXPECT_TRUE(near(equirectDirection({0.75f, 0.5f}), {1, 0, 0}));
  EXPECT_TRUE(near(equirectDirection({0.25f, 0.5f}), {-1, 0, 0}));
  EXPECT_TRUE(near(equirectDirection({0.0f, 0.5f}), {0, 0, 1}));
  EXPECT_TRUE(near(equirectDirection({0.3f, 0.0f}), {0, 1, 0}));
  EXPECT_TRUE(near(equirectDirection({0.3f, 1.0f}), {0, -1, 0}));
  for (glm::vec2 uv : {glm::vec2(0.1f, 0.3f), glm::vec2(0.6f, 0.8f), glm::vec2(0.95f, 0.5f)}) {
    glm::vec2 back = equirectCoordinates(2.0f * equirectDirection(uv));
    EXPECT_NEAR(back.x, uv.x, 1e-5f);
    EXPECT_NEAR(back.y, uv.y, 1e-5f);
  }
}

TEST(Sky, GradientAndSunDisc) {
  SkyDesc desc;
  desc.sunDirection = {0.0f, -1.0f,
                       -1.0f};  // sunlight travelling down and away: the sun is up behind
  desc.sunSizeDegrees = 4.0f;
  gpu::SkyParameters sky = skyParameters(desc, 2.0f, 64);
  EXPECT_EQ(sky.face.x, 64);
  auto near = [](glm::vec3 a, glm::vec3 b) { return glm::length(a - b) < 1e-5f; };
  EXPECT_TRUE(near(skyRadiance(sky, {0, 1, 0}), 2.0f * desc.zenith));
  EXPECT_TRUE(near(skyRadiance(sky, {1, 0, 0}), 2.0f * desc.horizon));
  EXPECT_TRUE(near(skyRadiance(sky, {0, -1, 0}), 2.0f * desc.ground));
  // sqrt in the elevation: a quarter of the way up is half way in colour.
  EXPECT_TRUE(near(skyRadiance(sky, glm::normalize(glm::vec3(std::sqrt(15.0f), 1, 0))),
                   2.0f * glm::mix(desc.horizon, desc.zenith, 0.5f)));
  glm::vec3 toSun = glm::normalize(glm::vec3(0, 1, 1));
  glm::vec3 base = skyRadiance(sky, glm::normalize(toSun + glm::vec3(0.2f, 0, 0)));
  EXPECT_GT(skyRadiance(sky, toSun).r, 2.0f * desc.sunIntensity.r);  // disc at full strength
  EXPECT_LT(base.r, 2.0f);                                           // 11 degrees off: no sun
  desc.sunSizeDegrees = 0.0f;
  EXPECT_LT(skyRadiance(skyParameters(desc, 1.0f, 64), toSun).r, 1.0f);
}

TEST(Environment, CpuRadianceOfEachKind) {
  Environment none;
  EXPECT_EQ(environmentRadiance(none, {0, 1, 0}), glm::vec3(0.0f));
  // A panorama whose left half is red and right half green, turned 90 degrees.
  auto image = std::make_shared<ImageRgba>(8, 4);
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 8; ++x)
      image->set(x, y, x < 4 ? glm::vec4(1, 0, 0, 1) : glm::vec4(0, 1, 0, 1));
  Environment panorama;
  panorama.kind = EnvironmentKind::Panorama;
  panorama.panorama = image;
  EXPECT_EQ(environmentRadiance(panorama, {-1, 0, 0}), glm::vec3(1, 0, 0));  // u = 0.25
  EXPECT_EQ(environmentRadiance(panorama, {1, 0, 0}), glm::vec3(0, 1, 0));   // u = 0.75
  panorama.rotationDegrees = 180.0f;
  panorama.intensity = 2.0f;
  EXPECT_NEAR(environmentRadiance(panorama, {-1, 0, 0}).g, 2.0f, 1e-5f);
}

}  // namespace
}  // namespace shadelab
