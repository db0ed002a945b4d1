// glTF materials beyond the metallic-roughness factors (issue 19): alphaMode
// MASK with alphaCutoff (in every shading model and in the shadow maps),
// doubleSided, and KHR_texture_transform (offset, rotation, scale and the
// texCoord override). Each has a golden at the default tolerance
// (kGoldenTolerance: PSNR >= 40 dB, at most 0.5% of pixels off by more than
// 4/255) and a must-fail twin: the same scene with the feature undone, which
// the golden comparison has to reject.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/base/names.h"
#include "core/scene/scene_loader.h"
#include "gpu_test_support.h"

namespace shadelab::test {
namespace {

Scene testModel(const std::string& file) {
  return loadScene(std::string(SHADELAB_TEST_DATA_DIR) + "/" + file);
}

// Pixels where two images differ at all.
std::vector<bool> differing(const ImageU8& a, const ImageU8& b) {
  std::vector<bool> mask(size_t(a.width) * a.height);
  for (uint32_t y = 0; y < a.height; ++y)
    for (uint32_t x = 0; x < a.width; ++x) mask[size_t(y) * a.width + x] = a.at(x, y) != b.at(x, y);
  return mask;
}

double luminance(glm::u8vec4 pixel) {
  return 0.2126 * pixel.r + 0.7152 * pixel.g + 0.0722 * pixel.b;
}

using GltfMaterials = GpuTest;

// alpha_mask.gltf: a quad with a 4x4 checker of alpha 0 and 1 (cut-off 0.5)
// standing over a floor. Per model, with shadows off: where the quad without
// its mask covers the floor (the footprint), the masked quad lets the floor
// through at half the pixels and leaves the other half as the unmasked quad
// draws them.
TEST_F(GltfMaterials, AlphaMaskCutsHalfTheCheckerInEveryShadingModel) {
  Scene masked = testModel("alpha_mask.gltf");
  ASSERT_EQ(masked.objects.size(), 2u);
  ASSERT_FLOAT_EQ(masked.objects[1].material.alphaCutoff, 0.5f);
  Scene unmasked = masked;
  unmasked.objects[1].material.alphaCutoff = 0.0f;
  Scene floorOnly = masked;
  floorOnly.objects.pop_back();
  for (auto [model, name] : kShadingModelNames) {
    RenderSettings settings{160, 120, model};
    ImageU8 withMask = render(masked, settings);
    ImageU8 withoutMask = render(unmasked, settings);
    ImageU8 floor = render(floorOnly, settings);
    std::vector<bool> footprint = differing(withoutMask, floor);
    size_t covered = 0, throughHoles = 0, asUnmasked = 0;
    for (uint32_t y = 0; y < floor.height; ++y)
      for (uint32_t x = 0; x < floor.width; ++x) {
        if (!footprint[size_t(y) * floor.width + x]) continue;
        ++covered;
        throughHoles += withMask.at(x, y) == floor.at(x, y);
        asUnmasked += withMask.at(x, y) == withoutMask.at(x, y);
      }
    ASSERT_GT(covered, 1000u) << name;
    double holes = double(throughHoles) / double(covered);
    EXPECT_GT(holes, 0.4) << name;
    EXPECT_LT(holes, 0.6) << name;
    // Every covered pixel is one or the other: nothing blends.
    EXPECT_GE(throughHoles + asUnmasked, covered - covered / 50) << name;
  }
}

TEST_F(GltfMaterials, AlphaMaskMatchesGolden) {
  RenderSettings settings{320, 240, ShadingModel::Phong};
  EXPECT_TRUE(matchesGolden("gltf-alpha-mask", render(testModel("alpha_mask.gltf"), settings)));
}

// Must-fail twin: MASK drawn opaque (as before issue 19).
TEST_F(GltfMaterials, ComparisonRejectsAlphaMaskDrawnOpaque) {
  Scene scene = testModel("alpha_mask.gltf");
  scene.objects[1].material.alphaCutoff = 0.0f;
  EXPECT_FALSE(
      matchesImage(loadGolden("gltf-alpha-mask"), render(scene, {320, 240, ShadingModel::Phong})));
}

// The floor seen from straight above, where the upright quad is edge-on (a
// line, no pixels): all the image shows of it is its shadow, holed only if
// the shadow pass cuts the mask too.
Scene shadowFromAbove(Scene scene) {
  scene.camera.eye = {0.0f, 6.0f, -1.5f};
  scene.camera.at = {0.0f, 0.0f, -1.5f};
  scene.camera.up = {0.0f, 0.0f, -1.0f};
  return scene;
}

RenderSettings withShadows() {
  RenderSettings settings{240, 240, ShadingModel::Phong};
  settings.shadows = ShadowMethod::Pcf3;
  return settings;
}

TEST_F(GltfMaterials, AlphaMaskCutsTheShadowMatchesGolden) {
  Scene scene = shadowFromAbove(testModel("alpha_mask.gltf"));
  ImageU8 image = render(scene, withShadows());
  EXPECT_TRUE(matchesGolden("gltf-alpha-mask-shadow", image));
  // The holes are lit: more of the floor than under a solid quad's shadow.
  Scene solid = scene;
  solid.objects[1].material.alphaCutoff = 0.0f;
  ImageU8 solidShadow = render(solid, withShadows());
  double holed = 0.0, full = 0.0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      holed += luminance(image.at(x, y));
      full += luminance(solidShadow.at(x, y));
    }
  EXPECT_GT(holed, full * 1.02);
}

// Must-fail twin: the shadow of the quad without its mask.
TEST_F(GltfMaterials, ComparisonRejectsAShadowWithoutHoles) {
  Scene scene = shadowFromAbove(testModel("alpha_mask.gltf"));
  scene.objects[1].material.alphaCutoff = 0.0f;
  EXPECT_FALSE(matchesImage(loadGolden("gltf-alpha-mask-shadow"), render(scene, withShadows())));
}

// double_sided.gltf: two quads showing the camera their back faces, the sun
// behind the camera; the left one doubleSided. Per model: it is drawn, and
// (but unlit) brighter than the ambient alone, as its flipped normal faces
// the sun; the right one is culled.
TEST_F(GltfMaterials, DoubleSidedBackFacesAreDrawnAndLitInEveryShadingModel) {
  Scene scene = testModel("double_sided.gltf");
  ASSERT_EQ(scene.objects.size(), 2u);
  ASSERT_TRUE(scene.objects[0].material.doubleSided);
  ASSERT_FALSE(scene.objects[1].material.doubleSided);
  Scene oneSided = scene;
  oneSided.objects[0].material.doubleSided = false;
  Scene unlit = scene;
  unlit.lights.clear();
  for (auto [model, name] : kShadingModelNames) {
    RenderSettings settings{160, 120, model};
    ImageU8 image = render(scene, settings);
    ImageU8 culled = render(oneSided, settings);
    ImageU8 ambient = render(unlit, settings);
    std::vector<bool> drawn = differing(image, culled);
    size_t pixels = 0, rightHalf = 0;
    double lit = 0.0, ambientOnly = 0.0;
    for (uint32_t y = 0; y < image.height; ++y)
      for (uint32_t x = 0; x < image.width; ++x) {
        if (!drawn[size_t(y) * image.width + x]) continue;
        ++pixels;
        rightHalf += x >= image.width / 2;
        lit += luminance(image.at(x, y));
        ambientOnly += luminance(ambient.at(x, y));
      }
    // The quad covers about a sixth of the frame, all of it on the left.
    EXPECT_GT(pixels, size_t(image.width) * image.height / 10) << name;
    EXPECT_EQ(rightHalf, 0u) << name;
    if (model != ShadingModel::Unlit) {
      EXPECT_GT(lit, ambientOnly * 1.5) << name;
    }
  }
}

TEST_F(GltfMaterials, DoubleSidedMatchesGolden) {
  RenderSettings settings{320, 240, ShadingModel::Phong};
  EXPECT_TRUE(matchesGolden("gltf-double-sided", render(testModel("double_sided.gltf"), settings)));
}

// Must-fail twin: doubleSided ignored (as before issue 19), the quad culled.
TEST_F(GltfMaterials, ComparisonRejectsDoubleSidedIgnored) {
  Scene scene = testModel("double_sided.gltf");
  scene.objects[0].material.doubleSided = false;
  EXPECT_FALSE(matchesImage(loadGolden("gltf-double-sided"),
                            render(scene, {320, 240, ShadingModel::Phong})));
}

// texture_transform.gltf: the 2x2 texture moved, rotated and scaled (left),
// read through the texCoord override from TEXCOORD_1 (middle), and a normal
// map shifted by half its width (right).
TEST_F(GltfMaterials, TextureTransformMatchesGolden) {
  Scene scene = testModel("texture_transform.gltf");
  ASSERT_EQ(scene.objects.size(), 3u);
  const UvTransform& moved = scene.objects[0].material.diffuseMap.transform;
  EXPECT_EQ(moved.offset, glm::vec2(0.5f, 0.0f));
  EXPECT_FLOAT_EQ(moved.rotation, 1.5707964f);
  EXPECT_EQ(moved.scale, glm::vec2(2.0f, 1.0f));
  EXPECT_EQ(scene.objects[2].material.normalMap.transform.offset, glm::vec2(0.5f, 0.0f));
  RenderSettings settings{320, 240, ShadingModel::Phong};
  EXPECT_TRUE(matchesGolden("gltf-texture-transform", render(scene, settings)));
}

// Must-fail twins: each transform undone, and the override ignored.
TEST_F(GltfMaterials, ComparisonRejectsEachTextureTransformUndone) {
  RenderSettings settings{320, 240, ShadingModel::Phong};
  ImageU8 golden = loadGolden("gltf-texture-transform");
  Scene diffuse = testModel("texture_transform.gltf");
  diffuse.objects[0].material.diffuseMap.transform = UvTransform{};
  EXPECT_FALSE(matchesImage(golden, render(diffuse, settings)));
  Scene normal = testModel("texture_transform.gltf");
  normal.objects[2].material.normalMap.transform = UvTransform{};
  EXPECT_FALSE(matchesImage(golden, render(normal, settings)));
  // Without the override the middle quad reads TEXCOORD_0, all (0, 0): one colour.
  std::ifstream file(std::string(SHADELAB_TEST_DATA_DIR) + "/texture_transform.gltf");
  std::stringstream text;
  text << file.rdbuf();
  std::string json = text.str();
  const std::string override = R"("KHR_texture_transform": {
       "texCoord": 1
      })";
  size_t at = json.find(override);
  ASSERT_NE(at, std::string::npos);
  json.replace(at, override.size(), R"("KHR_texture_transform": {})");
  std::filesystem::path copy = std::filesystem::path(testOutputDir()) / "no_override.gltf";
  std::ofstream(copy) << json;
  EXPECT_FALSE(matchesImage(golden, render(loadScene(copy.string()), settings)));
}

}  // namespace
}  // namespace shadelab::test
