// Impostors on the device: the captured atlas of a sphere (each cell sees a
// disc whose normals face the viewer at its centre), a golden of a teapot
// drawn as its impostor with a must-fail twin, the impostor within its bound
// of the full mesh in the built-in lod scene, and the parallax measurement
// against the bound it is ranked by.
#include <cmath>

#include "core/metrics/metrics.h"
#include "core/scene/impostor.h"
#include "core/scene/scene_json.h"
#include "core/scene/transform.h"
#include "gpu_test_support.h"
#include "measure/impostor_parallax.h"

namespace shadelab::test {
namespace {

constexpr uint32_t kWidth = 320;
constexpr uint32_t kHeight = 240;

Scene impostorScene() {
  return loadSceneJson(std::string(SHADELAB_TEST_DATA_DIR) + "/impostor.json");
}

// The teapot as its impostor: a bound far above the impostor's error.
RenderSettings impostorSettings() {
  RenderSettings settings{kWidth, kHeight, ShadingModel::Phong};
  settings.lod = true;
  settings.lodErrorPixels = 100.0f;
  return settings;
}

using ImpostorTest = GpuTest;

TEST_F(ImpostorTest, SphereAtlasSeesAFacingDiscInEveryCell) {
  Scene scene;
  ShapeDesc sphere;
  sphere.kind = ShapeKind::UvSphere;
  sphere.radius = 1.0f;
  sphere.tessellation = 48;
  Object object;
  object.mesh = scene.addShape(sphere);
  scene.objects.push_back(object);
  GpuScene gpu = renderer().upload(scene, {.environmentCube = false, .detailChains = true});
  ASSERT_EQ(gpu.impostorTextures.size(), 2u);
  ASSERT_EQ(gpu.impostorDraws, 1u);
  const Texture& coverage = gpu.impostorTextures[0];
  const Texture& normals = gpu.impostorTextures[1];
  const uint32_t cells = kImpostorCells, texels = kImpostorCellTexels;
  ASSERT_EQ(coverage.width, cells * texels);
  // The disc's radius in texels: the sphere's radius over the cell's half size.
  double discRadius = 0.5 * texels / impostorHalfSize(1.0f, texels);
  for (uint32_t row = 0; row < cells; ++row)
    for (uint32_t column = 0; column < cells; ++column) {
      SCOPED_TRACE(testing::Message() << "cell " << column << "," << row);
      uint32_t covered = 0;
      for (uint32_t y = 0; y < texels; ++y)
        for (uint32_t x = 0; x < texels; ++x)
          covered +=
              coverage
                  .rgba8[4 * ((size_t(row * texels + y) * coverage.width) + column * texels + x) +
                         3] == 255;
      double area = M_PI * discRadius * discRadius;
      // The captured level may lie up to half a texel inside the sphere (7% of
      // the disc's area at 14 texels of radius).
      EXPECT_NEAR(double(covered), area, 0.12 * area);
      // At the centre the sphere faces the viewer: normal (0, 0, 1), and its
      // height above the quad is the radius, less the chord error of the
      // level captured (up to half a texel: 254 / 2 / 32 codes), plus rounding.
      size_t centre =
          4 * ((size_t(row * texels + texels / 2) * normals.width) + column * texels + texels / 2);
      EXPECT_NEAR(normals.rgba8[centre + 0], 128, 8);
      EXPECT_NEAR(normals.rgba8[centre + 1], 128, 8);
      EXPECT_GE(normals.rgba8[centre + 2], 250);
      double height = 1.0 / impostorHalfSize(1.0f, texels);
      double halfTexel = 1.0 / texels;  // a texel is 2 halfSize / texels
      EXPECT_NEAR(normals.rgba8[centre + 3], 1.0 + 254.0 * (0.5 + 0.5 * (height - halfTexel)),
                  254.0 * 0.5 * halfTexel + 2.0);
      // The corners of a cell are its margin: nothing covers them.
      EXPECT_EQ(coverage.rgba8[4 * ((size_t(row * texels) * coverage.width) + column * texels) + 3],
                0);
    }
}

// Many distinct meshes: the first kMaxImpostorAtlases get an atlas each,
// the others keep chains that end in meshes.
TEST_F(ImpostorTest, AtlasesStopAtTheLimit) {
  Scene scene;
  for (size_t i = 0; i < kMaxImpostorAtlases + 6; ++i) {
    ShapeDesc sphere;
    sphere.kind = ShapeKind::UvSphere;
    sphere.radius = 0.5f + 0.01f * float(i);  // each its own mesh
    sphere.tessellation = 8;
    Object object;
    object.mesh = scene.addShape(sphere);
    object.transform = translation(glm::vec3(float(i), 0.0f, 0.0f));
    scene.objects.push_back(object);
  }
  GpuScene gpu = renderer().upload(scene, {.environmentCube = false, .detailChains = true});
  EXPECT_EQ(gpu.impostorTextures.size(), 2 * kMaxImpostorAtlases);
  EXPECT_EQ(gpu.impostorDraws, kMaxImpostorAtlases);
  for (size_t i = 0; i < gpu.draws.size(); ++i) {
    const DrawItem& draw = gpu.draws[i];
    ASSERT_GT(draw.levelCount, 0u);
    bool impostor =
        gpu.levels[draw.firstLevel + draw.levelCount - 1].impostor != DrawLevel::kNoImpostor;
    EXPECT_EQ(impostor, i < kMaxImpostorAtlases) << "object " << i;
  }
}

// Hostile sizes: a mesh shrunk towards zero or grown towards the float
// limit has a radius of 0 or infinity (impostorRadiusUsable) and keeps a
// chain of meshes (without the check the capture divides by 0), and the scene still draws
// (no validation message, no crash) with the one sphere of ordinary size as its impostor.
TEST_F(ImpostorTest, MeshesTooSmallOrTooLargeKeepTheirMeshChains) {
  Scene scene;
  const float radii[] = {1e-35f, 1.0f, 1e35f};
  for (float radius : radii) {
    ShapeDesc sphere;
    sphere.kind = ShapeKind::UvSphere;
    sphere.radius = radius;
    sphere.tessellation = 16;
    Object object;
    object.mesh = scene.addShape(sphere);
    scene.objects.push_back(object);
  }
  EXPECT_FALSE(impostorRadiusUsable(std::nanf("")));
  GpuScene gpu = renderer().upload(scene, {.environmentCube = false, .detailChains = true});
  EXPECT_EQ(gpu.impostorDraws, 1u);
  EXPECT_EQ(gpu.impostorTextures.size(), 2u);
  for (const DrawItem& draw : gpu.draws) {
    ASSERT_GT(draw.levelCount, 0u);
    bool impostor =
        gpu.levels[draw.firstLevel + draw.levelCount - 1].impostor != DrawLevel::kNoImpostor;
    EXPECT_EQ(impostor, draw.constants.object.x == 1);
  }
  RenderSettings settings = impostorSettings();
  scene.camera.eye = glm::vec3(0.0f, 0.0f, 40.0f);
  scene.camera.far = 1000.0f;
  RenderResult result = renderer().renderToImage(scene, settings);
  EXPECT_EQ(result.stats.impostors, 1u);
}

// Only a rotation and one positive scale keep their impostor: a mirroring
// transform would need the atlas's images reversed (and its mesh is wound
// for the mirror), and the blend turns and scales its quad by one rotation
// and one scale. The others end their chain in the coarsest mesh.
TEST_F(ImpostorTest, OnlyTurnedAndEvenlyScaledObjectsGetImpostors) {
  glm::mat4 turned = rotationY(glm::radians(30.0f));
  EXPECT_TRUE(impostorTransformUsable(turned));
  EXPECT_TRUE(impostorTransformUsable(turned * scaling(glm::vec3(2.5f))));
  EXPECT_FALSE(impostorTransformUsable(turned * scaling(glm::vec3(-1.0f, 1.0f, 1.0f))));
  EXPECT_FALSE(impostorTransformUsable(turned * scaling(glm::vec3(1.8f, 0.7f, 1.0f))));
  glm::mat4 sheared(1.0f);
  sheared[1][0] = 0.5f;
  EXPECT_FALSE(impostorTransformUsable(sheared));
  EXPECT_FALSE(impostorTransformUsable(scaling(glm::vec3(0.0f))));
  EXPECT_FALSE(impostorTransformUsable(scaling(glm::vec3(std::nanf("")))));
  for (bool blend : {false, true}) {
    RenderSettings settings = impostorSettings();
    settings.impostorBlend = blend;
    const std::pair<glm::mat4, uint32_t> cases[] = {
        {turned * scaling(glm::vec3(1.2f)), 1u},
        {scaling(glm::vec3(-1.0f, 1.0f, 1.0f)) * turned, 0u},
        {turned * scaling(glm::vec3(1.8f, 0.7f, 1.0f)), 0u}};
    for (const auto& [transform, impostors] : cases) {
      Scene scene = impostorScene();
      scene.objects[1].transform = transform;
      RenderResult result = renderer().renderToImage(scene, settings);
      EXPECT_EQ(result.stats.impostors, impostors) << "blend " << blend;
      EXPECT_EQ(result.stats.coarserDraws, 1u) << "blend " << blend;
    }
  }
}

TEST_F(ImpostorTest, TeapotImpostorMatchesGolden) {
  RenderResult result = renderer().renderToImage(impostorScene(), impostorSettings());
  EXPECT_EQ(result.stats.impostors, 1u);
  EXPECT_TRUE(matchesGolden("impostor-teapot", encodeSrgb8(result.image)));
}

// Must-fail twin: the teapot turned by 70 degrees is drawn from other cells
// of the same atlas; the golden must reject it (as it would a cell chosen
// for the wrong direction).
TEST_F(ImpostorTest, GoldenRejectsTheTeapotSeenFromAnotherCell) {
  Scene scene = impostorScene();
  scene.objects[1].transform = rotationY(glm::radians(70.0f));
  RenderResult result = renderer().renderToImage(scene, impostorSettings());
  EXPECT_EQ(result.stats.impostors, 1u);
  EXPECT_FALSE(matchesImage(loadGolden("impostor-teapot"), encodeSrgb8(result.image)));
}

// --impostors blend: a golden of the teapot drawn from its three blended
// cells, and its must-fail twin: the same view from the nearest cell alone
// (the default's image) is rejected by it.
TEST_F(ImpostorTest, BlendedTeapotImpostorMatchesGolden) {
  RenderSettings settings = impostorSettings();
  settings.impostorBlend = true;
  RenderResult result = renderer().renderToImage(impostorScene(), settings);
  EXPECT_EQ(result.stats.impostors, 1u);
  EXPECT_TRUE(matchesGolden("impostor-teapot-blend", encodeSrgb8(result.image)));
}

TEST_F(ImpostorTest, GoldenOfTheBlendRejectsTheNearestCell) {
  RenderResult result = renderer().renderToImage(impostorScene(), impostorSettings());
  EXPECT_EQ(result.stats.impostors, 1u);
  EXPECT_FALSE(matchesImage(loadGolden("impostor-teapot-blend"), encodeSrgb8(result.image)));
}

// What the blend is for: the camera orbits the teapot in half-degree steps
// across cell boundaries. From the nearest cell the image jumps where the
// cell changes; blended it turns smoothly. Measured: the largest RMSE
// between consecutive frames, each way.
TEST_F(ImpostorTest, BlendTurnsWithoutJumpsAtCellBoundaries) {
  Scene scene = impostorScene();
  std::vector<Camera> cameras;
  for (int step = 0; step <= 48; ++step) {
    Camera camera = scene.camera;
    float azimuth = glm::radians(0.5f * float(step));
    glm::vec3 offset = camera.eye - camera.at;
    camera.eye =
        camera.at + glm::vec3(offset.x * std::cos(azimuth) + offset.z * std::sin(azimuth), offset.y,
                              -offset.x * std::sin(azimuth) + offset.z * std::cos(azimuth));
    cameras.push_back(camera);
  }
  auto largestStep = [&](bool blend) {
    RenderSettings settings = impostorSettings();
    settings.impostorBlend = blend;
    ImageU8 previous;
    double largest = 0.0;
    RenderStats stats =
        renderer().renderSequence(scene, settings, cameras, [&](uint32_t index, ImageRgba&& image) {
          ImageU8 frame = encodeSrgb8(image);
          if (index > 0) largest = std::max(largest, compareImages(previous, frame).rmse);
          previous = std::move(frame);
        });
    EXPECT_EQ(stats.impostors, 1u);
    return largest;
  };
  double nearest = largestStep(false), blended = largestStep(true);
  std::printf("orbit in 0.5 degree steps: largest step RMSE nearest cell %.2f, blended %.2f\n",
              nearest, blended);
  EXPECT_LT(blended, 0.5 * nearest);
}

// The lod scene at a 4 px bound: some teapots and tori far enough away are
// drawn as impostors, and the image stays close to the one drawn in full.
TEST_F(ImpostorTest, LodSceneImpostorsStayCloseToTheFullMeshes) {
  Scene scene = builtinScene("lod");
  RenderSettings settings{640, 360, ShadingModel::Phong};
  RenderResult full = renderer().renderToImage(scene, settings);
  settings.lod = true;
  settings.lodErrorPixels = 4.0f;
  RenderResult withImpostors = renderer().renderToImage(scene, settings);
  settings.impostorCells = 0;
  RenderResult without = renderer().renderToImage(scene, settings);
  ImageU8 reference = encodeSrgb8(full.image);
  double flipWith = flipError(reference, encodeSrgb8(withImpostors.image)).mean;
  double flipWithout = flipError(reference, encodeSrgb8(without.image)).mean;
  std::printf("lod scene at 4 px: %u impostors, mean FLIP %.4f (meshes only: %.4f)\n",
              withImpostors.stats.impostors, flipWith, flipWithout);
  EXPECT_GT(withImpostors.stats.impostors, 5u);
  EXPECT_EQ(without.stats.impostors, 0u);
  EXPECT_LT(withImpostors.stats.triangles, without.stats.triangles);
  EXPECT_LT(flipWith, 0.02);
}

// The impostor is ranked by impostorError: the outline of the impostor is
// on average within that bound of the mesh's, and more cells bring it closer.
TEST_F(ImpostorTest, ParallaxStaysWithinTheBoundAndShrinksWithMoreCells) {
  std::vector<ImpostorParallax> results =
      measureImpostorParallax(renderer(), {4, 16}, 12, kWidth, kHeight);
  ASSERT_EQ(results.size(), 2u);
  for (const ImpostorParallax& r : results) {
    std::printf("%u cells: bound %.2f px, outline mean %.2f max %.2f px, FLIP %.4f\n", r.cells,
                r.boundPixels, r.meanOutlinePixels, r.maxOutlinePixels, r.meanFlip);
    EXPECT_TRUE(r.allImpostors);
    EXPECT_LT(r.meanOutlinePixels, r.boundPixels);
    EXPECT_GT(r.meanOutlinePixels, 0.0);  // an impostor is not the mesh
  }
  EXPECT_LT(results[1].meanOutlinePixels, results[0].meanOutlinePixels);
  EXPECT_LT(results[1].meanFlip, results[0].meanFlip);
  // Blended, the same bound holds (impostorError takes the larger angle).
  ImpostorParallax blended =
      measureImpostorParallax(renderer(), {16}, 12, kWidth, kHeight, true).front();
  std::printf("16 cells blended: bound %.2f px, outline mean %.2f max %.2f px, FLIP %.4f\n",
              blended.boundPixels, blended.meanOutlinePixels, blended.maxOutlinePixels,
              blended.meanFlip);
  EXPECT_TRUE(blended.blend);
  EXPECT_TRUE(blended.allImpostors);
  EXPECT_LT(blended.maxOutlinePixels, blended.boundPixels);
  EXPECT_GT(blended.meanOutlinePixels, 0.0);
}

}  // namespace
}  // namespace shadelab::test
