// Mesh instancing on the device: the copies of an "instances" block drawn as
// one instanced draw give, bit for bit, the image of the same objects drawn
// one by one (with shadows and levels of detail, which choose per copy), and
// culling per copy changes no pixel. The built-in `lod` scene (instanced
// teapots and tori among tree billboards) keeps the 0.5 px bound.
#include <cstdio>
#include <cstring>
#include <string>

#include "core/metrics/metrics.h"
#include "core/scene/mesh.h"
#include "core/scene/scene_json.h"
#include "core/scene/shape.h"
#include "gpu_test_support.h"

namespace shadelab::test {
namespace {

constexpr uint32_t kWidth = 320;
constexpr uint32_t kHeight = 180;

// Teapots in a row into the distance, on a floor, lit by a shadowing sun.
std::string teapotsJson(const std::string& teapots) {
  return R"({"camera": {"eye": [0, 3, 9], "at": [0, 0.5, -6], "fovy": 45, "far": 200},
    "lights": [{"type": "directional", "direction": [-0.5, -0.8, -0.35], "intensity": 0.9}],
    "materials": {"glaze": {"kd": [0.8, 0.3, 0.2], "ks": 0.5, "shininess": 48}},
    "objects": [{"shape": "plane", "size": 80}, )" +
         teapots + "]}";
}

constexpr int kCopies = 6;

float copyZ(int i) {
  return 4.0f - 7.0f * float(i);
}

std::string instancedTeapots() {
  std::string list;
  for (int i = 0; i < kCopies; ++i)
    list += std::string(i ? ", " : "") + R"([{"translate": [0, 0, )" + std::to_string(copyZ(i)) +
            R"(]}, {"rotate": {"axis": [0, 1, 0], "degrees": 30}}])";
  return teapotsJson(R"({"shape": "teapot", "tessellation": 12, "material": "glaze",
      "instances": {"list": [)" +
                     list + "]}}");
}

// The same teapots as objects of their own; `shift` moves the third aside.
std::string separateTeapots(float shift) {
  std::string objects;
  for (int i = 0; i < kCopies; ++i)
    objects +=
        std::string(i ? ", " : "") +
        R"({"shape": "teapot", "tessellation": 12, "material": "glaze", "transform": [{"translate": [)" +
        std::to_string(i == 2 ? shift : 0.0f) + ", 0, " + std::to_string(copyZ(i)) +
        R"(]}, {"rotate": {"axis": [0, 1, 0], "degrees": 30}}]})";
  return teapotsJson(objects);
}

RenderSettings settings(bool lod) {
  RenderSettings s{kWidth, kHeight, ShadingModel::Phong};
  s.shadows = ShadowMethod::Pcf3;
  s.lod = lod;
  return s;
}

bool sameFloats(const ImageRgba& a, const ImageRgba& b) {
  return a.pixels.size() == b.pixels.size() &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

// `scene` at 320x180, Phong, in full and with --lod auto at 0.5 px: both
// frames' counts and the mean FLIP of the levelled image against the full one.
struct FullAndLevelled {
  RenderStats full, levelled;
  double flip = 0.0;
};
FullAndLevelled renderFullAndLevelled(Renderer& renderer, const Scene& scene) {
  RenderSettings s{320, 180, ShadingModel::Phong};
  RenderResult full = renderer.renderToImage(scene, s);
  s.lod = true;
  RenderResult levelled = renderer.renderToImage(scene, s);
  return {full.stats, levelled.stats,
          flipError(encodeSrgb8(full.image), encodeSrgb8(levelled.image)).mean};
}

class Instancing : public GpuTest, public ::testing::WithParamInterface<bool> {};

TEST_P(Instancing, CopiesEqualTheSameObjectsOneByOneBitForBit) {
  bool lod = GetParam();
  Scene instanced = parseSceneJson(instancedTeapots(), "instanced.json");
  Scene separate = parseSceneJson(separateTeapots(0.0f), "separate.json");
  ASSERT_EQ(instanced.objects.size(), size_t(kCopies + 1));
  EXPECT_EQ(instanced.objects[3].instanceGroup, 1u);
  EXPECT_EQ(instanced.objects[3].name, "objects[1][2]");
  EXPECT_EQ(separate.objects[3].instanceGroup, Object::kNotInstanced);
  RenderResult a = renderer().renderToImage(instanced, settings(lod));
  RenderResult b = renderer().renderToImage(separate, settings(lod));
  EXPECT_EQ(a.stats.triangles, b.stats.triangles);
  EXPECT_EQ(a.stats.coarserDraws, b.stats.coarserDraws);
  EXPECT_EQ(b.stats.drawCalls, uint32_t(kCopies + 1));
  // The floor, then one draw per level in use (all copies at one level without LOD).
  if (lod) {
    EXPECT_GT(a.stats.coarserDraws, 0u);
    EXPECT_GT(a.stats.drawCalls, 2u);
    EXPECT_LT(a.stats.drawCalls, b.stats.drawCalls);
  } else {
    EXPECT_EQ(a.stats.drawCalls, 2u);
  }
  EXPECT_TRUE(sameFloats(a.image, b.image));
  // Twin: the third teapot a hundredth of a unit aside is caught by the same comparison.
  RenderResult moved =
      renderer().renderToImage(parseSceneJson(separateTeapots(0.01f), "moved.json"), settings(lod));
  EXPECT_FALSE(sameFloats(a.image, moved.image));
}

INSTANTIATE_TEST_SUITE_P(LevelsOfDetail, Instancing, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "LodAuto" : "Full"; });

// Copies out of view are culled one by one: fewer drawn, the same pixels,
// and --instancing off draws the survivors one by one to the same image.
TEST_F(GpuTest, InstanceCopiesAreCulledOneByOne) {
  Scene scene =
      parseSceneJson(teapotsJson(R"({"shape": "teapot", "tessellation": 6, "material": "glaze",
        "instances": {"grid": {"count": [9, 1, 9], "spacing": [5, 1, 5]}}})"),
                     "grid.json");
  scene.camera.eye = {0.0f, 4.0f, 24.0f};
  scene.camera.at = {6.0f, 0.0f, 0.0f};
  RenderSettings culled = settings(false);
  RenderResult a = renderer().renderToImage(scene, culled);
  RenderSettings all = culled;
  all.frustumCulling = false;
  RenderResult b = renderer().renderToImage(scene, all);
  RenderSettings oneByOne = culled;
  oneByOne.instancing = false;
  RenderResult c = renderer().renderToImage(scene, oneByOne);
  EXPECT_GT(a.stats.culledDraws, 10u);
  EXPECT_EQ(b.stats.culledDraws, 0u);
  EXPECT_EQ(a.stats.drawCalls, 2u);
  EXPECT_EQ(c.stats.drawCalls, 82u - c.stats.culledDraws);
  EXPECT_LT(a.stats.triangles, b.stats.triangles);
  EXPECT_TRUE(sameFloats(a.image, b.image));
  EXPECT_TRUE(sameFloats(a.image, c.image));
}

// A --tess 4 scene's chain starts below its 4x meshes: a sphere of 32
// slices built at 128, close enough to need more than 32 but not 128, is
// drawn at 64 (without the chain's 64 and 32 it was drawn in full).
TEST_F(GpuTest, RetessellatedShapesChainFromTheirFactor) {
  Scene scene;
  scene.camera.eye = {0.0f, 0.0f, 3.5f};
  scene.lights.push_back(Light{});
  ShapeDesc sphere;
  sphere.kind = ShapeKind::UvSphere;
  sphere.tessellation = 32;
  scene.objects.push_back({"ball", scene.addShape(sphere), glm::mat4(1.0f), Material{}});
  scene.retessellate(4.0f);
  RenderSettings s{640, 360, ShadingModel::Phong};
  s.lod = true;
  RenderResult result = renderer().renderToImage(scene, s);
  ShapeDesc expected = sphere;
  expected.tessellation = 64;
  EXPECT_EQ(result.stats.coarserDraws, 1u);
  EXPECT_EQ(result.stats.triangles, buildShape(expected).triangleCount());
}

// A UV-projected copy of a mesh gets the mesh's levels too (its own
// vertices, the mesh's triangles), so a far textured sphere with planar UVs
// is drawn coarser, within the bound.
TEST_F(GpuTest, UvProjectedCopiesHaveLevels) {
  Scene scene = parseSceneJson(
      R"({"camera": {"eye": [0, 0, 12], "at": [0, 0, 0]},
          "lights": [{"type": "directional", "direction": [-1, -1, -1]}],
          "objects": [{"shape": "sphere", "tessellation": 96,
            "material": {"uv_mapping": "planar", "diffuse_map": {"procedural": "checker", "size": 64}}}]})",
      "projected.json");
  FullAndLevelled run = renderFullAndLevelled(renderer(), scene);
  EXPECT_EQ(run.levelled.coarserDraws, 1u);
  EXPECT_LT(run.levelled.triangles * 4, run.full.triangles);
  EXPECT_LT(run.flip, 0.01);
}

// A copy whose material was changed after loading (as C++ code may do) is
// not merged with its group: drawn on its own, to the image the copies give
// one by one.
TEST_F(GpuTest, CopiesThatDifferAreDrawnOnTheirOwn) {
  Scene scene = parseSceneJson(instancedTeapots(), "instanced.json");
  scene.objects[4].material.kd = glm::vec3(0.1f, 0.7f, 0.2f);
  RenderSettings s = settings(false);
  RenderResult batched = renderer().renderToImage(scene, s);
  s.instancing = false;
  RenderResult oneByOne = renderer().renderToImage(scene, s);
  EXPECT_EQ(batched.stats.drawCalls, 3u) << "the floor, the five alike, the green one";
  EXPECT_TRUE(sameFloats(batched.image, oneByOne.image));
}

// A loaded (custom) mesh with projected UVs draws its simplified levels over
// the projected copy's vertices.
TEST_F(GpuTest, UvProjectedLoadedMeshesHaveLevels) {
  Scene scene = parseSceneJson(
      R"({"camera": {"eye": [0, 0, 12], "at": [0, 0, 0]},
          "lights": [{"type": "directional", "direction": [-1, -1, -1]}],
          "objects": [{"shape": "plane", "size": 0.01,
            "material": {"diffuse_map": {"procedural": "checker", "size": 64}}}]})",
      "custom.json");
  Material material = scene.objects[0].material;
  material.uvProjection = UvProjection::Planar;
  scene.objects.push_back(
      {"ball", scene.addMesh(makeUvSphere(1.0f, 96, 48)), glm::mat4(1.0f), material});
  FullAndLevelled run = renderFullAndLevelled(renderer(), scene);
  EXPECT_EQ(run.levelled.coarserDraws, 1u);
  EXPECT_LT(run.levelled.triangles * 2, run.full.triangles);
  EXPECT_LT(run.flip, 0.01);
}

// On the built-in scene, with shadows, at 640x360: 0.5 px draws a small
// fraction of the triangles at a mean FLIP under 0.01 against every object
// in full; the same comparison catches a 40 px bound.
TEST_F(GpuTest, BuiltInLodSceneKeepsTheHalfPixelBound) {
  Scene scene = builtinScene("lod");
  auto draw = [&](bool lod, float bound, RenderStats& stats) {
    RenderSettings s{640, 360, ShadingModel::Phong};
    s.shadows = ShadowMethod::Pcf3;
    s.lod = lod;
    s.lodErrorPixels = bound;
    RenderResult result = renderer().renderToImage(scene, s);
    stats = result.stats;
    return encodeSrgb8(result.image);
  };
  RenderStats full, fine, coarse;
  ImageU8 reference = draw(false, 0.5f, full);
  double fineError = flipError(reference, draw(true, 0.5f, fine)).mean;
  double coarseError = flipError(reference, draw(true, 40.0f, coarse)).mean;
  std::printf(
      "lod scene: %llu -> %llu triangles at 0.5 px (mean FLIP %.4f), %llu at 40 px (%.4f)\n",
      static_cast<unsigned long long>(full.triangles),
      static_cast<unsigned long long>(fine.triangles), fineError,
      static_cast<unsigned long long>(coarse.triangles), coarseError);
  EXPECT_GT(fine.coarserDraws, 40u);
  EXPECT_LT(fine.triangles * 10, full.triangles);
  EXPECT_LT(fineError, 0.01);
  EXPECT_GT(coarseError, 0.01);
}

}  // namespace
}  // namespace shadelab::test
