#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <initializer_list>
#include <limits>
#include <span>
#include <vector>

#include "core/scene/lighting.h"

namespace shadelab {
namespace {

constexpr float kTolerance = 1e-5f;

// The scene most tests share, chosen so every term is a round number: the eye
// at the origin, a floor point P = (0, -3, -4) with N = +Y, hence
// V = normalize(-P) = (0, 0.6, 0.8). A light straight above P has L = N = R,
// so N.L = 1 and R.V = 0.6.
const glm::vec3 kPoint{0.0f, -3.0f, -4.0f};
const glm::vec3 kUp{0.0f, 1.0f, 0.0f};

Light pointLight(glm::vec3 position, glm::vec3 intensity,
                 glm::vec3 attenuation = glm::vec3(1.0f, 0.0f, 0.0f)) {
  return {LightType::Point, position, {}, intensity, attenuation};
}

// `towardLight` need not be unit length: the equation normalises it. Attenuation (0, 0, 0)
// would make a point light's f_att 0, so any light seen proves directional lights skip f_att.
Light directionalLight(glm::vec3 towardLight, glm::vec3 intensity) {
  return {LightType::Directional, {}, -towardLight, intensity, glm::vec3(0.0f)};
}

// What illuminate() takes besides the surface: Ia and the lights, in eye space.
struct Lighting {
  glm::vec3 ambient;
  std::vector<Light> lights;
};

Lighting lightingWith(glm::vec3 ambient, std::initializer_list<Light> lights) {
  return {ambient, lights};
}

glm::vec3 light(const Lighting& lighting, glm::vec3 position, glm::vec3 normal,
                const Material& material, bool blinn = false) {
  return illuminate(lighting.ambient, lighting.lights, position, normal, material, blinn);
}

Material material(glm::vec3 ka, glm::vec3 kd, glm::vec3 ks, float shininess) {
  return Material{ka, kd, ks, shininess};
}

// ka 0.1, kd 0.5, ks 0.4, n 2 under Ia 0.2: ambient term Ia ka = 0.02.
const Material kGrey = material(glm::vec3(0.1f), glm::vec3(0.5f), glm::vec3(0.4f), 2.0f);

bool isFinite(glm::vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void expectColor(glm::vec3 actual, glm::vec3 expected, float tolerance = kTolerance) {
  EXPECT_NEAR(actual.r, expected.r, tolerance);
  EXPECT_NEAR(actual.g, expected.g, tolerance);
  EXPECT_NEAR(actual.b, expected.b, tolerance);
}

TEST(Illuminate, AmbientOnlyIsIaTimesKa) {
  const Lighting lighting = lightingWith({0.5f, 0.4f, 0.2f}, {});
  const Material m = material({0.2f, 0.5f, 1.0f}, glm::vec3(0.7f), glm::vec3(0.3f), 32.0f);
  expectColor(light(lighting, kPoint, kUp, m), {0.1f, 0.2f, 0.2f});
}

TEST(Illuminate, PointLightStraightAbove) {
  // d = 2, f_att = 1: 0.02 + 1 * (0.5 * 1 + 0.4 * 0.6^2) = 0.02 + 0.5 + 0.144.
  const Lighting lighting = lightingWith(glm::vec3(0.2f), {pointLight({0, -1, -4}, glm::vec3(1))});
  expectColor(light(lighting, kPoint, kUp, kGrey), glm::vec3(0.664f));
}

TEST(Illuminate, AttenuationIsOneOverQuadratic) {
  // d = 2 and (a, b, c) = (1, 0.5, 0.25): 1 / (1 + 0.5 * 2 + 0.25 * 4) = 1/3; kd (N.L) = 0.6.
  const Lighting lighting =
      lightingWith(glm::vec3(0.0f), {pointLight({0, -1, -4}, glm::vec3(1), {1.0f, 0.5f, 0.25f})});
  const Material m = material(glm::vec3(0), glm::vec3(0.6f), glm::vec3(0), 2.0f);
  expectColor(light(lighting, kPoint, kUp, m), glm::vec3(0.2f));
}

TEST(Illuminate, NonPositiveAttenuationDenominatorLightsNothing) {
  for (const glm::vec3 abc : {glm::vec3(0.0f), glm::vec3(-1.0f, 0.0f, 0.0f)}) {
    const Lighting lighting =
        lightingWith(glm::vec3(0.2f), {pointLight({0, -1, -4}, glm::vec3(1), abc)});
    expectColor(light(lighting, kPoint, kUp, kGrey), glm::vec3(0.02f));
  }
}

TEST(Illuminate, DirectionalLightIgnoresDistanceAndAttenuation) {
  // L = (0, 1, -1)/sqrt2: N.L = 0.70711; R = (0, 1, 1)/sqrt2, R.V = 1.4/sqrt2, (R.V)^2 = 0.98.
  // 2 * (0.5 * 0.70711 + 0.4 * 0.98) = 1.491107.
  const Lighting lighting =
      lightingWith(glm::vec3(0.0f), {directionalLight({0, 1, -1}, glm::vec3(2))});
  expectColor(light(lighting, kPoint, kUp, kGrey), glm::vec3(1.491107f));
  // Without specular, a floor point 100 units away is lit exactly the same: 2 * 0.5 * 0.70711.
  const Material matte = material(glm::vec3(0), glm::vec3(0.5f), glm::vec3(0), 2.0f);
  expectColor(light(lighting, kPoint + glm::vec3(100.0f, 0.0f, -50.0f), kUp, matte),
              glm::vec3(0.707107f));
}

TEST(Illuminate, TwoLightsAdd) {
  // 0.02 ambient + 0.644 (point) + 1.491107 (directional).
  const Light point = pointLight({0, -1, -4}, glm::vec3(1));
  const Light sun = directionalLight({0, 1, -1}, glm::vec3(2));
  expectColor(light(lightingWith(glm::vec3(0.2f), {point, sun}), kPoint, kUp, kGrey),
              glm::vec3(2.155107f));
  expectColor(light(lightingWith(glm::vec3(0.2f), {sun, point}), kPoint, kUp, kGrey),
              glm::vec3(2.155107f));
}

TEST(Illuminate, OnlyTheLightsGivenAreUsed) {
  const Lighting lighting = lightingWith(
      glm::vec3(0.2f),
      {pointLight({0, -1, -4}, glm::vec3(1)), directionalLight({0, 1, -1}, glm::vec3(2))});
  const std::span<const Light> lights(lighting.lights);
  expectColor(illuminate(lighting.ambient, lights.first(1), kPoint, kUp, kGrey, false),
              glm::vec3(0.664f));
  expectColor(illuminate(lighting.ambient, lights.first(0), kPoint, kUp, kGrey, false),
              glm::vec3(0.02f));
}

TEST(Illuminate, EachChannelUsesItsOwnCoefficients) {
  // Per channel: Ia ka + Ip (kd * 1 + ks * 0.36).
  //   r: 1 * 0.1 + 1 * (0.5 + 0)           = 0.6
  //   g: 0.5 * 0.2 + 2 * (0.25 + 0.5 * 0.36) = 0.96
  //   b: 0.25 * 0.3 + 4 * (0 + 1 * 0.36)   = 1.515
  const Lighting lighting =
      lightingWith({1.0f, 0.5f, 0.25f}, {pointLight({0, -1, -4}, {1.0f, 2.0f, 4.0f})});
  const Material m = material({0.1f, 0.2f, 0.3f}, {0.5f, 0.25f, 0.0f}, {0.0f, 0.5f, 1.0f}, 2.0f);
  expectColor(light(lighting, kPoint, kUp, m), {0.6f, 0.96f, 1.515f});
}

TEST(Illuminate, LightBehindSurfaceGivesAmbientOnly) {
  const Lighting below = lightingWith(glm::vec3(0.2f), {pointLight({0, -5, -4}, glm::vec3(1))});
  expectColor(light(below, kPoint, kUp, kGrey), glm::vec3(0.02f));
  // L = (0, -0.6, -0.8): N.L = -0.6 yet R.V = 0.28 > 0, so a specular term
  // would leak without the N.L test. L = -V also makes Blinn's H = 0/0.
  const glm::vec3 towardLight{0.0f, -0.6f, -0.8f};
  EXPECT_GT(glm::dot(reflectAbout(towardLight, kUp), glm::normalize(-kPoint)), 0.25f);
  const Lighting behind =
      lightingWith(glm::vec3(0.2f), {directionalLight(towardLight, glm::vec3(1))});
  expectColor(light(behind, kPoint, kUp, kGrey, false), glm::vec3(0.02f));
  expectColor(light(behind, kPoint, kUp, kGrey, true), glm::vec3(0.02f));
  // Grazing (N.L = 0) is "behind" too.
  const Lighting grazing =
      lightingWith(glm::vec3(0.2f), {directionalLight({1, 0, 0}, glm::vec3(1))});
  expectColor(light(grazing, kPoint, kUp, kGrey), glm::vec3(0.02f));
}

TEST(Illuminate, BlinnPhongUsesHalfVector) {
  // H = normalize(L + V) = normalize(0, 1.6, 0.8) = (0, 2, 1)/sqrt5, (N.H)^2 = 0.8:
  // 0.02 + 0.5 + 0.4 * 0.8 = 0.84, where Phong gives 0.664.
  const Lighting lighting = lightingWith(glm::vec3(0.2f), {pointLight({0, -1, -4}, glm::vec3(1))});
  expectColor(light(lighting, kPoint, kUp, kGrey, true), glm::vec3(0.84f));
  expectColor(light(lighting, kPoint, kUp, kGrey, false), glm::vec3(0.664f));
}

TEST(Illuminate, ShininessExtremesStayFinite) {
  // R.V = 0.6: n = 0 means specular factor 1; 0.6^128 and 0.6^1000 vanish.
  const Lighting lighting = lightingWith(glm::vec3(0.2f), {pointLight({0, -1, -4}, glm::vec3(1))});
  const std::pair<float, float> cases[] = {
      {0.0f, 0.92f}, {1.0f, 0.76f}, {128.0f, 0.52f}, {1000.0f, 0.52f}};
  for (const auto& [n, expected] : cases) {
    for (const bool blinn : {false, true}) {
      const Material m = material(glm::vec3(0.1f), glm::vec3(0.5f), glm::vec3(0.4f), n);
      const glm::vec3 color = light(lighting, kPoint, kUp, m, blinn);
      EXPECT_TRUE(isFinite(color)) << "n " << n << " blinn " << blinn;
      if (!blinn) expectColor(color, glm::vec3(expected));
    }
  }
}

TEST(Illuminate, ShininessZeroIsFullSpecularEvenWhereRDotVIsNegative) {
  // Directional L = (0, 1, 1)/sqrt2: R = (0, 1, -1)/sqrt2, R.V = -0.2/sqrt2 < 0.
  // n = 2 clamps the cosine to 0; n = 0 uses the factor 1: 0.5 * 0.70711 + 0.4.
  const Lighting lighting =
      lightingWith(glm::vec3(0.0f), {directionalLight({0, 1, 1}, glm::vec3(1))});
  expectColor(light(lighting, kPoint, kUp, kGrey), glm::vec3(0.353553f));
  const Material m = material(glm::vec3(0.1f), glm::vec3(0.5f), glm::vec3(0.4f), 0.0f);
  expectColor(light(lighting, kPoint, kUp, m), glm::vec3(0.753553f));
}

TEST(Illuminate, BadNormalsGiveAmbientOnly) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const Lighting lighting = lightingWith(
      glm::vec3(0.2f),
      {pointLight({0, -1, -4}, glm::vec3(1)), directionalLight({0, 1, -1}, glm::vec3(2))});
  for (const glm::vec3 normal :
       {glm::vec3(0.0f), glm::vec3(nan, 1.0f, 0.0f), glm::vec3(nan), glm::vec3(0.0f, inf, 0.0f)}) {
    for (const bool blinn : {false, true}) {
      const glm::vec3 color = light(lighting, kPoint, normal, kGrey, blinn);
      EXPECT_TRUE(isFinite(color));
      expectColor(color, glm::vec3(0.02f));
    }
  }
}

TEST(Illuminate, NormalLengthDoesNotMatter) {
  const Lighting lighting = lightingWith(glm::vec3(0.2f), {pointLight({0, -1, -4}, glm::vec3(1))});
  expectColor(light(lighting, kPoint, glm::vec3(0.0f, 5.0f, 0.0f), kGrey), glm::vec3(0.664f));
  expectColor(light(lighting, kPoint, glm::vec3(0.0f, 1e-10f, 0.0f), kGrey), glm::vec3(0.664f));
}

TEST(Illuminate, LightAtTheSurfacePointLightsNothing) {
  for (const glm::vec3 abc : {glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f)}) {
    const Lighting lighting =
        lightingWith(glm::vec3(0.2f), {pointLight(kPoint, glm::vec3(1), abc)});
    for (const bool blinn : {false, true}) {
      const glm::vec3 color = light(lighting, kPoint, kUp, kGrey, blinn);
      EXPECT_TRUE(isFinite(color));
      expectColor(color, glm::vec3(0.02f));
    }
  }
}

// A view that turns a quarter about y (x -> +z, z -> -x) and moves by (1, 2, 3).
TEST(LightInView, MovesPointsAndTurnsDirections) {
  const glm::mat4 view{{0, 0, 1, 0}, {0, 1, 0, 0}, {-1, 0, 0, 0}, {1, 2, 3, 1}};
  const Light point = lightInView(pointLight({1, 0, 0}, glm::vec3(0.5f), {1, 2, 3}), view);
  EXPECT_EQ(point.type, LightType::Point);
  expectColor(point.position, {1, 2, 4});
  expectColor(point.intensity, glm::vec3(0.5f));
  expectColor(point.attenuation, {1, 2, 3});
  // Shining along +x, from 4 units long to unit length; translation plays no part.
  const Light sun = lightInView(directionalLight({-4, 0, 0}, glm::vec3(2)), view);
  EXPECT_EQ(sun.type, LightType::Directional);
  expectColor(sun.direction, {0, 0, 1});
  const Light none = lightInView(directionalLight(glm::vec3(0), glm::vec3(2)), view);
  expectColor(none.direction, glm::vec3(0));
  EXPECT_TRUE(isFinite(none.direction));
}

// The equation sees only relative vectors and angles, so a rigid change of
// space changes nothing: lit in eye space with lights from lightInView, a
// point gets the colour it gets in world space moved so the eye is the origin.
TEST(LightInView, EyeSpaceLightingMatchesWorldSpace) {
  const glm::vec3 eye{0.0f, 3.0f, 4.0f};
  const glm::mat4 view = glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  const Light world[] = {pointLight({0, 2, 0}, glm::vec3(1)),
                         directionalLight({0, 1, -1}, glm::vec3(2))};
  const Light eyeSpace[] = {lightInView(world[0], view), lightInView(world[1], view)};
  // In world space, moved so the eye is the origin (V = -position).
  Light fromEye[] = {world[0], world[1]};
  fromEye[0].position -= eye;
  const glm::vec3 position{0.0f, 0.0f, 0.0f};
  const glm::vec3 expected =
      illuminate(glm::vec3(0.2f), fromEye, position - eye, kUp, kGrey, false);
  const glm::vec3 actual =
      illuminate(glm::vec3(0.2f), eyeSpace, glm::vec3(view * glm::vec4(position, 1.0f)),
                 glm::mat3(view) * kUp, kGrey, false);
  expectColor(actual, expected);
  EXPECT_GT(expected.r, 0.5f);
}

TEST(ReflectAbout, KeepsTheAngleAndLength) {
  const glm::vec3 normals[] = {kUp, glm::normalize(glm::vec3(1, 2, 3)),
                               glm::normalize(glm::vec3(-1, 0, 1))};
  const glm::vec3 lights[] = {glm::normalize(glm::vec3(0, 1, -1)),
                              glm::normalize(glm::vec3(3, 1, 2)),
                              glm::normalize(glm::vec3(-2, -1, 0.5f))};
  for (const glm::vec3 n : normals) {
    for (const glm::vec3 l : lights) {
      const glm::vec3 r = reflectAbout(l, n);
      EXPECT_NEAR(glm::dot(r, n), glm::dot(l, n), kTolerance);
      EXPECT_NEAR(glm::length(r), 1.0f, kTolerance);
      // L and R are mirror images: their sum lies along N.
      EXPECT_NEAR(glm::length(glm::cross(r + l, n)), 0.0f, kTolerance);
    }
  }
  expectColor(reflectAbout(glm::normalize(glm::vec3(0, 1, -1)), kUp),
              glm::normalize(glm::vec3(0, 1, 1)));
}

}  // namespace
}  // namespace shadelab
