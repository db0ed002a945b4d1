// Image tests: built-in scenes rendered headless on the device and compared
// with committed goldens; must-fail twins proving the comparison catches a
// wrong image; determinism; projections, culling and depth testing measured
// on the readback.
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "core/base/errors.h"
#include "core/scene/scene.h"
#include "core/scene/transform.h"
#include "core/vulkan/gpu_scene.h"
#include "gpu_test_support.h"

namespace shadelab::test {
namespace {

constexpr uint32_t kWidth = 320;
constexpr uint32_t kHeight = 180;

RenderSettings small(ShadingModel model = ShadingModel::Phong) {
  return {kWidth, kHeight, model};
}

// Every shading model on each scene with a golden: tests/golden/<scene>-<mode>.png.
struct GoldenCase {
  const char* scene;
  ShadingModel model;
};

class ShadingGolden : public GpuTest, public ::testing::WithParamInterface<GoldenCase> {};

TEST_P(ShadingGolden, MatchesGolden) {
  auto [sceneName, model] = GetParam();
  ImageU8 image = render(builtinScene(sceneName), small(model));
  EXPECT_TRUE(
      matchesGolden(std::string(sceneName) + "-" + std::string(shadingModelName(model)), image));
}

std::vector<GoldenCase> goldenCases() {
  std::vector<GoldenCase> cases;
  for (const char* scene : {"default", "spheres", "teapot"})
    for (ShadingModel model : {ShadingModel::Flat, ShadingModel::Gouraud, ShadingModel::Phong,
                               ShadingModel::BlinnPhong, ShadingModel::Unlit})
      cases.push_back({scene, model});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(ScenesAndModels, ShadingGolden, ::testing::ValuesIn(goldenCases()),
                         [](const auto& info) {
                           std::string name = std::string(info.param.scene) + "_" +
                                              std::string(shadingModelName(info.param.model));
                           std::erase(name, '-');
                           return name;
                         });

using RenderImages = GpuTest;

// Must-fail twins: each wrong image must be rejected by the golden tolerance.
TEST_F(RenderImages, ComparisonRejectsMovedLight) {
  Scene scene = builtinScene("default");
  scene.lights[0].position += glm::vec3(0.5f, 0.0f, 0.0f);
  EXPECT_FALSE(matchesImage(loadGolden("default-phong"), render(scene, small())));
}

TEST_F(RenderImages, SpheresComparisonRejectsMovedLight) {
  Scene scene = builtinScene("spheres");
  scene.lights[0].position += glm::vec3(0.5f, 0.0f, 0.0f);
  EXPECT_FALSE(matchesImage(loadGolden("spheres-phong"), render(scene, small())));
}

TEST_F(RenderImages, TeapotComparisonRejectsCoarserTessellation) {
  Scene scene = builtinScene("teapot");
  scene.retessellate(0.5f);  // 4 quads per patch side instead of 8
  EXPECT_FALSE(matchesImage(loadGolden("teapot-flat"), render(scene, small(ShadingModel::Flat))));
}

TEST_F(RenderImages, ComparisonRejectsCameraTurnedOneDegree) {
  Scene scene = builtinScene("default");
  glm::vec4 eye = rotationY(glm::radians(1.0f)) * glm::vec4(scene.camera.eye, 1.0f);
  scene.camera.eye = glm::vec3(eye);
  EXPECT_FALSE(matchesImage(loadGolden("default-phong"), render(scene, small())));
}

TEST_F(RenderImages, ComparisonRejectsOnePercentOfPixelsWrong) {
  ImageU8 image = loadGolden("default-phong");
  // A 24x24 patch is 1% of the image: twice the 0.5% the tolerance allows.
  for (uint32_t y = 80; y < 104; ++y)
    for (uint32_t x = 150; x < 174; ++x) image.set(x, y, {255, 0, 255, 255});
  EXPECT_FALSE(matchesImage(loadGolden("default-phong"), image));
}

TEST_F(RenderImages, OrthographicCameraMatchesGolden) {
  Scene scene = builtinScene("default");
  scene.camera.projection = Projection::Orthographic;
  float halfHeight = 2.6f;
  float halfWidth = halfHeight * float(kWidth) / float(kHeight);
  scene.camera.left = -halfWidth, scene.camera.right = halfWidth;
  scene.camera.bottom = -halfHeight, scene.camera.top = halfHeight;
  scene.camera.near = 1.0f, scene.camera.far = 30.0f;
  EXPECT_TRUE(matchesGolden("default-orthographic", render(scene, small())));
}

// A symmetric frustum with top = n tan(fovy/2) is the perspective projection.
TEST_F(RenderImages, SymmetricFrustumEqualsPerspective) {
  Scene perspective = builtinScene("default");
  Scene frustum = perspective;
  Camera& camera = frustum.camera;
  camera.projection = Projection::Frustum;
  camera.top = camera.near * std::tan(glm::radians(camera.fovyDegrees) / 2.0f);
  camera.bottom = -camera.top;
  camera.right = camera.top * float(kWidth) / float(kHeight);
  camera.left = -camera.right;
  EXPECT_TRUE(matchesImage(render(perspective, small()), render(frustum, small())));
  // An off-centre frustum shifts the image: it must not match.
  camera.left += 0.01f, camera.right += 0.01f;
  EXPECT_FALSE(matchesImage(render(perspective, small()), render(frustum, small())));
}

TEST_F(RenderImages, RendersAreBitIdentical) {
  Scene scene = builtinScene("default");
  RenderResult first = renderer().renderToImage(scene, small());
  RenderResult second = renderer().renderToImage(scene, small());
  Renderer fresh(context());
  RenderResult third = fresh.renderToImage(scene, small());
  ASSERT_EQ(first.image.pixels.size(), second.image.pixels.size());
  EXPECT_EQ(0, std::memcmp(first.image.pixels.data(), second.image.pixels.data(),
                           first.image.pixels.size() * sizeof(float)));
  EXPECT_EQ(0, std::memcmp(first.image.pixels.data(), third.image.pixels.data(),
                           first.image.pixels.size() * sizeof(float)));
}

uint64_t pixelsUnlike(const ImageU8& image, glm::u8vec4 background) {
  uint64_t count = 0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) count += image.at(x, y) != background;
  return count;
}

Scene singleSphere(glm::vec3 eye) {
  Scene scene;
  scene.name = "sphere";
  scene.background = {0.0f, 0.0f, 1.0f};
  scene.camera.eye = eye;
  scene.camera.at = {0.0f, 0.0f, 0.0f};
  if (glm::length(eye) < 1e-6f) scene.camera.at = {0.0f, 0.0f, -1.0f};
  scene.lights.push_back({});
  scene.objects.push_back(
      {"sphere", scene.addMesh(makeUvSphere(1.0f, 32, 16)), glm::mat4(1.0f), Material{}});
  return scene;
}

// Emission is added, unlit, in every lit model, whether the material is
// compiled into the pipeline or read from the push constants: two black
// spheres under no light, in no ambient, one glowing (1, 0.5, 0.125) and one
// (0.25, 0, 1) (equal but for their emission, so a pipeline key without it
// would draw both alike), must show those values at their centres, within
// an RGBA16F step, as the tracer's local term adds Material::emissive. Before
// emission reached the shaders both were black, which the check rejects.
TEST_F(RenderImages, EmissionIsAddedInEveryLitModel) {
  Scene scene = singleSphere({0.0f, 0.0f, 6.0f});
  scene.background = glm::vec3(0.0f);
  scene.ambient = glm::vec3(0.0f);
  scene.lights.clear();
  Material black{glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f), 8.0f};
  scene.objects[0].material = black;
  scene.objects[0].material.emissive = {1.0f, 0.5f, 0.125f};
  scene.objects[0].transform = translation({-1.5f, 0.0f, 0.0f});
  scene.objects.push_back(scene.objects[0]);
  scene.objects[1].material.emissive = {0.25f, 0.0f, 1.0f};
  scene.objects[1].transform = translation({1.5f, 0.0f, 0.0f});
  for (ShadingModel model :
       {ShadingModel::Flat, ShadingModel::Gouraud, ShadingModel::Phong, ShadingModel::BlinnPhong})
    for (bool constants : {false, true}) {
      SCOPED_TRACE(std::string(shadingModelName(model)) + (constants ? ", compiled in" : ""));
      RenderSettings settings = small(model);
      settings.materialConstants = constants;
      ImageRgba image = renderer().renderToImage(scene, settings).image;
      // The spheres' centres: 1.5 units either side, 6 units from the eye.
      const float offset = 1.5f / (6.0f * std::tan(glm::radians(scene.camera.fovyDegrees) / 2.0f)) *
                           float(kHeight) / 2.0f;
      for (size_t i = 0; i < 2; ++i) {
        const float x = float(kWidth) / 2.0f + (i == 0 ? -offset : offset);
        glm::vec3 seen(image.at(uint32_t(x), kHeight / 2));
        glm::vec3 expected = scene.objects[i].material.emissive;
        EXPECT_NEAR(seen.r, expected.r, 1e-3f) << "sphere " << i;
        EXPECT_NEAR(seen.g, expected.g, 1e-3f) << "sphere " << i;
        EXPECT_NEAR(seen.b, expected.b, 1e-3f) << "sphere " << i;
      }
    }
}

// The emission's packing into one push-constant word (RGB9E5): exact for
// values with 9 significant bits, within 1/512 of the largest channel
// otherwise, never negative or NaN, rounding up into the next exponent.
TEST(EmissivePacking, KeepsNineBitsOfTheLargestChannel) {
  EXPECT_EQ(packEmissive(glm::vec3(0.0f)), 0u);
  EXPECT_EQ(unpackEmissive(packEmissive({1.0f, 0.5f, 0.125f})), glm::vec3(1.0f, 0.5f, 0.125f));
  EXPECT_EQ(unpackEmissive(packEmissive({4.0f, 2.0f, 0.0f})), glm::vec3(4.0f, 2.0f, 0.0f));
  EXPECT_EQ(unpackEmissive(packEmissive({-1.0f, NAN, 3.0f})), glm::vec3(0.0f, 0.0f, 3.0f));
  EXPECT_EQ(unpackEmissive(packEmissive(glm::vec3(1e9f))), glm::vec3(65408.0f));
  EXPECT_EQ(unpackEmissive(packEmissive(glm::vec3(511.9f / 512.0f))), glm::vec3(1.0f));
  for (glm::vec3 value : {glm::vec3(0.1f, 0.2f, 0.3f), glm::vec3(12.3f, 0.01f, 7.0f),
                          glm::vec3(1e-4f, 2e-4f, 3e-4f)}) {
    glm::vec3 back = unpackEmissive(packEmissive(value));
    float largest = std::max({value.r, value.g, value.b});
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(back[c], value[c], largest / 512.0f) << c;
  }
}

// visibleDraws' order: the opaque draws front to back (early depth testing
// then skips what they hide), the transparent ones back to front after
// them, what lies behind the eye culled. The old order (opaque in scene
// order) gives 0, 1, 4 first and fails.
TEST(DrawOrder, OpaqueFrontToBackThenTransparentBackToFront) {
  GpuScene scene;
  auto add = [&](float z, bool transparent, uint32_t id) {
    DrawItem draw;
    draw.worldBounds = {{-0.5f, -0.5f, z - 0.5f}, {0.5f, 0.5f, z + 0.5f}};
    draw.transparent = transparent;
    draw.material = id;  // names the draw here
    scene.draws.push_back(draw);
  };
  add(-10.0f, false, 0);
  add(-3.0f, false, 1);
  add(-6.0f, true, 2);
  add(-20.0f, true, 3);
  add(-5.0f, false, 4);
  add(5.0f, false, 5);  // behind the eye
  // The eye at the origin looking down -z.
  glm::mat4 projection = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f);
  uint32_t culled = 0;
  auto order = [&](bool frontToBack) {
    std::vector<uint32_t> ids;
    for (const DrawItem& draw :
         visibleDraws(scene, glm::mat4(1.0f), projection, true, frontToBack, culled))
      ids.push_back(draw.material);
    return ids;
  };
  EXPECT_EQ(order(true), (std::vector<uint32_t>{1, 4, 0, 3, 2}));
  EXPECT_EQ(culled, 1u);
  // Without frontToBack (study zfight) the opaque ones keep scene order.
  EXPECT_EQ(order(false), (std::vector<uint32_t>{0, 1, 4, 3, 2}));
}

// Counter-clockwise front faces with back-face culling: from inside a closed
// sphere every triangle faces away, so nothing is drawn.
TEST_F(RenderImages, BackFacesAreCulled) {
  glm::u8vec4 blue{0, 0, 255, 255};
  EXPECT_EQ(pixelsUnlike(render(singleSphere(glm::vec3(0.0f)), small()), blue), 0u);
  EXPECT_GT(pixelsUnlike(render(singleSphere({0.0f, 0.0f, 4.0f}), small()), blue),
            uint64_t(kWidth * kHeight / 10));
}

// The z-buffer makes the image independent of drawing order.
TEST_F(RenderImages, DepthTestMakesDrawOrderIrrelevant) {
  Scene forward = builtinScene("default");
  Scene reversed = forward;
  std::reverse(reversed.objects.begin(), reversed.objects.end());
  ImageU8 a = render(forward, small());
  ImageU8 b = render(reversed, small());
  EXPECT_EQ(compareImages(a, b).maxDifference, 0);
}

TEST_F(RenderImages, FrameStatisticsCoverEveryFrame) {
  Scene scene = builtinScene("default");
  RenderResult result = renderer().renderToImage(scene, {{64, 64, ShadingModel::Phong}, 7});
  ASSERT_EQ(result.stats.deviceMs.size(), 7u);
  ASSERT_EQ(result.stats.wallMs.size(), 7u);
  for (double ms : result.stats.deviceMs) EXPECT_GT(ms, 0.0);
  EXPECT_EQ(result.stats.triangles, scene.triangleCount());
  EXPECT_EQ(result.stats.drawCalls, scene.objects.size());
}

TEST_F(RenderImages, ImpossibleSizesAreInputErrors) {
  Scene scene = builtinScene("default");
  EXPECT_THROW(renderer().renderToImage(scene, {0, 10, ShadingModel::Phong}), InputError);
  EXPECT_THROW(renderer().renderToImage(scene, {100000, 10, ShadingModel::Phong}), InputError);
  RenderResult tiny = renderer().renderToImage(scene, {1, 1, ShadingModel::Phong});
  EXPECT_EQ(tiny.image.width, 1u);
}

// Per-frame settings reach a frame at record time: switching them on one
// upload draws exactly what a fresh renderToImage with those settings draws,
// and settings the device cannot draw are refused when applied, leaving the
// applied ones in place.
class FrameSettingsOnOneUpload : public GpuTest {
 protected:
  ImageU8 recordFrame(Renderer& renderer, const GpuScene& gpuScene, const Scene& scene) {
    const FrameSettings& settings = renderer.frameSettings();
    Buffer readback(context(), VkDeviceSize(settings.width) * settings.height * 8,
                    VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::HostVisible);
    RenderStats stats;
    renderer.waitForFrame(stats);
    renderer.beginFrame();
    renderer.recordScene(gpuScene, scene, stats);
    renderer.recordReadback(readback);
    renderer.submitFrame();
    renderer.finishFrames(stats);
    return encodeSrgb8(unpackHalfImage(readback.mapped(), settings.width, settings.height));
  }
  // Applies each of `variants` in turn to one upload of `scene`.
  void expectFreshRenders(const Scene& scene, const std::vector<RenderSettings>& variants) {
    Renderer renderer(context());
    GpuScene gpuScene = renderer.upload(scene);
    for (const RenderSettings& settings : variants) {
      renderer.applyFrameSettings(gpuScene, settings);
      ImageU8 switched = recordFrame(renderer, gpuScene, scene);
      EXPECT_EQ(compareImages(render(scene, settings), switched).maxDifference, 0) << scene.name;
    }
    EXPECT_EQ(renderer.uploadCount(), 1u);
  }
};

TEST_F(FrameSettingsOnOneUpload, TextureAndEnvironmentSwitchesMatchFreshRenders) {
  RenderSettings base{160, 90, ShadingModel::Phong};
  RenderSettings noBump = base, tint = base, nearest = base, noEnvironment = base;
  noBump.textures.bump = false;
  tint.textures.mipTint = true;
  nearest.textures.filterOverride = TextureFilter::Nearest;
  noEnvironment.environment = false;
  expectFreshRenders(builtinScene("bump"), {noBump, base, noBump});
  expectFreshRenders(builtinScene("mip-plane"), {tint, nearest, base, tint});
  expectFreshRenders(builtinScene("env"), {noEnvironment, base, noEnvironment});
  // Must-fail twin: the switches change the image, so a stale one is caught.
  EXPECT_GT(compareImages(render(builtinScene("bump"), base), render(builtinScene("bump"), noBump))
                .maxDifference,
            0);
}

TEST_F(FrameSettingsOnOneUpload, RefusedSettingsLeaveTheAppliedOnes) {
  Scene scene = builtinScene("default");
  Renderer renderer(context());
  GpuScene gpuScene = renderer.upload(scene);
  RenderSettings settings{96, 54, ShadingModel::Gouraud};
  renderer.applyFrameSettings(gpuScene, settings);
  FrameSettings badMsaa = settings, badSize = settings, badSplit = settings;
  badMsaa.msaaSamples = 3;
  badSize.width = 0;
  badSplit.width = 3;
  badSplit.splitModels = {ShadingModel::Flat, ShadingModel::Gouraud, ShadingModel::Phong,
                          ShadingModel::BlinnPhong};
  for (const FrameSettings& bad : {badMsaa, badSize, badSplit})
    EXPECT_THROW(renderer.applyFrameSettings(gpuScene, bad), InputError);
  EXPECT_EQ(renderer.frameSettings().msaaSamples, 1u);
  EXPECT_EQ(renderer.frameSettings().width, 96u);
  EXPECT_EQ(
      compareImages(render(scene, settings), recordFrame(renderer, gpuScene, scene)).maxDifference,
      0);
}

}  // namespace
}  // namespace shadelab::test

namespace shadelab::test {
namespace {

// The guard every GPU test relies on must itself be able to fail: a
// deliberately invalid call has to be counted.
TEST(ValidationLayer, CountsAnInvalidCall) {
  Context& context = sharedContext();
  context.resetValidationReport();
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.anisotropyEnable = VK_TRUE;
  info.maxAnisotropy =
      1000.0f;  // above maxSamplerAnisotropy: VUID-VkSamplerCreateInfo-anisotropyEnable-01071
  info.maxLod = 1.0f;
  VkSampler sampler = VK_NULL_HANDLE;
  vkCreateSampler(context.device(), &info, nullptr, &sampler);
  if (sampler) vkDestroySampler(context.device(), sampler, nullptr);
  EXPECT_GE(context.validationReport().errors, 1u);
  context.resetValidationReport();
}

// Messages raised while the device is destroyed count too (what the CLI's
// exit code reads): an object left alive is reported by vkDestroyDevice.
TEST(ValidationLayer, CountsWhatTeardownReports) {
  ContextOptions options;
  options.validation = true;
  Context context(options);
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.maxLod = 1.0f;
  VkSampler leaked = VK_NULL_HANDLE;
  ASSERT_EQ(vkCreateSampler(context.device(), &info, nullptr, &leaked), VK_SUCCESS);
  EXPECT_EQ(context.validationReport().total(), 0u);
  EXPECT_GE(context.shutdown().errors, 1u);
}

}  // namespace
}  // namespace shadelab::test
