// Loaded and generated scenes on the device: every shared model renders;
// frustum culling drops draws without changing a pixel; translucent objects
// blend back to front whatever order they are listed in; and the table of
// what --simplify and --tess auto keep and what that costs in image error.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "core/metrics/metrics.h"
#include "core/scene/lod.h"
#include "core/scene/mesh.h"
#include "core/scene/scene_loader.h"
#include "core/scene/shape.h"
#include "core/scene/transform.h"
#include "gpu_test_support.h"
#include "shared_assets.h"

namespace shadelab::test {
namespace {

uint64_t pixelsUnlike(const ImageU8& image, glm::u8vec4 colour) {
  uint64_t count = 0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) count += image.at(x, y) != colour;
  return count;
}

using GltfRender = GpuTest;

// Every scene in every model with shadows, drawn with `memory`'s settings
// and with `compiled`'s switch on: no linear value more than one RGBA16F
// step apart, the 8-bit images the same.
void expectOneHalfStepApart(Renderer& renderer, const std::vector<Scene>& scenes,
                            void (*compiled)(RenderSettings&, bool)) {
  for (const Scene& scene : scenes)
    for (int model = 0; model < kShadingModelCount; ++model) {
      RenderSettings on{160, 90, ShadingModel(model)};
      on.shadows = ShadowMethod::Hard;
      RenderSettings off = on;
      compiled(on, true);
      compiled(off, false);
      ImageRgba a = renderer.renderToImage(scene, on).image;
      ImageRgba b = renderer.renderToImage(scene, off).image;
      std::string what = scene.name + " " + std::string(shadingModelName(ShadingModel(model)));
      EXPECT_EQ(valuesBeyondOneHalfStep(a.pixels, b.pixels), 0u) << what;
      EXPECT_EQ(compareImages(encodeSrgb8(a), encodeSrgb8(b)).maxDifference, 0) << what;
    }
}

TEST_F(GltfRender, EverySharedModelRendersInView) {
  std::vector<std::filesystem::path> models = sharedModels();
  if (models.empty()) GTEST_SKIP() << "no models in " << sharedAssetsDir();
  for (const std::filesystem::path& model : models) {
    Scene scene = loadScene(model.string());
    RenderResult result = renderer().renderToImage(scene, {160, 90, ShadingModel::Phong});
    ImageU8 image = encodeSrgb8(result.image);
    // The framed model covers a good part of the frame and nothing is culled.
    EXPECT_GT(pixelsUnlike(image, image.at(0, 0)), 160u * 90u / 50u) << model;
    EXPECT_EQ(result.stats.culledDraws, 0u) << model;
    EXPECT_EQ(result.stats.triangles, scene.triangleCount()) << model;
  }
}

// Goldens of loaded scenes: the material mapping, the hierarchy and the
// framing all show in them. Must-fail twins change one of those a little.
Scene sharedModel(const std::string& file) {
  return loadScene((sharedAssetsDir() / "models" / file).string());
}

TEST_F(GltfRender, SharedModelsMatchGoldens) {
  if (!std::filesystem::exists(sharedAssetsDir() / "models"))
    GTEST_SKIP() << "no models in " << sharedAssetsDir();
  RenderSettings settings{320, 180, ShadingModel::Phong};
  EXPECT_TRUE(matchesGolden("gltf-suzanne", render(sharedModel("suzanne.gltf"), settings)));
  EXPECT_TRUE(matchesGolden("gltf-color-teapot-spheres",
                            render(sharedModel("color_teapot_spheres.gltf"), settings)));
}

TEST_F(GltfRender, ComparisonRejectsADarkerMaterialOrAMovedNode) {
  if (!std::filesystem::exists(sharedAssetsDir() / "models"))
    GTEST_SKIP() << "no models in " << sharedAssetsDir();
  RenderSettings settings{320, 180, ShadingModel::Phong};
  Scene metallic = sharedModel("suzanne.gltf");
  metallic.objects[0].material.kd *= 0.8f;  // as metallic 0.2 would give
  EXPECT_FALSE(matchesImage(loadGolden("gltf-suzanne"), render(metallic, settings)));
  Scene moved = sharedModel("color_teapot_spheres.gltf");
  moved.objects[0].transform = translation({0.0f, 1.0f, 0.0f}) * moved.objects[0].transform;
  EXPECT_FALSE(matchesImage(loadGolden("gltf-color-teapot-spheres"), render(moved, settings)));
}

TEST_F(GltfRender, GltfPlacedInASceneFileMatchesGolden) {
  std::string path = std::string(SHADELAB_TEST_DATA_DIR) + "/gltf_in_scene.json";
  RenderSettings settings{320, 180, ShadingModel::Phong};
  EXPECT_TRUE(matchesGolden("gltf-in-scene", render(loadScene(path), settings)));
  Scene shifted = loadScene(path);
  for (size_t i = 1; i < shifted.objects.size(); ++i)  // the glTF's, not the floor
    shifted.objects[i].transform = translation({0.1f, 0.0f, 0.0f}) * shifted.objects[i].transform;
  EXPECT_FALSE(matchesImage(loadGolden("gltf-in-scene"), render(shifted, settings)));
}

// The 2x2 texture (red, green / blue, white) on the quad, its first row at
// the top as glTF's uv (0, 0) is the image's first texel; the twin samples
// it upside down.
TEST_F(GltfRender, TextureAppearsTheWayUpGltfMeans) {
  std::string path = std::string(SHADELAB_TEST_DATA_DIR) + "/textured.gltf";
  Scene scene = loadScene(path);
  scene.objects[0].material.transparency = 0.0f;  // the texture's own colours
  RenderSettings settings{160, 120, ShadingModel::Unlit};
  ImageU8 image = render(scene, settings);
  EXPECT_TRUE(matchesGolden("gltf-textured", image));
  for (Vertex& vertex : scene.meshes[0].vertices) vertex.uv.y = 1.0f - vertex.uv.y;
  EXPECT_FALSE(matchesImage(loadGolden("gltf-textured"), render(scene, settings)));
}

// Materials compiled into their pipelines (the default) against materials
// read from push constants: in every model, with textures, environment,
// shadows, transparency and a glTF model's materials. Compiled-in constants
// let the JIT fold and round differently, so a few linear values differ by
// one RGBA16F step (measured: 1 value of shadows/Blinn-Phong, 10 of the
// glTF model's Gouraud); none differs by more, and the 8-bit image is the
// same. The twin: the same check sees a material 1% darker.
TEST_F(GltfRender, MaterialConstantsChangeNoMoreThanOneHalfStep) {
  std::vector<Scene> scenes;
  for (const char* name : {"default", "bump", "env", "shadows", "whitted"})
    scenes.push_back(builtinScene(name));
  if (std::filesystem::exists(sharedAssetsDir() / "models"))
    scenes.push_back(sharedModel("color_teapot_spheres.gltf"));
  expectOneHalfStepApart(renderer(), scenes, [](RenderSettings& settings, bool on) {
    settings.materialConstants = on;
  });
  Scene darker = builtinScene("default");
  darker.objects[1].material.kd *= 0.99f;
  RenderSettings settings{160, 90, ShadingModel::Phong};
  EXPECT_GT(valuesBeyondOneHalfStep(
                renderer().renderToImage(builtinScene("default"), settings).image.pixels,
                renderer().renderToImage(darker, settings).image.pixels),
            100u);
}

// The frame's lights compiled into the pipelines (FrameSettings::
// lightConstants) against lights read from the frame's uniform block: every
// model, with textures, shadows, billboards and a scene of
// three point lights (one attenuated) and two directional ones. As with the
// materials, folded constants may round differently by one RGBA16F step and
// the 8-bit image is the same. Twins: the check sees one light 1% dimmer;
// and a camera path with lightConstants, whose lights move in eye space from
// the second frame on, falls back to reading them (each frame the same as
// without constants, not the first frame's lights compiled into the next).
TEST_F(GltfRender, LightConstantsChangeNoMoreThanOneHalfStep) {
  std::vector<Scene> scenes;
  for (const char* name : {"default", "bump", "shadows", "trees"})
    scenes.push_back(builtinScene(name));
  Scene lights = builtinScene("default");
  lights.name = "default, five lights";
  Light point;
  point.position = {-3.0f, 2.0f, 1.0f};
  point.intensity = {0.4f, 0.3f, 0.2f};
  point.attenuation = {1.0f, 0.1f, 0.02f};
  lights.lights.push_back(point);
  point.position = {2.0f, 4.0f, -2.0f};
  point.attenuation = {1.0f, 0.0f, 0.0f};
  lights.lights.push_back(point);
  Light directional;
  directional.type = LightType::Directional;
  directional.direction = {0.3f, -1.0f, -0.2f};
  directional.intensity = glm::vec3(0.25f);
  lights.lights.push_back(directional);
  directional.direction = {-0.5f, -0.2f, 0.4f};
  lights.lights.push_back(directional);
  scenes.push_back(lights);
  expectOneHalfStepApart(renderer(), scenes,
                         [](RenderSettings& settings, bool on) { settings.lightConstants = on; });
  RenderSettings settings{160, 90, ShadingModel::Phong};
  settings.lightConstants = true;
  Scene dimmer = lights;
  dimmer.lights[1].intensity *= 0.99f;
  EXPECT_GT(valuesBeyondOneHalfStep(renderer().renderToImage(lights, settings).image.pixels,
                                    renderer().renderToImage(dimmer, settings).image.pixels),
            100u);

  std::vector<Camera> path(3, lights.camera);
  path[1].eye += glm::vec3(1.5f, 0.5f, 0.0f);
  path[2].eye -= glm::vec3(1.0f, 0.0f, 1.0f);
  std::vector<ImageRgba> withConstants(path.size()), without(path.size());
  renderer().renderSequence(lights, settings, path,
                            [&](uint32_t i, ImageRgba&& image) { withConstants[i] = image; });
  RenderSettings reading = settings;
  reading.lightConstants = false;
  renderer().renderSequence(lights, reading, path,
                            [&](uint32_t i, ImageRgba&& image) { without[i] = image; });
  for (size_t i = 0; i < path.size(); ++i)
    EXPECT_EQ(valuesBeyondOneHalfStep(withConstants[i].pixels, without[i].pixels), 0u)
        << "camera " << i;
}

// The default scene with a ring of 24 spheres around the camera: those
// behind it and off to the sides are culled. With culling on the image is
// the same to the bit and fewer draws are made.
TEST_F(GltfRender, CullingChangesNoPixelButReducesDraws) {
  Scene scene = builtinScene("default");
  ShapeDesc ball;
  ball.kind = ShapeKind::UvSphere;
  ball.radius = 0.4f;
  uint32_t mesh = scene.addShape(ball);
  for (int i = 0; i < 24; ++i) {
    glm::mat4 place = translation(scene.camera.eye) * rotationY(glm::radians(15.0f * float(i))) *
                      translation({0.0f, 0.0f, -3.0f});
    scene.objects.push_back({"ring", mesh, place, Material{}});
  }
  RenderSettings culling{320, 180, ShadingModel::Phong};
  RenderSettings everything = culling;
  everything.frustumCulling = false;
  RenderResult culled = renderer().renderToImage(scene, culling);
  RenderResult all = renderer().renderToImage(scene, everything);
  EXPECT_EQ(compareImages(encodeSrgb8(culled.image), encodeSrgb8(all.image)).maxDifference, 0);
  EXPECT_EQ(all.stats.drawCalls, scene.objects.size());
  EXPECT_EQ(all.stats.culledDraws, 0u);
  // 45 degrees of vertical view at 16:9 sees about 70 degrees across: 5 of
  // the 24 spheres 15 degrees apart, each partly, and none of the rest.
  EXPECT_GE(culled.stats.culledDraws, 17u);
  EXPECT_LE(culled.stats.culledDraws, 20u);
  EXPECT_EQ(culled.stats.drawCalls + culled.stats.culledDraws, scene.objects.size());
  EXPECT_LT(culled.stats.triangles, all.stats.triangles);
  // Reversed-Z swaps the near and far planes' depths; the planes still bound
  // the same volume, so the same draws are culled.
  culling.depth = everything.depth = DepthMode::ReversedZ;
  RenderResult reversedCulled = renderer().renderToImage(scene, culling);
  RenderResult reversedAll = renderer().renderToImage(scene, everything);
  EXPECT_EQ(compareImages(encodeSrgb8(reversedCulled.image), encodeSrgb8(reversedAll.image))
                .maxDifference,
            0);
  EXPECT_EQ(reversedCulled.stats.culledDraws, culled.stats.culledDraws);
}

// Three overlapping translucent quads (red nearest, then green, then blue)
// over an opaque white one.
Scene translucentQuads(const std::vector<int>& order) {
  Scene scene;
  scene.name = "translucent";
  scene.camera.eye = {0.0f, 0.0f, 6.0f};
  scene.background = glm::vec3(0.1f);
  scene.ambient = glm::vec3(1.0f);
  Light light;
  light.type = LightType::Directional;
  light.direction = {0.0f, 0.0f, -1.0f};
  scene.lights.push_back(light);
  uint32_t quad = scene.addMesh(makePlane(2.0f, 1));
  glm::mat4 facing = rotationX(glm::radians(90.0f));  // the plane's +y normal to +z
  const glm::vec3 colours[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Material white;
  white.kd = white.ka = glm::vec3(0.8f);
  white.ks = glm::vec3(0.0f);
  scene.objects.push_back(
      {"back", quad, translation({0, 0, -3}) * scaling(glm::vec3(2)) * facing, white});
  for (int i : order) {
    Material material;
    material.kd = colours[i];
    material.ka = 0.2f * colours[i];
    material.ks = glm::vec3(0.0f);
    material.transparency = 0.5f;
    glm::vec3 offset(0.5f * float(i) - 0.5f, 0.3f * float(i) - 0.3f, -float(i));
    scene.objects.push_back({"quad", quad, translation(offset) * facing, material});
  }
  return scene;
}

TEST_F(GltfRender, TranslucentObjectsBlendBackToFrontInAnyListedOrder) {
  std::vector<int> order = {0, 1, 2};
  ImageU8 first = render(translucentQuads(order), {320, 180, ShadingModel::Phong});
  EXPECT_TRUE(matchesGolden("translucent-quads", first));
  int permutations = 0;
  while (std::next_permutation(order.begin(), order.end())) {
    ImageU8 image = render(translucentQuads(order), {320, 180, ShadingModel::Phong});
    EXPECT_EQ(compareImages(first, image).maxDifference, 0) << order[0] << order[1] << order[2];
    ++permutations;
  }
  EXPECT_EQ(permutations, 5);
}

// Must-fail twin: the same quads with red and blue swapped in depth blend
// to different colours where they overlap, and the golden rejects them.
TEST_F(GltfRender, ComparisonRejectsLayersInAnotherDepthOrder) {
  Scene scene = translucentQuads({0, 1, 2});
  std::swap(scene.objects[1].material, scene.objects[3].material);
  EXPECT_FALSE(matchesImage(loadGolden("translucent-quads"),
                            render(scene, {320, 180, ShadingModel::Phong})));
}

struct LodRow {
  std::string scene;
  uint64_t before = 0, after = 0;
  ImageDifference difference;
};

void printTable(const std::string& title, const std::vector<LodRow>& rows) {
  std::printf("%s\n%-24s %10s %10s %7s %9s %9s\n", title.c_str(), "scene", "triangles", "kept",
              "kept%", "PSNR dB", "max err");
  std::ofstream csv(testOutputDir() + "/lod_table.csv", std::ios::app);
  for (const LodRow& row : rows) {
    double percent = 100.0 * double(row.after) / double(std::max<uint64_t>(row.before, 1));
    std::printf("%-24s %10llu %10llu %6.1f%% %9.2f %9d\n", row.scene.c_str(),
                static_cast<unsigned long long>(row.before),
                static_cast<unsigned long long>(row.after), percent, row.difference.psnr,
                row.difference.maxDifference);
    csv << title << ',' << row.scene << ',' << row.before << ',' << row.after << ','
        << row.difference.psnr << ',' << row.difference.maxDifference << '\n';
  }
}

constexpr uint32_t kLodWidth = 640, kLodHeight = 360;
constexpr float kLodErrorPixels = 0.5f;

// --simplify 0.5 on every shared model at 640x360 against its unsimplified
// render. The bound is on geometry, not shading, so the image error is
// measured, and held to a floor that catches a broken conversion.
TEST_F(GltfRender, SimplificationTableForTheSharedModels) {
  std::vector<std::filesystem::path> models = sharedModels();
  if (models.empty()) GTEST_SKIP() << "no models in " << sharedAssetsDir();
  RenderSettings settings{kLodWidth, kLodHeight, ShadingModel::Phong};
  std::vector<LodRow> rows;
  for (const std::filesystem::path& model : models) {
    Scene full = loadScene(model.string());
    Scene simplified = full;
    SimplifyStats stats =
        simplifyForView(simplified, {full.camera, kLodWidth, kLodHeight}, kLodErrorPixels);
    LodRow row{model.filename().string(), full.triangleCount(), simplified.triangleCount(), {}};
    row.difference = compareImages(render(full, settings), render(simplified, settings));
    rows.push_back(row);
    EXPECT_LE(stats.trianglesAfter, stats.trianglesBefore) << model;
    EXPECT_GT(row.difference.psnr, 30.0) << model;
  }
  printTable("--simplify 0.5 px at 640x360, against the unsimplified mesh", rows);
  uint64_t before = 0, after = 0;
  for (const LodRow& row : rows) before += row.before, after += row.after;
  EXPECT_LT(after, before / 2);  // the point of it: most triangles are not needed
}

// --tess auto at 0.5 px against the same scene at 4x its base tessellation.
TEST_F(GltfRender, AutoTessellationTableForTheBuiltinScenes) {
  RenderSettings settings{kLodWidth, kLodHeight, ShadingModel::Phong};
  std::vector<LodRow> rows;
  for (const char* name : {"default", "spheres", "teapot"}) {
    Scene reference = builtinScene(name);
    reference.retessellate(4.0f);
    Scene automatic = builtinScene(name);
    tessellateForView(automatic, {automatic.camera, kLodWidth, kLodHeight}, kLodErrorPixels);
    LodRow row{name, reference.triangleCount(), automatic.triangleCount(), {}};
    row.difference = compareImages(render(reference, settings), render(automatic, settings));
    rows.push_back(row);
    EXPECT_GT(row.difference.psnr, 35.0) << name;
  }
  printTable("--tess auto 0.5 px at 640x360, against 4x the base tessellation", rows);
}

// --lod auto on a row of finely tessellated balls (custom meshes, as loaded
// ones are) going into the distance: far fewer triangles, and the image
// within a mean FLIP of 0.01 of the full meshes at the 0.5 px bound. The
// must-fail side: a 40 px bound takes coarse levels the metric does see.
TEST_F(GltfRender, LevelsOfDetailDrawFewerTrianglesWithinTheBound) {
  Scene scene;
  scene.camera.eye = glm::vec3(0.0f, 1.5f, 6.0f);
  scene.camera.at = glm::vec3(0.0f, 0.5f, -10.0f);
  scene.lights.push_back(Light{});
  scene.lights.back().type = LightType::Directional;
  scene.lights.back().direction = glm::vec3(-1.0f, -2.0f, -1.5f);
  uint32_t ball = scene.addMesh(makeUvSphere(1.0f, 128, 64));
  for (int i = 0; i < 6; ++i) {
    Material material;
    material.kd = glm::vec3(0.8f, 0.3f + 0.1f * float(i), 0.2f);
    material.ks = glm::vec3(0.5f);
    material.shininess = 40.0f;
    glm::mat4 transform = translation(glm::vec3(i % 2 ? 1.5f : -1.5f, 0.0f, -6.0f * float(i)));
    scene.objects.push_back({"ball " + std::to_string(i), ball, transform, material});
  }
  auto draw = [&](bool lod, float bound, RenderStats* stats) {
    RenderSettings settings{640, 360, ShadingModel::Phong};
    settings.lod = lod;
    settings.lodErrorPixels = bound;
    RenderResult result = renderer().renderToImage(scene, settings);
    if (stats) *stats = result.stats;
    return encodeSrgb8(result.image);
  };
  RenderStats full, fine, coarse;
  ImageU8 reference = draw(false, 0.5f, &full);
  ImageU8 atHalfPixel = draw(true, 0.5f, &fine);
  ImageU8 atFortyPixels = draw(true, 40.0f, &coarse);
  EXPECT_EQ(full.coarserDraws, 0u);
  EXPECT_EQ(full.triangles, scene.triangleCount());
  EXPECT_GE(fine.coarserDraws, 4u);  // the nearest one or two stay whole
  EXPECT_LT(fine.triangles * 3, full.triangles);
  EXPECT_LT(coarse.triangles, fine.triangles);
  double fineError = flipError(reference, atHalfPixel).mean;
  double coarseError = flipError(reference, atFortyPixels).mean;
  std::printf("lod: %llu -> %llu triangles at 0.5 px (mean FLIP %.4f), %llu at 40 px (%.4f)\n",
              static_cast<unsigned long long>(full.triangles),
              static_cast<unsigned long long>(fine.triangles), fineError,
              static_cast<unsigned long long>(coarse.triangles), coarseError);
  EXPECT_LT(fineError, 0.01);
  EXPECT_GT(coarseError, 2.0 * fineError);
  // Drawing the same frame again (the levels drawn last time as the
  // hysteresis' start) changes nothing in a still view.
  EXPECT_EQ(draw(true, 0.5f, nullptr).pixels, atHalfPixel.pixels);
}

// The same for procedural shapes, whose levels are the shape rebuilt at
// half the tessellation each time: spheres and teapots in a row, with
// shadows, which the casters must cast at the level drawn (a coarser sphere
// lies inside the full one: shadowed by the full caster, it went dark).
TEST_F(GltfRender, ProceduralLevelsOfDetailStayWithinTheBound) {
  Scene scene;
  scene.camera.eye = glm::vec3(0.0f, 1.5f, 6.0f);
  scene.camera.at = glm::vec3(0.0f, 0.5f, -10.0f);
  scene.lights.push_back(Light{});
  scene.lights.back().position = glm::vec3(2.0f, 6.0f, 4.0f);
  uint32_t sphere =
      scene.addShape({.kind = ShapeKind::UvSphere, .radius = 1.0f, .tessellation = 128});
  uint32_t teapot = scene.addShape({.kind = ShapeKind::Teapot, .tessellation = 16});
  for (int i = 0; i < 6; ++i) {
    Material material;
    material.kd = glm::vec3(0.3f, 0.5f, 0.8f);
    material.ks = glm::vec3(0.6f);
    material.shininess = 60.0f;
    glm::mat4 transform = translation(glm::vec3(i % 2 ? 1.5f : -1.5f, 0.0f, -6.0f * float(i)));
    if (i % 2) transform = transform * scaling(glm::vec3(0.5f));
    scene.objects.push_back(
        {"shape " + std::to_string(i), i % 2 ? teapot : sphere, transform, material});
  }
  auto draw = [&](bool lod, float bound, RenderStats& stats) {
    RenderSettings settings{640, 360, ShadingModel::Phong};
    settings.shadows = ShadowMethod::Hard;
    settings.lod = lod;
    settings.lodErrorPixels = bound;
    RenderResult result = renderer().renderToImage(scene, settings);
    stats = result.stats;
    return encodeSrgb8(result.image);
  };
  RenderStats full, fine, coarse;
  ImageU8 reference = draw(false, 0.5f, full);
  ImageU8 atHalfPixel = draw(true, 0.5f, fine);
  ImageU8 atFortyPixels = draw(true, 40.0f, coarse);
  EXPECT_EQ(full.triangles, scene.triangleCount());
  EXPECT_GE(fine.coarserDraws, 4u);
  EXPECT_LT(fine.triangles * 2, full.triangles);
  double fineError = flipError(reference, atHalfPixel).mean;
  double coarseError = flipError(reference, atFortyPixels).mean;
  std::printf(
      "procedural lod: %llu -> %llu triangles at 0.5 px (mean FLIP %.4f), %llu at 40 px "
      "(%.4f)\n",
      static_cast<unsigned long long>(full.triangles),
      static_cast<unsigned long long>(fine.triangles), fineError,
      static_cast<unsigned long long>(coarse.triangles), coarseError);
  EXPECT_LT(fineError, 0.01);
  EXPECT_GT(coarseError, 2.0 * fineError);
  // Measured: 0.0646 at 40 px; with the full meshes as casters 0.0936 (and
  // 0.0063 rather than 0.0041 at 0.5 px).
  EXPECT_LT(coarseError, 0.08);
}

}  // namespace
}  // namespace shadelab::test
