#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <limits>

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

gpu::GpuLight pointLight(glm::vec3 position, glm::vec3 intensity,
                         glm::vec3 attenuation = glm::vec3(1.0f, 0.0f, 0.0f)) {
  return {glm::vec4(position, 1.0f), glm::vec4(intensity, 0.0f), glm::vec4(attenuation, 0.0f),
          glm::ivec4(LIGHT_POINT, 0, 0, 0)};
}

// `towardLight` need not be unit length: the shader normalises it. Attenuation (0, 0, 0)
// would make a point light's f_att 0, so any light seen proves directional lights skip f_att.
gpu::GpuLight directionalLight(glm::vec3 towardLight, glm::vec3 intensity) {
  return {glm::vec4(towardLight, 0.0f), glm::vec4(intensity, 0.0f), glm::vec4(0.0f),
          glm::ivec4(LIGHT_DIRECTIONAL, 0, 0, 0)};
}

// FrameData built by hand (makeFrameData needs the Vulkan side of the build).
gpu::FrameData frameWith(glm::vec3 ambient, std::initializer_list<gpu::GpuLight> lights) {
  gpu::FrameData frame{};
  frame.projection = glm::mat4(1.0f);
  frame.ambient = glm::vec4(ambient, 0.0f);
  int count = 0;
  for (const gpu::GpuLight& light : lights) {
    frame.lights[count++] = light;
  }
  frame.lightCount = glm::ivec4(count, 0, 0, 0);
  return frame;
}

glm::vec3 light(const gpu::FrameData& frame, glm::vec3 position, glm::vec3 normal,
                const Material& material, bool blinn = false) {
  return illuminate(frame, uint32_t(frame.lightCount.x), position, normal, material, blinn);
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
  const gpu::FrameData frame = frameWith({0.5f, 0.4f, 0.2f}, {});
  const Material m = material({0.2f, 0.5f, 1.0f}, glm::vec3(0.7f), glm::vec3(0.3f), 32.0f);
  expectColor(light(frame, kPoint, kUp, m), {0.1f, 0.2f, 0.2f});
}

TEST(Illuminate, PointLightStraightAbove) {
  // d = 2, f_att = 1: 0.02 + 1 * (0.5 * 1 + 0.4 * 0.6^2) = 0.02 + 0.5 + 0.144.
  const gpu::FrameData frame = frameWith(glm::vec3(0.2f), {pointLight({0, -1, -4}, glm::vec3(1))});
  expectColor(light(frame, kPoint, kUp, kGrey), glm::vec3(0.664f));
}

TEST(Illuminate, AttenuationIsOneOverQuadratic) {
  // d = 2 and (a, b, c) = (1, 0.5, 0.25): 1 / (1 + 0.5 * 2 + 0.25 * 4) = 1/3; kd (N.L) = 0.6.
  const gpu::FrameData frame =
      frameWith(glm::vec3(0.0f), {pointLight({0, -1, -4}, glm::vec3(1), {1.0f, 0.5f, 0.25f})});
  const Material m = material(glm::vec3(0), glm::vec3(0.6f), glm::vec3(0), 2.0f);
  expectColor(light(frame, kPoint, kUp, m), glm::vec3(0.2f));
}

TEST(Illuminate, NonPositiveAttenuationDenominatorLightsNothing) {
  for (const glm::vec3 abc : {glm::vec3(0.0f), glm::vec3(-1.0f, 0.0f, 0.0f)}) {
    const gpu::FrameData frame =
        frameWith(glm::vec3(0.2f), {pointLight({0, -1, -4}, glm::vec3(1), abc)});
    expectColor(light(frame, kPoint, kUp, kGrey), glm::vec3(0.02f));
  }
}

TEST(Illuminate, DirectionalLightIgnoresDistanceAndAttenuation) {
  // L = (0, 1, -1)/sqrt2: N.L = 0.70711; R = (0, 1, 1)/sqrt2, R.V = 1.4/sqrt2, (R.V)^2 = 0.98.
  // 2 * (0.5 * 0.70711 + 0.4 * 0.98) = 1.491107.
  const gpu::FrameData frame =
      frameWith(glm::vec3(0.0f), {directionalLight({0, 1, -1}, glm::vec3(2))});
  expectColor(light(frame, kPoint, kUp, kGrey), glm::vec3(1.491107f));
  // Without specular, a floor point 100 units away is lit exactly the same: 2 * 0.5 * 0.70711.
  const Material matte = material(glm::vec3(0), glm::vec3(0.5f), glm::vec3(0), 2.0f);
  expectColor(light(frame, kPoint + glm::vec3(100.0f, 0.0f, -50.0f), kUp, matte),
              glm::vec3(0.707107f));
}

TEST(Illuminate, TwoLightsAdd) {
  // 0.02 ambient + 0.644 (point) + 1.491107 (directional).
  const gpu::GpuLight point = pointLight({0, -1, -4}, glm::vec3(1));
  const gpu::GpuLight sun = directionalLight({0, 1, -1}, glm::vec3(2));
  expectColor(light(frameWith(glm::vec3(0.2f), {point, sun}), kPoint, kUp, kGrey),
              glm::vec3(2.155107f));
  expectColor(light(frameWith(glm::vec3(0.2f), {sun, point}), kPoint, kUp, kGrey),
              glm::vec3(2.155107f));
}

TEST(Illuminate, OnlyTheFirstLightCountLightsAreUsed) {
  const gpu::FrameData frame = frameWith(
      glm::vec3(0.2f),
      {pointLight({0, -1, -4}, glm::vec3(1)), directionalLight({0, 1, -1}, glm::vec3(2))});
  expectColor(illuminate(frame, 1, kPoint, kUp, kGrey, false), glm::vec3(0.664f));
  expectColor(illuminate(frame, 0, kPoint, kUp, kGrey, false), glm::vec3(0.02f));
}

TEST(Illuminate, EachChannelUsesItsOwnCoefficients) {
  // Per channel: Ia ka + Ip (kd * 1 + ks * 0.36).
  //   r: 1 * 0.1 + 1 * (0.5 + 0)           = 0.6
  //   g: 0.5 * 0.2 + 2 * (0.25 + 0.5 * 0.36) = 0.96
  //   b: 0.25 * 0.3 + 4 * (0 + 1 * 0.36)   = 1.515
  const gpu::FrameData frame =
      frameWith({1.0f, 0.5f, 0.25f}, {pointLight({0, -1, -4}, {1.0f, 2.0f, 4.0f})});
  const Material m = material({0.1f, 0.2f, 0.3f}, {0.5f, 0.25f, 0.0f}, {0.0f, 0.5f, 1.0f}, 2.0f);
  expectColor(light(frame, kPoint, kUp, m), {0.6f, 0.96f, 1.515f});
}

TEST(Illuminate, LightBehindSurfaceGivesAmbientOnly) {
  const gpu::FrameData below = frameWith(glm::vec3(0.2f), {pointLight({0, -5, -4}, glm::vec3(1))});
  expectColor(light(below, kPoint, kUp, kGrey), glm::vec3(0.02f));
  // L = (0, -0.6, -0.8): N.L = -0.6 yet R.V = 0.28 > 0, so a specular term
  // would leak without the N.L test. L = -V also makes Blinn's H = 0/0.
  const glm::vec3 towardLight{0.0f, -0.6f, -0.8f};
  EXPECT_GT(glm::dot(reflectAbout(towardLight, kUp), glm::normalize(-kPoint)), 0.25f);
  const gpu::FrameData behind =
      frameWith(glm::vec3(0.2f), {directionalLight(towardLight, glm::vec3(1))});
  expectColor(light(behind, kPoint, kUp, kGrey, false), glm::vec3(0.02f));
  expectColor(light(behind, kPoint, kUp, kGrey, true), glm::vec3(0.02f));
  // Grazing (N.L = 0) is "behind" too.
  const gpu::FrameData grazing =
      frameWith(glm::vec3(0.2f), {directionalLight({1, 0, 0}, glm::vec3(1))});
  expectColor(light(grazing, kPoint, kUp, kGrey), glm::vec3(0.02f));
}

TEST(Illuminate, BlinnPhongUsesHalfVector) {
  // H = normalize(L + V) = normalize(0, 1.6, 0.8) = (0, 2, 1)/sqrt5, (N.H)^2 = 0.8:
  // 0.02 + 0.5 + 0.4 * 0.8 = 0.84, where Phong gives 0.664.
  const gpu::FrameData frame = frameWith(glm::vec3(0.2f), {pointLight({0, -1, -4}, glm::vec3(1))});
  expectColor(light(frame, kPoint, kUp, kGrey, true), glm::vec3(0.84f));
  expectColor(light(frame, kPoint, kUp, kGrey, false), glm::vec3(0.664f));
}

TEST(Illuminate, ShininessExtremesStayFinite) {
  // R.V = 0.6: n = 0 means specular factor 1; 0.6^128 and 0.6^1000 vanish.
  const gpu::FrameData frame = frameWith(glm::vec3(0.2f), {pointLight({0, -1, -4}, glm::vec3(1))});
  const std::pair<float, float> cases[] = {
      {0.0f, 0.92f}, {1.0f, 0.76f}, {128.0f, 0.52f}, {1000.0f, 0.52f}};
  for (const auto& [n, expected] : cases) {
    for (const bool blinn : {false, true}) {
      const Material m = material(glm::vec3(0.1f), glm::vec3(0.5f), glm::vec3(0.4f), n);
      const glm::vec3 color = light(frame, kPoint, kUp, m, blinn);
      EXPECT_TRUE(isFinite(color)) << "n " << n << " blinn " << blinn;
      if (!blinn) expectColor(color, glm::vec3(expected));
    }
  }
}

TEST(Illuminate, ShininessZeroIsFullSpecularEvenWhereRDotVIsNegative) {
  // Directional L = (0, 1, 1)/sqrt2: R = (0, 1, -1)/sqrt2, R.V = -0.2/sqrt2 < 0.
  // n = 2 clamps the cosine to 0; n = 0 uses the factor 1: 0.5 * 0.70711 + 0.4.
  const gpu::FrameData frame =
      frameWith(glm::vec3(0.0f), {directionalLight({0, 1, 1}, glm::vec3(1))});
  expectColor(light(frame, kPoint, kUp, kGrey), glm::vec3(0.353553f));
  const Material m = material(glm::vec3(0.1f), glm::vec3(0.5f), glm::vec3(0.4f), 0.0f);
  expectColor(light(frame, kPoint, kUp, m), glm::vec3(0.753553f));
}

TEST(Illuminate, BadNormalsGiveAmbientOnly) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const gpu::FrameData frame = frameWith(
      glm::vec3(0.2f),
      {pointLight({0, -1, -4}, glm::vec3(1)), directionalLight({0, 1, -1}, glm::vec3(2))});
  for (const glm::vec3 normal :
       {glm::vec3(0.0f), glm::vec3(nan, 1.0f, 0.0f), glm::vec3(nan), glm::vec3(0.0f, inf, 0.0f)}) {
    for (const bool blinn : {false, true}) {
      const glm::vec3 color = light(frame, kPoint, normal, kGrey, blinn);
      EXPECT_TRUE(isFinite(color));
      expectColor(color, glm::vec3(0.02f));
    }
  }
}

TEST(Illuminate, NormalLengthDoesNotMatter) {
  const gpu::FrameData frame = frameWith(glm::vec3(0.2f), {pointLight({0, -1, -4}, glm::vec3(1))});
  expectColor(light(frame, kPoint, glm::vec3(0.0f, 5.0f, 0.0f), kGrey), glm::vec3(0.664f));
  expectColor(light(frame, kPoint, glm::vec3(0.0f, 1e-10f, 0.0f), kGrey), glm::vec3(0.664f));
}

TEST(Illuminate, LightAtTheSurfacePointLightsNothing) {
  for (const glm::vec3 abc : {glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f)}) {
    const gpu::FrameData frame =
        frameWith(glm::vec3(0.2f), {pointLight(kPoint, glm::vec3(1), abc)});
    for (const bool blinn : {false, true}) {
      const glm::vec3 color = light(frame, kPoint, kUp, kGrey, blinn);
      EXPECT_TRUE(isFinite(color));
      expectColor(color, glm::vec3(0.02f));
    }
  }
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
