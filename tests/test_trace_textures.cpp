// Textures and environments in the traced reference: a checker plane seen
// from above gives the checker's analytic colour at known pixels and, far
// minified, the linear mean of its two colours (area filtering, not a
// point sample); a constant environment is reflected times kr as the
// rasteriser's environment mapping does; the textured example scene agrees
// with the rasteriser, and not with other S-mappings; a golden of a textured
// scene under the sky, with must-fail twins.
#include <cmath>
#include <cstdio>
#include <functional>
#include <tuple>

#include "core/base/image.h"
#include "core/metrics/metrics.h"
#include "core/scene/procedural_textures.h"
#include "core/scene/scene_loader.h"
#include "core/scene/texture.h"
#include "core/scene/transform.h"
#include "core/trace/raytracer.h"
#include "environment_test_support.h"
#include "gpu_test_support.h"

namespace shadelab::test {
namespace {

constexpr glm::vec3 kLow{0.05f, 0.1f, 0.2f}, kHigh{0.9f, 0.6f, 0.3f};

// The colour the 8-bit sRGB texel of a linear colour decodes to.
glm::vec3 stored(glm::vec3 linear) {
  glm::vec3 result;
  for (int c = 0; c < 3; ++c)
    result[c] = srgbToLinear(std::round(linearToSrgb(linear[c]) * 255.0f) / 255.0f);
  return result;
}

// A 2 x 2 plane filling an orthographic view from above (row 0 at z = -1),
// unlit: ambient 1 times ka = 1 times the texel, so a pixel is its texel.
Scene checkerPlane(float uvScale) {
  Scene scene;
  scene.camera.eye = {0.0f, 5.0f, 0.0f};
  scene.camera.up = {0.0f, 0.0f, -1.0f};
  scene.camera.projection = Projection::Orthographic;
  scene.ambient = glm::vec3(1.0f);
  scene.textures.push_back(heightColorTexture(proceduralHeight({HeightPattern::Checker, 64, 4}),
                                              kLow, kHigh, "checker"));
  Material board;
  board.ka = glm::vec3(1.0f);
  board.kd = board.ks = glm::vec3(0.0f);
  board.diffuseMap.texture = 0;
  board.uvScale = glm::vec2(uvScale);
  scene.objects.push_back(
      {"board", scene.addShape({ShapeKind::Plane, 2.0f}), glm::mat4(1.0f), board});
  return scene;
}

ImageRgba traceAt(const Scene& scene, uint32_t width, uint32_t height, uint32_t spp) {
  TraceSettings settings;
  settings.width = width, settings.height = height, settings.samplesPerPixel = spp;
  return RayTracer(scene).render(settings).image;
}

// Pixel centre -> plane point -> uv (makePlane: u = x / 2 + 0.5, v = 0.5 -
// z / 2) -> st = (u s, 1 - v s) -> check parity (even: the high colour).
TEST(TraceTextures, CheckerPlaneShowsTheAnalyticCheckerColour) {
  const float scale = 2.0f;  // 8 checks across 160 pixels: 20 pixels each
  const ImageRgba image = traceAt(checkerPlane(scale), 160, 160, 1);
  float worst = 0.0f;
  int highs = 0, lows = 0;
  for (int cellY = 0; cellY < 8; ++cellY)
    for (int cellX = 0; cellX < 8; ++cellX) {
      // Check centres and points 6 pixels off them, clear of the filtered edges.
      for (glm::ivec2 offset : {glm::ivec2(0), glm::ivec2(6, -6), glm::ivec2(-6, 5)}) {
        const glm::ivec2 pixel = glm::ivec2(cellX * 20 + 10, cellY * 20 + 10) + offset;
        const float x = -1.0f + 2.0f * (float(pixel.x) + 0.5f) / 160.0f;
        const float z = -1.0f + 2.0f * (float(pixel.y) + 0.5f) / 160.0f;
        const glm::vec2 uv{x / 2.0f + 0.5f, 0.5f - z / 2.0f};
        const glm::vec2 st{uv.x * scale, 1.0f - uv.y * scale};
        const bool high = (int(std::floor(st.x * 4.0f)) + int(std::floor(st.y * 4.0f))) % 2 == 0;
        (high ? highs : lows)++;
        const glm::vec3 expected = stored(high ? kHigh : kLow);
        worst = std::max(worst, glm::length(glm::vec3(image.at(pixel.x, pixel.y)) - expected));
      }
    }
  std::printf("checker plane: worst |traced - analytic| %.6f over %d + %d pixels\n", worst, highs,
              lows);
  EXPECT_EQ(highs, lows);
  EXPECT_LE(worst, 1e-4f);
}

// 64 checks per pixel: any point sample is one of the two colours; the
// area filter (the mip level from the pixel's footprint) gives their mean
// in linear light, mip levels being averaged in linear light as on the GPU.
TEST(TraceTextures, MinifiedCheckerAveragesToTheLinearMean) {
  const ImageRgba image = traceAt(checkerPlane(256.0f), 32, 32, 1);
  const glm::vec3 mean = 0.5f * (stored(kLow) + stored(kHigh));
  float worst = 0.0f;
  for (uint32_t y = 0; y < 32; ++y)
    for (uint32_t x = 0; x < 32; ++x)
      worst = std::max(worst, glm::length(glm::vec3(image.at(x, y)) - mean));
  std::printf("minified checker: worst |traced - linear mean| %.5f (the colours are %.3f apart)\n",
              worst, glm::length(stored(kHigh) - stored(kLow)));
  EXPECT_LE(worst, 0.01f);
}

using TraceEnvironment = GpuTest;

// The scene of EnvironmentShading.ConstantEnvironmentTimesReflectivityInEveryLitModel
// (test_environment_images.cpp) with mirrors only: a ray through glass
// crosses two surfaces in the tracer (kt^2), one in environment mapping.
// Mirror (kr 0.6) and textured mirror (kr 0.8, its texel scaling kd = 0),
// black otherwise: traced and rasterised both show kr c, the sky c.
TEST_F(TraceEnvironment, ConstantEnvironmentTimesReflectivityAsInTheRasteriser) {
  const glm::vec3 colour{0.8f, 0.5f, 0.2f};
  Scene scene;
  scene.camera.eye = {0.0f, 0.0f, 6.0f};
  scene.environment = constantSky(colour);
  scene.lights.push_back({});
  const uint32_t sphere = scene.addShape({ShapeKind::UvSphere, 1.0f, {}, 0.7f, 1.0f, 0.25f, 24});
  Material mirror;
  mirror.ka = mirror.kd = mirror.ks = glm::vec3(0.0f);
  mirror.reflectivity = 0.6f;
  scene.objects.push_back({"mirror", sphere, translation({-1.6f, 0, 0}), mirror});
  scene.textures.push_back(solidTexture({200, 30, 30, 255}, TextureRole::Color, "red"));
  Material textured = mirror;
  textured.reflectivity = 0.8f;
  textured.diffuseMap.texture = 0;
  scene.objects.push_back({"textured", sphere, translation({1.6f, 0, 0}), textured});
  const ImageRgba traced = traceAt(scene, 160, 90, 1);
  const ImageRgba raster = renderer().renderToImage(scene, {160, 90, ShadingModel::Phong}).image;
  float worstTraced = 0.0f, worstRaster = 0.0f;
  // Within 5 pixels of a centre (of 12.7) reflected rays turn under 50
  // degrees from the view ray and miss the other sphere; further out the
  // tracer rightly shows one sphere in the other, which environment mapping cannot.
  for (auto [centreX, expected] : {std::pair{51, 0.6f * colour}, std::pair{109, 0.8f * colour}})
    for (int dy = -5; dy <= 5; ++dy)
      for (int dx = -5; dx <= 5; ++dx) {
        const uint32_t x = uint32_t(centreX + dx), y = uint32_t(45 + dy);
        worstTraced = std::max(worstTraced, glm::length(glm::vec3(traced.at(x, y)) - expected));
        worstRaster = std::max(worstRaster, glm::length(glm::vec3(raster.at(x, y)) - expected));
      }
  std::printf("constant environment: worst |colour - kr c| traced %.6f, rasterised %.6f\n",
              worstTraced, worstRaster);
  EXPECT_LE(worstTraced, 1.0f / 255.0f);
  EXPECT_LE(worstRaster, 1.0f / 255.0f);
  EXPECT_LE(glm::length(glm::vec3(traced.at(2, 2)) - colour), 1e-5f);  // a miss sees the sky
}

// assets/scenes/textured.json (a checker floor, a box-mapped brick crate
// with a normal map, a height-mapped ball, a cylindrically mapped teapot
// with mirrored and clamped wrap) traced at pixel centres without shadows
// against raster Phong: the uv, S-mappings, wraps, sRGB decoding and bump
// maps agree when the FLIP is small, and the same comparison with the
// tracer given other S-mappings (box -> planar, cylindrical -> spherical)
// must be clearly worse.
double texturedSceneFlip(Renderer& renderer, bool swapMappings) {
  const Scene scene = loadScene(std::string(SHADELAB_ASSET_DIR) + "/scenes/textured.json");
  Scene traced = scene;
  if (swapMappings)
    for (Object& object : traced.objects) {
      UvProjection& projection = object.material.uvProjection;
      if (projection == UvProjection::Box) projection = UvProjection::Planar;
      if (projection == UvProjection::Cylindrical) projection = UvProjection::Spherical;
    }
  TraceSettings trace;
  trace.width = 160, trace.height = 90, trace.samplesPerPixel = 1, trace.shadows = false;
  RenderSettings raster{trace.width, trace.height, ShadingModel::Phong};
  // The teapot at the rasteriser's own tessellation: the BVH builds in a tenth of the time.
  return flipError(encodeSrgb8(RayTracer(traced, 1.0f).render(trace).image),
                   encodeSrgb8(renderer.renderToImage(scene, raster).image))
      .mean;
}

TEST_F(TraceEnvironment, TexturedSceneAgreesWithTheRasteriser) {
  const double same = texturedSceneFlip(renderer(), false);
  const double swapped = texturedSceneFlip(renderer(), true);
  std::printf(
      "textured.json, raster Phong vs trace: mean FLIP %.4f; tracer with other "
      "S-mappings %.4f\n",
      same, swapped);
  EXPECT_LE(same, 0.02);
  EXPECT_GT(swapped, same + 0.005);
}

// glTF's alphaMode MASK, KHR_texture_transform, single-sided culling and
// nearest magnification in the traced reference (tests/data:
// alpha_mask.gltf's checker-holed quad over a floor, texture_transform.gltf's
// offset/rotated/scaled base colour and shifted normal map on 2x2 nearest
// textures, double_sided.gltf's two quads seen from behind, one of them
// single-sided), traced at pixel centres without shadows against raster
// Phong: the features agree when the FLIP is small, and the tracer with a
// feature undone (`undo` changes the traced scene only) must be clearly worse.
double gltfFeatureFlip(Renderer& renderer, const std::string& file,
                       const std::function<void(Material&)>& undo) {
  const Scene scene = loadScene(std::string(SHADELAB_TEST_DATA_DIR) + "/" + file);
  Scene traced = scene;
  if (undo)
    for (Object& object : traced.objects) undo(object.material);
  TraceSettings trace;
  trace.width = 160, trace.height = 120, trace.samplesPerPixel = 1, trace.shadows = false;
  RenderSettings raster{trace.width, trace.height, ShadingModel::Phong};
  return flipError(encodeSrgb8(RayTracer(traced).render(trace).image),
                   encodeSrgb8(renderer.renderToImage(scene, raster).image))
      .mean;
}

TEST_F(TraceEnvironment, GltfMaterialFeaturesAgreeWithTheRasteriser) {
  struct Case {
    const char* file;
    const char* feature;
    std::function<void(Material&)> undo;
  };
  const Case cases[] = {
      {"alpha_mask.gltf", "the mask", [](Material& m) { m.alphaCutoff = 0.0f; }},
      {"texture_transform.gltf", "the transforms",
       [](Material& m) { m.diffuseMap.transform = m.normalMap.transform = {}; }},
      {"texture_transform.gltf", "nearest magnification",
       [](Material& m) {
         m.diffuseMap.sampler.filter = m.normalMap.sampler.filter = TextureFilter::Bilinear;
       }},
      {"double_sided.gltf", "culling", [](Material& m) { m.doubleSided = true; }},
  };
  for (const Case& c : cases) {
    const double same = gltfFeatureFlip(renderer(), c.file, nullptr);
    const double undone = gltfFeatureFlip(renderer(), c.file, c.undo);
    std::printf("%s, raster Phong vs trace: mean FLIP %.4f; tracer without %s %.4f\n", c.file, same,
                c.feature, undone);
    EXPECT_LE(same, 0.02) << c.file;
    EXPECT_GT(undone, 2.0 * same + 0.005) << c.file << ": " << c.feature;
  }
}

// glTF BLEND covers the factor's alpha times the base colour texel's, in the
// rasteriser (TEXTURE_ALPHA) and the tracer alike (alpha_blend.gltf: a pane
// whose texture's alpha rises 0, 1/3, 2/3, 1 across it, at a factor of 0.8,
// before a blue wall). Must-fail twin: the trace of the pane with its
// texels made opaque against the same raster image.
// With an environment too: a BLEND surface is blended, not refracted by the
// environment term (which drew it opaque).
TEST_F(TraceEnvironment, GltfBlendCoversTheTexelsAlpha) {
  for (bool sky : {false, true}) {
    Scene scene = loadScene(std::string(SHADELAB_TEST_DATA_DIR) + "/alpha_blend.gltf");
    if (sky) scene.environment.kind = EnvironmentKind::Sky;
    TraceSettings trace;
    trace.width = 160, trace.height = 120, trace.samplesPerPixel = 1, trace.shadows = false;
    RenderSettings settings{trace.width, trace.height, ShadingModel::Phong};
    const ImageU8 raster = encodeSrgb8(renderer().renderToImage(scene, settings).image);
    const double same = flipError(encodeSrgb8(RayTracer(scene).render(trace).image), raster).mean;
    Scene opaque = scene;
    for (Texture& texture : opaque.textures)
      for (size_t a = 3; a < texture.rgba8.size(); a += 4) texture.rgba8[a] = 255;
    const double ignored =
        flipError(encodeSrgb8(RayTracer(opaque).render(trace).image), raster).mean;
    std::printf(
        "alpha_blend.gltf%s, raster Phong vs trace: mean FLIP %.4f; texels' alpha ignored %.4f\n",
        sky ? " under the sky" : "", same, ignored);
    EXPECT_LE(same, 0.02) << (sky ? "sky" : "no environment");
    EXPECT_GT(ignored, 2.0 * same + 0.005) << (sky ? "sky" : "no environment");
  }
}

// A glTF BLEND card's texels pass 1 - their coverage in the shadow maps, as
// the tracer's shadow rays do (shadow_pass.cpp), where they once cast the
// whole card and then cast where a texel covered half or more: a horizontal
// card at y = 1 whose texture is clear on one half and opaque on the other,
// under a near-vertical sun, over a floor seen from below the card (no view
// ray crosses it). On the floor under each half the rasteriser's hard
// shadow must be what the tracer's shadow ray finds, within 6 of 255: lit
// under the clear half, dark under the opaque one. Then texels of alpha 100
// and 160 (which the half threshold made lit and dark) and a card of
// transparency 0.5 (whose factor alpha the threshold left out): each half
// within 6 of the trace of the same scene, and between lit and dark.
TEST_F(TraceEnvironment, BlendedCardsPassWhatTheirTexelsLeaveUncovered) {
  Scene scene;
  scene.camera.eye = {0.0f, 0.5f, 4.0f};
  scene.camera.at = {0.0f, 0.0f, 0.0f};
  scene.ambient = glm::vec3(0.2f);
  scene.lights.push_back({LightType::Directional, {}, {0.05f, -1.0f, 0.03f}, glm::vec3(0.9f)});
  Texture halves;
  halves.name = "halves";
  halves.width = 2, halves.height = 1;
  halves.rgba8 = {200, 120, 40, 0, 200, 120, 40, 255};
  scene.textures.push_back(halves);
  Material card;
  card.alphaCoverage = true;
  card.diffuseMap.texture = 0;
  card.diffuseMap.sampler.filter = TextureFilter::Nearest;
  card.doubleSided = true;
  scene.objects.push_back(
      {"floor", scene.addShape({ShapeKind::Plane, 8.0f}), glm::mat4(1.0f), Material{}});
  scene.objects.push_back(
      {"card", scene.addShape({ShapeKind::Plane, 2.0f}), translation({0.0f, 1.0f, 0.0f}), card});
  const uint32_t width = 160, height = 120;
  RenderSettings settings{width, height, ShadingModel::Phong};
  settings.shadows = kDefaultShadowMethod;
  TraceSettings trace;
  trace.width = width, trace.height = height, trace.samplesPerPixel = 1, trace.shadows = true;
  const glm::mat4 toClip =
      scene.camera.projectionMatrix(float(width) / float(height)) * scene.camera.viewMatrix();
  auto green = [&](const ImageU8& image, glm::vec3 world) {
    glm::vec4 clip = toClip * glm::vec4(world, 1.0f);
    glm::vec2 ndc = glm::vec2(clip) / clip.w;
    auto x = uint32_t((ndc.x * 0.5f + 0.5f) * float(width));
    auto y = uint32_t((ndc.y * 0.5f + 0.5f) * float(height));
    return int(image.pixels[(size_t(y) * width + x) * 4 + 1]);
  };
  // The floor under each half, traced and rasterised, for texel alphas
  // `left` and `right` and the card's transparency.
  struct Halves {
    int traced[2], raster[2];
  };
  auto halvesOf = [&](uint8_t left, uint8_t right, float transparency) {
    Scene changed = scene;
    changed.textures[0].rgba8[3] = left;
    changed.textures[0].rgba8[7] = right;
    changed.objects[1].material.transparency = transparency;
    const ImageU8 raster = encodeSrgb8(renderer().renderToImage(changed, settings).image);
    const ImageU8 traced = encodeSrgb8(RayTracer(changed).render(trace).image);
    Halves halves{};
    for (int i = 0; i < 2; ++i) {
      const glm::vec3 floor(i == 0 ? -0.5f : 0.5f, 0.0f, 0.0f);
      halves.traced[i] = green(traced, floor);
      halves.raster[i] = green(raster, floor);
      std::printf(
          "texel alphas %d/%d, transparency %.1f, floor under the %s half: trace %d, "
          "raster %d\n",
          left, right, transparency, i == 0 ? "left" : "right", halves.traced[i], halves.raster[i]);
    }
    return halves;
  };
  const Halves clearAndOpaque = halvesOf(0, 255, 0.0f);
  const int lit = clearAndOpaque.traced[0], dark = clearAndOpaque.traced[1];
  ASSERT_GT(lit, dark + 40);  // the scene shows both cases
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(clearAndOpaque.raster[i], clearAndOpaque.traced[i], 6);
  for (const auto& [left, right, transparency] :
       {std::tuple<uint8_t, uint8_t, float>{100, 160, 0.0f}, {0, 255, 0.5f}}) {
    const Halves halves = halvesOf(left, right, transparency);
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR(halves.raster[i], halves.traced[i], 6) << int(left) << "/" << int(right);
      if (i == 1 || left > 0) {  // partly covered: between lit and dark
        EXPECT_GT(halves.traced[i], dark + 10);
        EXPECT_LT(halves.traced[i], lit - 10);
      }
    }
  }
}

// A checker floor, a mirror sphere and a dimpled (height-mapped) sphere
// under the procedural sky with its sun.
Scene texturedSkyScene() {
  Scene scene;
  scene.camera.eye = {0.0f, 1.6f, 5.0f};
  scene.camera.at = {0.0f, 0.6f, 0.0f};
  scene.ambient = glm::vec3(0.3f);
  scene.environment.kind = EnvironmentKind::Sky;
  scene.environment.sky.sunDirection = {0.5f, -0.6f, -0.6f};
  scene.lights.push_back({LightType::Directional, {}, {0.5f, -0.6f, -0.6f}, glm::vec3(0.9f)});
  scene.textures.push_back(heightColorTexture(proceduralHeight({HeightPattern::Checker, 64, 2}),
                                              glm::vec3(0.08f), glm::vec3(0.75f), "checker"));
  scene.textures.push_back(
      heightMapTexture(proceduralHeight({HeightPattern::Dimples, 64, 4}), "dimples"));
  Material floor;
  floor.diffuseMap.texture = 0;
  floor.uvScale = glm::vec2(4.0f);
  scene.objects.push_back(
      {"floor", scene.addShape({ShapeKind::Plane, 8.0f}), glm::mat4(1.0f), floor});
  const uint32_t sphere = scene.addShape({ShapeKind::UvSphere, 1.0f, {}, 0.6f});
  Material mirror;
  mirror.kd = glm::vec3(0.05f);
  mirror.reflectivity = 0.85f;
  scene.objects.push_back({"mirror", sphere, translation({-0.8f, 0.6f, 0.0f}), mirror});
  Material dimpled;
  dimpled.kd = {0.2f, 0.45f, 0.8f};
  dimpled.heightMap.texture = 1;
  dimpled.bumpScale = 3.0f;
  dimpled.uvScale = {4.0f, 2.0f};
  scene.objects.push_back({"dimpled", sphere, translation({0.8f, 0.6f, 0.4f}), dimpled});
  return scene;
}

ImageU8 traceSmall(const Scene& scene) {
  return encodeSrgb8(traceAt(scene, 160, 90, 4));
}

TEST(TraceTexturesGolden, TexturedSkySceneMatchesGolden) {
  EXPECT_TRUE(matchesGolden("trace-textured-sky", traceSmall(texturedSkyScene())));
}

// Must-fail twins: the floor untextured, the sky gone (misses and the
// mirror's reflections turn black), the dimples flat.
TEST(TraceTexturesGolden, ComparisonRejectsAnUntexturedFloor) {
  Scene scene = texturedSkyScene();
  scene.objects[0].material.diffuseMap.texture = -1;
  EXPECT_FALSE(matchesImage(loadGolden("trace-textured-sky"), traceSmall(scene)));
}

TEST(TraceTexturesGolden, ComparisonRejectsAMissingEnvironment) {
  Scene scene = texturedSkyScene();
  scene.environment.kind = EnvironmentKind::None;
  EXPECT_FALSE(matchesImage(loadGolden("trace-textured-sky"), traceSmall(scene)));
}

TEST(TraceTexturesGolden, ComparisonRejectsFlatDimples) {
  Scene scene = texturedSkyScene();
  scene.objects[2].material.heightMap.texture = -1;
  EXPECT_FALSE(matchesImage(loadGolden("trace-textured-sky"), traceSmall(scene)));
}

}  // namespace
}  // namespace shadelab::test
