// Shadow maps on the device: goldens of each filter on the `shadows` scene
// (contact shadows of a box and a sphere, a post's long shadow under a low
// sun, a point light's cube map), each with must-fail twins; the GPU's
// shadow term against the C++ twin of the equation with the tracer's exact
// shadow rays; acne and peter-panning of the default bias measured.
#include <cmath>
#include <functional>

#include "core/scene/lighting.h"
#include "core/scene/scene_json.h"
#include "core/scene/transform.h"
#include "core/trace/raytracer.h"
#include "core/vulkan/gpu_scene.h"
#include "gpu_test_support.h"
#include "measure/shadow_study.h"

namespace shadelab::test {
namespace {

constexpr uint32_t kWidth = 320;
constexpr uint32_t kHeight = 180;

RenderSettings shadowed(ShadowMethod method, ShadingModel model = ShadingModel::Phong) {
  RenderSettings settings{kWidth, kHeight, model};
  settings.shadows = method;
  return settings;
}

struct ShadowGoldenCase {
  ShadowMethod method;
  ShadingModel model;
  std::string name() const {
    return "shadows-" + std::string(nameOf(kShadowMethodNames, method)) + "-" +
           std::string(shadingModelName(model));
  }
};

class ShadowGolden : public GpuTest, public ::testing::WithParamInterface<ShadowGoldenCase> {};

TEST_P(ShadowGolden, MatchesGolden) {
  const ShadowGoldenCase& c = GetParam();
  EXPECT_TRUE(
      matchesGolden(c.name(), render(builtinScene("shadows"), shadowed(c.method, c.model))));
}

// Must-fail twins: the same frame without shadows, and with the sun turned
// by two degrees (every shadow moves, the lit shading barely), must be rejected.
TEST_P(ShadowGolden, ComparisonRejectsNoShadowsAndAMovedSun) {
  const ShadowGoldenCase& c = GetParam();
  ImageU8 golden = loadGolden(c.name());
  Scene scene = builtinScene("shadows");
  EXPECT_FALSE(matchesImage(golden, render(scene, shadowed(ShadowMethod::Off, c.model))));
  glm::vec4 turned = rotationY(glm::radians(2.0f)) * glm::vec4(scene.lights[0].direction, 0.0f);
  scene.lights[0].direction = glm::vec3(turned);
  EXPECT_FALSE(matchesImage(golden, render(scene, shadowed(c.method, c.model))));
}

INSTANTIATE_TEST_SUITE_P(
    Methods, ShadowGolden,
    ::testing::Values(ShadowGoldenCase{ShadowMethod::Hard, ShadingModel::Phong},
                      ShadowGoldenCase{ShadowMethod::Pcf3, ShadingModel::Phong},
                      ShadowGoldenCase{ShadowMethod::Pcf5, ShadingModel::Phong},
                      ShadowGoldenCase{ShadowMethod::Pcf3, ShadingModel::Flat},
                      ShadowGoldenCase{ShadowMethod::Pcf3, ShadingModel::Gouraud}),
    [](const auto& info) {
      std::string name = info.param.name();
      std::erase(name, '-');
      return name;
    });

using ShadowImages = GpuTest;

// Floor pixels (the plane is exact in both renderers) sampled on a grid:
// the GPU's Phong colour against illuminate() with k_shadow = 1 where the
// tracer's shadow ray reaches the light and 0 where it does not.
struct TwinAgreement {
  int samples = 0, agreeing = 0, shadowedSamples = 0;
};

TwinAgreement compareWithTwin(Renderer& renderer, const Scene& scene, bool useShadowTerm) {
  ImageRgba gpu = renderer.renderToImage(scene, shadowed(ShadowMethod::Pcf3)).image;
  std::vector<ShadowTruth> truths;
  for (uint32_t light = 0; light < scene.lights.size(); ++light)
    truths.push_back(traceShadowTruth(scene, light, kWidth, kHeight));
  RayTracer tracer(scene);
  CameraRays camera(scene.camera, kWidth, kHeight);
  glm::mat4 view = scene.camera.viewMatrix();
  std::vector<Light> lights;
  for (const Light& light : scene.lights) lights.push_back(lightInView(light, view));
  TwinAgreement result;
  for (uint32_t y = 2; y < kHeight; y += 4)
    for (uint32_t x = 2; x < kWidth; x += 4) {
      size_t p = size_t(y) * kWidth + x;
      std::optional<SurfaceHit> hit =
          tracer.intersect(camera.through(float(x) + 0.5f, float(y) + 0.5f), 0.0f, 1.0f);
      if (!hit || hit->object != 0) continue;  // the floor only
      std::vector<float> k;
      bool known = true;
      for (const ShadowTruth& truth : truths) {
        ShadowTruth::Pixel pixel = truth.pixels[p];
        known &= pixel != ShadowTruth::Pixel::Ignored;
        k.push_back(pixel == ShadowTruth::Pixel::Lit ? 1.0f : 0.0f);
      }
      if (!known) continue;
      glm::vec3 position(view * glm::vec4(hit->position, 1.0f));
      glm::vec3 normal = glm::mat3(view) * hit->geometricNormal;
      glm::vec3 expected =
          illuminate(scene.ambient, lights, position, normal, scene.objects[0].material, false,
                     useShadowTerm ? std::span<const float>(k) : std::span<const float>());
      glm::vec3 actual(gpu.pixels[p * 4], gpu.pixels[p * 4 + 1], gpu.pixels[p * 4 + 2]);
      ++result.samples;
      result.shadowedSamples += std::count(k.begin(), k.end(), 0.0f) > 0 ? 1 : 0;
      // Half-float target: a few thousandths of slack.
      result.agreeing += glm::all(glm::lessThan(glm::abs(actual - expected), glm::vec3(0.01f)));
    }
  return result;
}

// The lights that cast shadows are a specialization constant (bit i: the
// i-th light in FrameData's order, point lights first): a light whose JSON
// says "shadows": false has no lookup compiled at all.
TEST(ShadowedLights, LayoutMarksThemInFrameOrder) {
  Scene scene = builtinScene("shadows");  // a directional light, then a point light
  ASSERT_EQ(scene.lights.size(), 2u);
  EXPECT_EQ(lightLayoutOf(scene).shadowed, 0b11u);
  scene.lights[0].shadows = false;  // the directional light: slot 1, after the point light
  EXPECT_EQ(lightLayoutOf(scene).shadowed, 0b01u);
  scene.lights[1].shadows = false;
  EXPECT_EQ(lightLayoutOf(scene).shadowed, 0u);
}

// With every light's shadows off in the scene, shadow maps on draw exactly
// the frame without them; with one left on, not (the sun's shadows stay).
TEST_F(ShadowImages, LightsWithoutShadowsAreLitAsWithShadowsOff) {
  Scene scene = builtinScene("shadows");
  ImageU8 unshadowed = render(scene, shadowed(ShadowMethod::Off));
  Scene noneCast = scene;
  for (Light& light : noneCast.lights) light.shadows = false;
  ImageU8 none = render(noneCast, shadowed(ShadowMethod::Hard));
  EXPECT_EQ(none.pixels, unshadowed.pixels);
  Scene sunCasts = noneCast;
  sunCasts.lights[0].shadows = true;
  EXPECT_NE(render(sunCasts, shadowed(ShadowMethod::Hard)).pixels, unshadowed.pixels);
}

TEST_F(ShadowImages, GpuShadowTermAgreesWithTheCppTwin) {
  TwinAgreement agreement = compareWithTwin(renderer(), builtinScene("shadows"), true);
  ASSERT_GT(agreement.samples, 500);
  ASSERT_GT(agreement.shadowedSamples, 50);  // the floor holds shadows of both lights
  EXPECT_GE(agreement.agreeing, agreement.samples * 99 / 100)
      << agreement.agreeing << " of " << agreement.samples;
}

// Must-fail twin: the twin without its shadow term disagrees on the shadows.
TEST_F(ShadowImages, TwinWithoutShadowTermDisagrees) {
  TwinAgreement agreement = compareWithTwin(renderer(), builtinScene("shadows"), false);
  EXPECT_LT(agreement.agreeing, agreement.samples - agreement.shadowedSamples * 9 / 10);
}

// check(errors) for each light of `scene` and each filter, at the default
// bias and map size, against the tracer's truth for that light.
void forEachLightAndFilter(Renderer& renderer, const Scene& scene,
                           const std::function<void(const ShadowErrors&)>& check) {
  for (uint32_t light = 0; light < scene.lights.size(); ++light) {
    ShadowTruth truth = traceShadowTruth(scene, light, kWidth, kHeight);
    for (ShadowMethod method : {ShadowMethod::Hard, ShadowMethod::Pcf3, ShadowMethod::Pcf5}) {
      SCOPED_TRACE(std::to_string(light) + " " + std::string(nameOf(kShadowMethodNames, method)));
      check(measureShadowErrors(renderer, scene, light, truth, method, ShadowBias{},
                                kDefaultShadowMapSize));
    }
  }
}

// The default bias: acne under 0.1% of truly lit pixels and peter-panning
// under 1% of truly shadowed ones near contact, for each light kind and
// each filter (the filters' receiver-plane taps must not push shadows off
// their casters).
TEST_F(ShadowImages, DefaultBiasKeepsAcneAndPeterPanningSmall) {
  forEachLightAndFilter(renderer(), builtinScene("shadows"), [](const ShadowErrors& errors) {
    ASSERT_GT(errors.lit, 5000u);
    ASSERT_GT(errors.contact, 100u);
    EXPECT_LT(errors.acneFraction(), 0.001);
    EXPECT_LT(errors.peterPanningFraction(), 0.01);
  });
}

// Percentage-closer filtering compares its outer taps, up to 2 sqrt(2)
// texels away, at the centre's depth: on a floor lit at a grazing angle the
// taps have to compare the depth the surface has where they look, or lit
// floor is dimmed in rings (before each tap took its receiver-plane depth,
// PCF5 dimmed 11.6% of this floor's pixels, by 1-3 8-bit codes, under the
// point light). The floor is the only object, so every pixel is truly lit;
// the measure is the share of it drawn below 0.98 of its light (one PCF5
// tap in 25 shadowed). Directional lights had no rings; both kinds are held
// to it. Twin: a hard lookup with no bias at all dims the floor (acne), and
// the measure says so.
TEST_F(ShadowImages, FilteredLookupsKeepALitFloorLit) {
  Scene scene = parseSceneJson(R"({
    "camera": {"eye": [0, 3, 9], "at": [0, 0, 0], "fovy": 50},
    "ambient": 0, "background": 0,
    "lights": [{"type": "point", "position": [0, 1, 0], "intensity": 1},
               {"type": "directional", "direction": [-1, -0.3, -0.45], "intensity": 1}],
    "objects": [{"name": "floor", "shape": "plane", "size": 30, "tessellation": 8,
                 "material": {"ka": 0, "kd": 0.8, "ks": 0, "shininess": 4}}]})",
                               "floor.json");
  forEachLightAndFilter(renderer(), scene, [](const ShadowErrors& errors) {
    ASSERT_GT(errors.lit, 20000u);
    EXPECT_LT(errors.dimmedFraction(), 0.001) << errors.dimmed << " of " << errors.lit;
  });
  ShadowTruth truth = traceShadowTruth(scene, 0, kWidth, kHeight);
  ShadowErrors noBias = measureShadowErrors(renderer(), scene, 0, truth, ShadowMethod::Hard,
                                            {0.0f, 0.0f, 0.0f}, kDefaultShadowMapSize);
  EXPECT_GT(noBias.dimmedFraction(), 0.05) << noBias.dimmed << " of " << noBias.lit;
}

// Must-fail twins of the measure: no bias shows acne, a large one peter-panning.
TEST_F(ShadowImages, ZeroBiasShowsAcneAndLargeBiasPeterPanning) {
  Scene scene = builtinScene("shadows");
  ShadowTruth truth = traceShadowTruth(scene, 0, kWidth, kHeight);
  ShadowErrors none = measureShadowErrors(renderer(), scene, 0, truth, ShadowMethod::Hard,
                                          {0.0f, 0.0f, 0.0f}, kDefaultShadowMapSize);
  EXPECT_GT(none.acneFraction(), 0.01);
  ShadowErrors large = measureShadowErrors(renderer(), scene, 0, truth, ShadowMethod::Hard,
                                           {64.0f, 0.0f, 64.0f}, kDefaultShadowMapSize);
  EXPECT_GT(large.peterPanningFraction(), 0.02) << large.peterPanning << " of " << large.contact;
}

// Shadows through glass: a ball of kt 0.85 and ior 1.5 over a floor, under a
// directional light and, apart, a point light above it. Each crossing of
// the ball passes kt (1 - F), so the floor under the ball gets
// (0.85 (1 - F))^2 of the light: 0.67 under its centre, 0.59 where the
// light meets it 0.9 of its radius out. The raster floor must agree with the tracer's exact shadow
// rays within 4 of 255 (sRGB) under the centre and near the rim, for every filter; the code before
// the translucent layers left the floor in full shadow. And the ball's own lit top, in front of its
// translucent depth, must stay as lit as when the ball casts nothing (the gate: without it the top
// would be dimmed by its own transmittance).
// The green channel (sRGB) of `image` where `camera` sees world point `world`.
int greenAt(const ImageU8& image, const Camera& camera, glm::vec3 world) {
  const glm::mat4 toClip =
      camera.projectionMatrix(float(image.width) / float(image.height)) * camera.viewMatrix();
  glm::vec4 clip = toClip * glm::vec4(world, 1.0f);
  glm::vec2 ndc = glm::vec2(clip) / clip.w;
  auto x = uint32_t((ndc.x * 0.5f + 0.5f) * float(image.width));
  auto y = uint32_t((ndc.y * 0.5f + 0.5f) * float(image.height));
  return int(image.pixels[(size_t(y) * image.width + x) * 4 + 1]);
}

struct GlassCase {
  const char* name;
  Light light;
  float ior = 1.5f;
  friend void PrintTo(const GlassCase& c, std::ostream* os) { *os << c.name; }
};

// A ball of kt 0.85 and radius 1 at (0, 1.5, 0) over a floor: object 1.
Scene glassBallScene(const Light& light, float ior) {
  Scene scene;
  scene.camera.eye = {0.0f, 5.0f, 6.0f};
  scene.camera.at = {0.0f, 0.5f, 0.0f};
  scene.ambient = glm::vec3(0.1f);
  scene.lights.push_back(light);
  ShapeDesc floorShape{ShapeKind::Plane};
  floorShape.size = 12.0f;
  Material floor{glm::vec3(0.1f), glm::vec3(0.8f), glm::vec3(0.0f), 1.0f};
  scene.objects.push_back({"floor", scene.addShape(floorShape), glm::mat4(1.0f), floor});
  ShapeDesc ball{ShapeKind::UvSphere};
  ball.radius = 1.0f;
  ball.tessellation = 64;
  Material glass{glm::vec3(0.1f), glm::vec3(0.6f), glm::vec3(0.0f), 1.0f};
  glass.transparency = 0.85f;
  glass.ior = ior;
  scene.objects.push_back({"glass", scene.addShape(ball), translation({0.0f, 1.5f, 0.0f}), glass});
  return scene;
}

class GlassShadow : public GpuTest, public ::testing::WithParamInterface<GlassCase> {};

TEST_P(GlassShadow, FloorGetsWhatTheTracerPassesAndTheLitSideStaysLit) {
  const Scene scene = glassBallScene(GetParam().light, GetParam().ior);
  const uint32_t width = 320, height = 240;
  TraceSettings trace;
  trace.width = width, trace.height = height, trace.samplesPerPixel = 1, trace.shadows = true;
  const ImageU8 traced = encodeSrgb8(RayTracer(scene).render(trace).image);
  auto green = [&](const ImageU8& image, glm::vec3 world) {
    return greenAt(image, scene.camera, world);
  };
  // Floor points under the ball (the light's rays through them meet it at
  // its centre and 0.9 of its radius out), found along the light.
  const Light& light = scene.lights[0];
  auto underBall = [&](glm::vec3 throughBall) {
    glm::vec3 towardsLight = light.type == LightType::Point
                                 ? glm::normalize(light.position - throughBall)
                                 : -glm::normalize(light.direction);
    return throughBall - towardsLight * (throughBall.y / towardsLight.y);
  };
  const glm::vec3 centre = underBall({0.0f, 1.5f, 0.0f});
  const glm::vec3 rim = underBall({0.9f, 1.5f, 0.0f});
  const int lit = green(traced, {3.0f, 0.0f, 1.0f});
  const int centreTrace = green(traced, centre), rimTrace = green(traced, rim);
  // The scene shows what it is for: a shadow, lighter than ambient alone,
  // darker towards the rim.
  ASSERT_LT(centreTrace, lit - 20);
  ASSERT_LT(rimTrace, centreTrace - 3);
  for (ShadowMethod method : {ShadowMethod::Hard, ShadowMethod::Pcf3, ShadowMethod::Pcf5}) {
    RenderSettings settings{width, height, ShadingModel::Phong};
    settings.shadows = method;
    const ImageU8 raster = render(scene, settings);
    const char* filter = nameOf(kShadowMethodNames, method).data();
    std::printf(
        "%s, %s: floor lit %d; under the centre trace %d raster %d; near the rim trace "
        "%d raster %d\n",
        GetParam().name, filter, lit, centreTrace, green(raster, centre), rimTrace,
        green(raster, rim));
    EXPECT_NEAR(green(raster, centre), centreTrace, 4) << filter;
    EXPECT_NEAR(green(raster, rim), rimTrace, 4) << filter;
    Scene noCaster = scene;
    noCaster.objects[1].castsShadows = false;
    const ImageU8 uncast = render(noCaster, settings);
    const glm::vec3 top =
        glm::vec3(0.0f, 2.5f, 0.0f) +
        0.2f * glm::normalize(glm::vec3(scene.camera.eye - glm::vec3(0.0f, 2.5f, 0.0f)));
    EXPECT_NEAR(green(raster, top), green(uncast, top), 1) << filter << ": the ball's lit top";
  }
}

INSTANTIATE_TEST_SUITE_P(
    Lights, GlassShadow,
    ::testing::Values(
        GlassCase{"directional",
                  {LightType::Directional, {}, {0.1f, -1.0f, 0.05f}, glm::vec3(0.9f)}},
        GlassCase{"point", {LightType::Point, {0.3f, 7.0f, 0.2f}, {}, glm::vec3(0.9f)}},
        // Air in water, say: a thinner ball (ior 0.75) reflects everything
        // past its critical angle, so its shadow's rim is black.
        GlassCase{
            "bubble", {LightType::Directional, {}, {0.1f, -1.0f, 0.05f}, glm::vec3(0.9f)}, 0.75f}),
    [](const auto& info) { return std::string(info.param.name); });

// The translucent layers exist while the scene has a transparent caster:
// the same renderer draws the glass scene, then the scene with the ball
// casting nothing (no such layers; prepare() drops them), then the glass
// scene again, which must come out bit for bit as the first time; and the
// middle one must differ (the ball's shadow is gone).
TEST_F(ShadowImages, TranslucentLayersComeAndGoWithTheScene) {
  Scene glass = glassBallScene({LightType::Point, {0.3f, 7.0f, 0.2f}, {}, glm::vec3(0.9f)}, 1.5f);
  Scene clear = glass;
  clear.objects[1].castsShadows = false;
  const RenderSettings settings = shadowed(kDefaultShadowMethod);
  const ImageU8 first = render(glass, settings);
  const ImageU8 without = render(clear, settings);
  const ImageU8 again = render(glass, settings);
  EXPECT_TRUE(first.pixels == again.pixels);
  EXPECT_FALSE(first.pixels == without.pixels);
}

// glTF BLEND without a texture (coverage, kt = 1 - the factor's alpha): the
// shadow maps pass 1 - alpha per surface, as the tracer's shadow rays do,
// with no Fresnel term. A card of alpha 0.4 (transparency 0.6) over a floor,
// under a light 70 degrees from the vertical, where Fresnel would pass 0.505
// instead of 0.6: the floor in its shadow gets 0.6 of the light in both
// renderers (within 3 of 255); the code before the translucent layers cast a
// full shadow there.
TEST_F(ShadowImages, BlendedFactorCardPassesOneMinusItsAlpha) {
  Scene scene;
  scene.camera.eye = {0.0f, 4.0f, 5.0f};
  scene.camera.at = {0.0f, 0.0f, 0.0f};
  scene.ambient = glm::vec3(0.1f);
  const float tilt = glm::radians(70.0f);
  const glm::vec3 travel(std::sin(tilt), -std::cos(tilt), 0.0f);
  scene.lights.push_back({LightType::Directional, {}, travel, glm::vec3(0.9f)});
  ShapeDesc floorShape{ShapeKind::Plane};
  floorShape.size = 12.0f;
  Material floor{glm::vec3(0.1f), glm::vec3(0.8f), glm::vec3(0.0f), 1.0f};
  scene.objects.push_back({"floor", scene.addShape(floorShape), glm::mat4(1.0f), floor});
  ShapeDesc cardShape{ShapeKind::Plane};
  cardShape.size = 2.0f;
  Material card{glm::vec3(0.1f), glm::vec3(0.5f), glm::vec3(0.0f), 1.0f};
  card.alphaCoverage = true;
  card.transparency = 0.6f;  // 1 - the factor's alpha
  card.doubleSided = true;
  scene.objects.push_back(
      {"card", scene.addShape(cardShape), translation({-2.0f, 1.0f, 0.0f}), card});
  const uint32_t width = 320, height = 240;
  TraceSettings trace;
  trace.width = width, trace.height = height, trace.samplesPerPixel = 1, trace.shadows = true;
  const ImageU8 traced = encodeSrgb8(RayTracer(scene).render(trace).image);
  RenderSettings settings{width, height, ShadingModel::Phong};
  settings.shadows = kDefaultShadowMethod;
  const ImageU8 raster = render(scene, settings);
  // Where the light through the card's centre (-2, 1, 0) meets the floor.
  const glm::vec3 under = glm::vec3(-2.0f, 1.0f, 0.0f) + travel / std::cos(tilt);
  const glm::vec3 open(0.0f, 0.0f, 2.0f);
  const int lit = greenAt(traced, scene.camera, open);
  const int expected = greenAt(traced, scene.camera, under);
  const int got = greenAt(raster, scene.camera, under);
  std::printf("floor lit %d (raster %d); under the card trace %d, raster %d\n", lit,
              greenAt(raster, scene.camera, open), expected, got);
  ASSERT_LT(expected, lit - 20);  // the card casts a shadow, lighter than ambient alone
  EXPECT_NEAR(got, expected, 3);
}

}  // namespace
}  // namespace shadelab::test
