// Bump mapping on the device: goldens of the bump scene in every shading
// model with must-fail twins, and the technique's known failure cases, each
// measured: silhouettes (a bump map cannot move them), mirrored UVs (the
// tangent frame's handedness), grazing angles (no NaN or Inf), the height
// map's normal against its formula, and flat/Gouraud ignoring bump maps.
#include <array>
#include <cmath>
#include <cstdio>

#include "core/scene/procedural_textures.h"
#include "core/scene/scene.h"
#include "core/scene/texture.h"
#include "core/scene/transform.h"
#include "gpu_test_support.h"
#include "measure/bump_silhouette.h"

namespace shadelab::test {
namespace {

constexpr uint32_t kWidth = 320;
constexpr uint32_t kHeight = 180;

RenderSettings settingsFor(uint32_t width, uint32_t height, ShadingModel model, bool bump = true) {
  RenderSettings settings{width, height, model};
  settings.textures.bump = bump;
  return settings;
}

float luminance(glm::vec4 c) {
  return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}

using BumpImages = GpuTest;

class BumpGolden : public GpuTest, public ::testing::WithParamInterface<ShadingModel> {};

TEST_P(BumpGolden, MatchesGoldenAndRejectsAMissingDiffuseMap) {
  ShadingModel model = GetParam();
  std::string name = "bump-" + std::string(shadingModelName(model));
  EXPECT_TRUE(
      matchesGolden(name, render(builtinScene("bump"), settingsFor(kWidth, kHeight, model))));
  Scene plain = builtinScene("bump");
  plain.objects[0].material.diffuseMap = {};  // the wall's bricks
  EXPECT_FALSE(matchesImage(loadGolden(name), render(plain, settingsFor(kWidth, kHeight, model))));
}

INSTANTIATE_TEST_SUITE_P(Models, BumpGolden,
                         ::testing::Values(ShadingModel::Flat, ShadingModel::Gouraud,
                                           ShadingModel::Phong, ShadingModel::BlinnPhong,
                                           ShadingModel::Unlit),
                         [](const auto& info) {
                           std::string name(shadingModelName(info.param));
                           std::erase(name, '-');
                           return name;
                         });

TEST_F(BumpImages, PhongGoldenRejectsBumpOff) {
  EXPECT_FALSE(matchesImage(
      loadGolden("bump-phong"),
      render(builtinScene("bump"), settingsFor(kWidth, kHeight, ShadingModel::Phong, false))));
}

// Flat lights once per triangle and Gouraud once per vertex, before any
// fragment reads a map, so both ignore normal and height maps: --bump changes
// nothing there, while Phong changes visibly.
TEST_F(BumpImages, FlatAndGouraudIgnoreBumpMapsPhongDoesNot) {
  Scene scene = builtinScene("bump");
  for (ShadingModel model : {ShadingModel::Flat, ShadingModel::Gouraud, ShadingModel::Phong}) {
    ImageDifference difference =
        compareImages(render(scene, settingsFor(kWidth, kHeight, model, true)),
                      render(scene, settingsFor(kWidth, kHeight, model, false)));
    std::printf("%s: bump on vs off, max difference %d, RMSE %.2f\n",
                std::string(shadingModelName(model)).c_str(), difference.maxDifference,
                difference.rmse);
    if (model == ShadingModel::Phong)
      EXPECT_GT(difference.rmse, 2.0);
    else
      EXPECT_EQ(difference.maxDifference, 0);
  }
}

// A bump map perturbs normals only: the sphere's outline must stay exactly
// where the plain sphere's is (a real displacement would move it), while the
// inside visibly changes.
TEST_F(BumpImages, BumpedSilhouetteIsPixelIdenticalToThePlainSphere) {
  Scene bumped = builtinScene("bump");
  bumped.objects.erase(bumped.objects.begin());  // the wall: the sphere against the background
  Scene plain = bumped;
  plain.objects[0].material.heightMap = {};
  ImageU8 a = render(bumped, settingsFor(kWidth, kHeight, ShadingModel::Phong));
  ImageU8 b = render(plain, settingsFor(kWidth, kHeight, ShadingModel::Phong));
  glm::u8vec4 background = a.at(0, 0);
  uint64_t covered = 0, mismatched = 0;
  double interior = 0.0;
  for (uint32_t y = 0; y < kHeight; ++y)
    for (uint32_t x = 0; x < kWidth; ++x) {
      bool inA = a.at(x, y) != background, inB = b.at(x, y) != background;
      covered += inA;
      mismatched += inA != inB;
      if (inA && inB) interior += std::abs(int(a.at(x, y).g) - int(b.at(x, y).g));
    }
  std::printf("silhouette: %llu pixels covered, %llu differ in coverage; mean |dG| inside %.2f\n",
              (unsigned long long)covered, (unsigned long long)mismatched,
              interior / double(covered));
  EXPECT_GT(covered, 5000u);
  EXPECT_EQ(mismatched, 0u);
  EXPECT_GT(interior / double(covered), 3.0);  // the dimples are there
}

// Two quads side by side in the xy plane facing +z; the right one's u runs
// backwards (a mirrored texture, as on the two halves of a symmetric model).
Mesh mirroredQuads() {
  Mesh mesh;
  auto quad = [&](float x0, float x1, float u0, float u1) {
    uint32_t base = uint32_t(mesh.vertices.size());
    for (auto [x, u, y, v] : {std::array{x0, u0, -1.0f, 0.0f}, std::array{x1, u1, -1.0f, 0.0f},
                              std::array{x1, u1, 1.0f, 1.0f}, std::array{x0, u0, 1.0f, 1.0f}})
      mesh.vertices.push_back({{x, y, 0.0f}, {0.0f, 0.0f, 1.0f}, {u, v}, glm::vec4(0.0f)});
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
  };
  quad(-1.0f, 0.0f, 0.0f, 1.0f);
  quad(0.0f, 1.0f, 1.0f, 0.0f);
  computeTangents(mesh);
  return mesh;
}

// A normal map tilted toward +u and +v everywhere, under a light symmetric in
// x: with the handedness in w, both halves tilt up (+v is +y on both) and
// mirror each other across x = 0, so they are lit alike.
Scene mirroredScene(const Mesh& mesh) {
  Scene scene;
  scene.camera.eye = {0.0f, 0.0f, 5.0f};
  scene.camera.projection = Projection::Orthographic;
  scene.camera.left = scene.camera.bottom = -1.0f;
  scene.camera.right = scene.camera.top = 1.0f;
  scene.ambient = glm::vec3(0.1f);
  scene.lights.push_back({LightType::Directional, {}, {0.0f, -1.0f, -1.0f}, glm::vec3(1.0f)});
  glm::vec3 n = glm::normalize(glm::vec3(0.4f, 0.6f, 1.0f));
  Texture tilt = solidTexture({uint8_t(std::lround((n.x * 0.5f + 0.5f) * 255.0f)),
                               uint8_t(std::lround((n.y * 0.5f + 0.5f) * 255.0f)),
                               uint8_t(std::lround((n.z * 0.5f + 0.5f) * 255.0f)), 255},
                              TextureRole::Data, "tilt");
  scene.textures.push_back(tilt);
  Material material{glm::vec3(0.1f), glm::vec3(0.8f), glm::vec3(0.0f), 1.0f};
  material.normalMap.texture = 0;
  scene.objects.push_back({"quads", scene.addMesh(mesh), glm::mat4(1.0f), material});
  return scene;
}

std::pair<double, double> halfMeans(const ImageRgba& image) {
  double left = 0.0, right = 0.0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x)
      (x < image.width / 2 ? left : right) += luminance(image.at(x, y));
  double half = double(image.width / 2) * image.height;
  return {left / half, right / half};
}

// Study bump-silhouette's headline: the same dimples as real displacement
// (256 slices, where the outline has converged to within 4 pixels of 1024)
// notch the outline, which the bump-mapped sphere keeps exactly; inside, the
// bump map's shading stays close to the real geometry's.
TEST_F(BumpImages, DisplacedGeometryChangesTheOutlineBumpMappingDoesNot) {
  BumpSilhouetteMeasurement m = measureBumpSilhouette(renderer(), 256, 480, 360);
  std::printf(
      "bump vs displaced (256 slices): outline differs on %llu of %llu px, bump vs plain "
      "%llu px, interior mean FLIP %.4f\n",
      (unsigned long long)m.silhouetteDifference, (unsigned long long)m.coveredBump,
      (unsigned long long)m.bumpVersusPlain, m.interiorFlip);
  EXPECT_EQ(m.bumpVersusPlain, 0u);
  EXPECT_GT(m.silhouetteDifference, 50u);
  EXPECT_LT(m.silhouetteDifference, m.coveredBump / 50);
  EXPECT_GT(m.interiorFlip, 0.02);
  EXPECT_LT(m.interiorFlip, 0.1);
}

TEST_F(BumpImages, MirroredUvsLightBothHalvesAlikeThanksToHandedness) {
  Mesh mesh = mirroredQuads();
  EXPECT_EQ(mesh.vertices[0].tangent.w, 1.0f);
  EXPECT_EQ(mesh.vertices[4].tangent.w, -1.0f);  // the mirrored quad
  RenderSettings settings = settingsFor(64, 64, ShadingModel::Phong);
  auto [left, right] = halfMeans(renderer().renderToImage(mirroredScene(mesh), settings).image);
  // The classic bug: a frame without handedness (w = +1 everywhere) tilts the
  // mirrored half down, away from the light.
  Mesh wrong = mesh;
  for (Vertex& vertex : wrong.vertices) vertex.tangent.w = 1.0f;
  auto [wrongLeft, wrongRight] =
      halfMeans(renderer().renderToImage(mirroredScene(wrong), settings).image);
  std::printf(
      "mirrored UVs: left %.4f, right %.4f (ratio %.4f); without handedness right %.4f "
      "(ratio %.4f)\n",
      left, right, right / left, wrongRight, wrongRight / wrongLeft);
  EXPECT_NEAR(right / left, 1.0, 0.01);
  EXPECT_LT(wrongRight / wrongLeft, 0.9);
}

// A height map rising along u at 1/255 per texel (texel x holds x), bump scale
// 64: n = normalize(-64/255, 0, 1) in tangent space, here (x, y, z) in the
// world. Lit from the -x side, the GPU must match I = Ia ka + Ip kd (N.L).
TEST_F(BumpImages, HeightMapNormalMatchesTheFormula) {
  Scene scene = mirroredScene(mirroredQuads());
  scene.meshes[0] = makePlane(2.0f, 1);
  for (Vertex& vertex : scene.meshes[0].vertices)  // the plane into xy, facing +z
    vertex = {{vertex.position.x, -vertex.position.z, 0.0f},
              {0.0f, 0.0f, 1.0f},
              vertex.uv,
              {1.0f, 0.0f, 0.0f, 1.0f}};
  Texture ramp{"ramp", 256, 1, std::vector<uint8_t>(256 * 4), false};
  for (uint32_t x = 0; x < 256; ++x)
    ramp.rgba8[x * 4] = ramp.rgba8[x * 4 + 1] = ramp.rgba8[x * 4 + 2] = uint8_t(x);
  scene.textures = {ramp};
  Material& material = scene.objects[0].material;
  material.normalMap = {};
  material.heightMap.texture = 0;
  material.heightMap.sampler.wrapU = TextureWrap::ClampToEdge;
  material.bumpScale = 64.0f;
  glm::vec3 toLight = glm::normalize(glm::vec3(-1.0f, 0.0f, 1.0f));
  scene.lights = {{LightType::Directional, {}, -toLight, glm::vec3(1.0f)}};
  ImageRgba image = renderer().renderToImage(scene, settingsFor(64, 64, ShadingModel::Phong)).image;
  glm::vec3 n = glm::normalize(glm::vec3(-64.0f / 255.0f, 0.0f, 1.0f));
  float expected = 0.1f * 0.1f + 0.8f * glm::dot(n, toLight);
  float flat = 0.1f * 0.1f + 0.8f * toLight.z;
  float measured = image.at(32, 32).r;
  std::printf("height ramp: lit %.4f, formula %.4f, unbumped %.4f\n", measured, expected, flat);
  EXPECT_NEAR(measured, expected, 2.0f / 255.0f);
  EXPECT_GT(measured, flat + 0.05f);  // tilted toward the light, not away
}

// Grazing views and grazing light on strong normal and height maps: the
// perturbed normal may face away from the eye or the light, but no channel
// may become NaN or infinite.
TEST_F(BumpImages, GrazingAnglesGiveNoNanOrInf) {
  Scene scene = builtinScene("bump");
  scene.objects[0].material.heightMap = scene.objects[1].material.heightMap;
  scene.objects[0].material.bumpScale = 40.0f;
  scene.objects[1].material.normalMap = scene.objects[0].material.normalMap;
  scene.objects[1].material.bumpScale = 40.0f;
  scene.lights[1].direction = {0.0f, 0.0f, -1.0f};  // parallel to the wall
  uint64_t bad = 0;
  for (glm::vec3 eye : {glm::vec3(7.9f, 2.0f, -1.49f), glm::vec3(0.0f, 6.0f, -1.45f),
                        glm::vec3(0.0f, 1.0f, 5.5f)}) {
    scene.camera.eye = eye;
    scene.camera.at = {0.0f, 1.0f, -1.5f};
    for (ShadingModel model : {ShadingModel::Phong, ShadingModel::BlinnPhong}) {
      ImageRgba image = renderer().renderToImage(scene, settingsFor(96, 96, model)).image;
      for (float value : image.pixels) bad += !std::isfinite(value);
    }
  }
  EXPECT_EQ(bad, 0u);
}

}  // namespace
}  // namespace shadelab::test
