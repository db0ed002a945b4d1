// Environment mapping in the forward pass, measured: a constant environment
// is reflected exactly times kr (and transmitted times kt) in every lit
// model; a mirror reflects the world-space direction R = 2(N.V)N - V; total
// internal reflection falls back to R with no NaN; --env off is the
// background-only render; goldens with must-fail twins.
#include <cmath>

#include "core/scene/scene_loader.h"
#include "core/scene/texture.h"
#include "core/scene/transform.h"
#include "core/trace/optics.h"
#include "core/vulkan/depth.h"
#include "environment_test_support.h"
#include "gpu_test_support.h"

namespace shadelab::test {
namespace {

Material environmentOnly(float reflectivity, float transparency) {
  Material material;
  material.ka = material.kd = material.ks = glm::vec3(0.0f);
  material.reflectivity = reflectivity;
  material.transparency = transparency;
  return material;
}

using EnvironmentShading = GpuTest;

// With ka = kd = ks = 0 the colour is the environment term alone: kr c for a
// mirror and kt [F c + (1 - F) c] = kt c for glass, whatever F is; a
// textured mirror (its texel scales kd = 0) takes the textured variants.
TEST_F(EnvironmentShading, ConstantEnvironmentTimesReflectivityInEveryLitModel) {
  glm::vec3 colour{0.8f, 0.5f, 0.2f};
  Scene scene;
  scene.name = "constant";
  scene.camera.eye = {0.0f, 0.0f, 6.0f};
  scene.environment = constantSky(colour);
  scene.lights.push_back({});
  uint32_t sphere = scene.addShape({ShapeKind::UvSphere, 1.0f, {}, 0.7f, 1.0f, 0.25f, 24});
  scene.objects.push_back({"mirror", sphere, translation({-1.6f, 0, 0}), environmentOnly(0.6f, 0)});
  scene.objects.push_back({"glass", sphere, translation({1.6f, 0, 0}), environmentOnly(0, 0.35f)});
  scene.textures.push_back(solidTexture({200, 30, 30, 255}, TextureRole::Color, "red"));
  Material textured = environmentOnly(0.8f, 0);
  textured.diffuseMap.texture = 0;
  scene.objects.push_back({"textured", sphere, glm::mat4(1.0f), textured});
  float worstOverall = 0.0f;
  for (ShadingModel model :
       {ShadingModel::Flat, ShadingModel::Gouraud, ShadingModel::Phong, ShadingModel::BlinnPhong}) {
    for (uint32_t samples : {1u, 4u}) {
      RenderSettings settings{160, 90, model};
      settings.msaaSamples = samples;
      ImageRgba image = renderer().renderToImage(scene, settings).image;
      // Sphere centres project to x = 80 -+ 29 (fovy 45 at distance 6), radius
      // 12.7 pixels; sample their insides.
      float worst = 0.0f;
      for (auto [centreX, expected] : {std::pair{51, 0.6f * colour}, std::pair{109, 0.35f * colour},
                                       std::pair{80, 0.8f * colour}})
        for (int dy = -8; dy <= 8; dy += 2)
          for (int dx = -8; dx <= 8; dx += 2) {
            glm::vec3 got(image.at(uint32_t(centreX + dx), uint32_t(45 + dy)));
            worst = std::max(worst, glm::length(got - expected));
          }
      EXPECT_LE(worst, 1.0f / 255.0f)
          << shadingModelName(model) << ", " << samples << "x: off by " << worst;
      worstOverall = std::max(worstOverall, worst);
      // The skybox around them is the constant itself.
      EXPECT_NEAR(image.at(2, 2).r, colour.r, 1.0f / 255.0f);
    }
  }
  std::printf("constant environment: worst |colour - k c| %.5f (bound 1/255 = %.5f)\n",
              worstOverall, 1.0f / 255.0f);
}

// A mirror floor under a direction-encoding panorama, seen by a camera
// turned off every axis: each pixel shows the colour of the world-space
// reflection of its view ray about N = +y.
class MirrorFloor : public GpuTest {
 protected:
  void SetUp() override {
    GpuTest::SetUp();
    scene.name = "mirror-floor";
    scene.camera.eye = {1.3f, 2.0f, 3.1f};
    scene.camera.at = {-0.4f, 0.0f, -0.7f};
    scene.camera.fovyDegrees = 50.0f;
    scene.environment = panoramaOf(512, 256, 128, encodeDirection);
    scene.lights.push_back({});
    uint32_t floor = scene.addShape({ShapeKind::Plane, 60.0f, {}, 1.0f, 1.0f, 0.25f, 1});
    scene.objects.push_back({"floor", floor, glm::mat4(1.0f), environmentOnly(1.0f, 0.0f)});
  }
  // Largest |colour - expected(ray)| over the floor's pixels, and how many
  // there were; `skip(ray)` leaves out pixels the comparison cannot judge.
  std::pair<float, int> worstOver(
      const ImageRgba& image, const std::function<glm::vec3(glm::vec3)>& expected,
      const std::function<bool(glm::vec3)>& skip = [](glm::vec3) { return false; }) {
    float worst = 0.0f;
    int count = 0;
    for (uint32_t y = 0; y < kHeight; y += 3)
      for (uint32_t x = 0; x < kWidth; x += 3) {
        glm::vec3 ray = pixelRay(scene.camera, kWidth, kHeight, x, y);
        if (ray.y > -0.15f || skip(ray)) continue;  // the floor's far edge and the sky
        float error = glm::length(glm::vec3(image.at(x, y)) - expected(ray));
        worst = std::max(worst, error);
        ++count;
      }
    return {worst, count};
  }
  static constexpr uint32_t kWidth = 96, kHeight = 64;
  Scene scene;
  const glm::vec3 up{0.0f, 1.0f, 0.0f};
};

TEST_F(MirrorFloor, ReflectsTheWorldSpaceMirrorDirection) {
  ImageRgba image = renderer().renderToImage(scene, {kWidth, kHeight, ShadingModel::Phong}).image;
  auto [worst, count] = worstOver(
      image, [&](glm::vec3 ray) { return encodeDirection(reflectionDirection(up, -ray)); });
  EXPECT_GT(count, 200);
  EXPECT_LT(worst, 0.01f) << "colour off by " << worst << " from encode(R)";
  std::printf("mirror floor: worst |colour - encode(R)| %.4f over %d pixels\n", worst, count);
  // Must-fail twin: R left in eye space (no inverse view rotation) is far off.
  glm::mat3 view(scene.camera.viewMatrix());
  auto [eyeSpaceWorst, unused] = worstOver(image, [&](glm::vec3 ray) {
    return encodeDirection(reflectionDirection(view * up, view * -ray));
  });
  EXPECT_GT(eyeSpaceWorst, 0.2f);
}

// ior 0.8 < 1: entering it, eta = 1 / 0.8 > 1, so beyond the critical angle
// asin(0.8) = 53.1 degrees no light is transmitted. There the colour must be
// env(R) (F = 1, T = R); below it F env(R) + (1 - F) env(T) by Snell's law.
// Within 0.75 degrees of the critical angle F and T change too fast with the
// angle (cos_t = sqrt(...) -> 0) for a pixel-centre ray to predict a fragment:
// those pixels are only checked for NaN.
TEST_F(MirrorFloor, TotalInternalReflectionFallsBackToReflection) {
  scene.objects[0].material = environmentOnly(0.0f, 1.0f);
  scene.objects[0].material.ior = 0.8f;
  ImageRgba image = renderer().renderToImage(scene, {kWidth, kHeight, ShadingModel::Phong}).image;
  for (float value : image.pixels) ASSERT_TRUE(std::isfinite(value));
  int totallyReflected = 0, transmitted = 0;
  auto [worst, count] = worstOver(
      image,
      [&](glm::vec3 ray) {
        glm::vec3 V = -ray;
        Refraction refraction = refractionDirection(up, V, 1.0f / 0.8f);
        float F = schlickFresnel(glm::dot(up, V), 1.0f, 0.8f);
        ++(refraction.totalInternalReflection ? totallyReflected : transmitted);
        glm::vec3 reflected = encodeDirection(reflectionDirection(up, V));
        return F * reflected + (1.0f - F) * encodeDirection(refraction.direction);
      },
      [](glm::vec3 ray) {
        float critical = glm::degrees(std::asin(0.8f));
        return std::abs(glm::degrees(std::acos(-ray.y)) - critical) < 0.75f;
      });
  EXPECT_GT(totallyReflected, 100);
  EXPECT_GT(transmitted, 100);
  EXPECT_LT(worst, 0.015f) << "off by " << worst;
  std::printf("ior 0.8 floor: %d pixels totally reflected, %d transmitted, worst error %.4f\n",
              totallyReflected, transmitted, worst);
}

TEST_F(EnvironmentShading, EnvOffIsTheBackgroundOnlyRender) {
  Scene scene = builtinScene("env");
  RenderSettings off{160, 90, ShadingModel::Phong};
  off.environment = false;
  Scene without = scene;
  without.environment = Environment{};
  ImageU8 a = render(scene, off);
  EXPECT_EQ(compareImages(a, render(without, {160, 90, ShadingModel::Phong})).maxDifference, 0);
  EXPECT_GT(compareImages(a, render(scene, {160, 90, ShadingModel::Phong})).rmse, 5.0);
}

// The skybox fills exactly what the depth buffer still holds at its cleared
// far value, in every depth mode (reversed-Z clears to 0 and swaps the
// planes): the same image as D32F within the golden tolerance, and not the
// background-only render.
TEST_F(EnvironmentShading, EveryDepthModeDrawsTheSameSkybox) {
  Scene scene = builtinScene("env");
  RenderSettings settings{160, 90, ShadingModel::Phong};
  ImageU8 reference = render(scene, settings);
  RenderSettings off = settings;
  off.environment = false;
  ImageU8 background = render(scene, off);
  for (DepthMode mode : valuesOf(kDepthModeNames)) {
    settings.depth = mode;
    ImageU8 image = render(scene, settings);
    EXPECT_TRUE(matchesImage(reference, image)) << depthModeName(mode);
    EXPECT_FALSE(matchesImage(background, image)) << depthModeName(mode);
  }
}

// The renderer keeps the cube while the environment stays the same; any
// change must rebuild it, never show the previous one.
TEST_F(EnvironmentShading, ChangedEnvironmentIsRebuiltUnchangedIsReused) {
  Scene scene = builtinScene("env");
  Scene brighter = scene;
  brighter.environment.intensity = 1.5f;
  RenderSettings settings{96, 54, ShadingModel::Phong};
  ImageU8 first = render(scene, settings);
  ImageU8 changed = render(brighter, settings);
  ImageU8 again = render(scene, settings);
  EXPECT_EQ(compareImages(first, again).maxDifference, 0);
  EXPECT_GT(compareImages(first, changed).rmse, 5.0);
}

RenderSettings golden(ShadingModel model, uint32_t samples = 1) {
  RenderSettings settings{320, 180, model};
  settings.msaaSamples = samples;
  return settings;
}

class EnvironmentGolden : public GpuTest, public ::testing::WithParamInterface<ShadingModel> {};

TEST_P(EnvironmentGolden, EnvSceneMatchesGolden) {
  ShadingModel model = GetParam();
  EXPECT_TRUE(matchesGolden("env-" + std::string(shadingModelName(model)),
                            render(builtinScene("env"), golden(model))));
}

INSTANTIATE_TEST_SUITE_P(LitModels, EnvironmentGolden,
                         ::testing::Values(ShadingModel::Flat, ShadingModel::Gouraud,
                                           ShadingModel::Phong),
                         [](const auto& info) {
                           std::string name(shadingModelName(info.param));
                           return name;
                         });

TEST_F(EnvironmentShading, EnvGoldenRejectsSunMovedFiveDegrees) {
  Scene scene = builtinScene("env");
  glm::vec4 moved =
      rotationY(glm::radians(5.0f)) * glm::vec4(scene.environment.sky.sunDirection, 0);
  scene.environment.sky.sunDirection = glm::vec3(moved);
  scene.lights[0].direction = glm::vec3(moved);
  EXPECT_FALSE(matchesImage(loadGolden("env-phong"), render(scene, golden(ShadingModel::Phong))));
}

TEST_F(EnvironmentShading, EnvGoldenRejectsMirrorWithoutEnvironmentTerm) {
  Scene scene = builtinScene("env");
  for (Object& object : scene.objects) object.material.reflectivity = 0.0f;
  EXPECT_FALSE(matchesImage(loadGolden("env-phong"), render(scene, golden(ShadingModel::Phong))));
}

// The example scene lit by the generated studio panorama (assets/environments/studio.hdr), 4x MSAA.
Scene studioScene() {
  return loadScene(std::string(SHADELAB_ASSET_DIR) + "/scenes/studio.json");
}

TEST_F(EnvironmentShading, StudioPanoramaMatchesGolden) {
  EXPECT_TRUE(
      matchesGolden("studio-phong-msaa4", render(studioScene(), golden(ShadingModel::Phong, 4))));
}

TEST_F(EnvironmentShading, StudioGoldenRejectsPanoramaTurnedTenDegrees) {
  Scene scene = studioScene();
  scene.environment.rotationDegrees += 10.0f;
  EXPECT_FALSE(matchesImage(loadGolden("studio-phong-msaa4"),
                            render(scene, golden(ShadingModel::Phong, 4))));
}

}  // namespace
}  // namespace shadelab::test
