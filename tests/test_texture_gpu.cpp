// Textures on the device: complete mip chains for odd and 1x1 sizes
// (every level read back at its expected size with the validation layer
// watching), sRGB-correct averages in the last level, and samplers created
// once per description.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/base/image.h"
#include "core/scene/procedural_textures.h"
#include "core/scene/texture.h"
#include "gpu_test_support.h"
#include "passes/forward_pass.h"
#include "passes/scene_textures.h"

namespace shadelab::test {
namespace {

using TextureUpload = GpuTest;

GpuTexture upload(Context& context, const Texture& texture) {
  MipGeneration mips(context);
  return std::move(uploadTextures(context, mips, {&texture}).front());
}

Texture checker(uint32_t width, uint32_t height, bool srgb) {
  Texture texture{"checker", width, height, std::vector<uint8_t>(size_t(width) * height * 4), srgb};
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      uint8_t value = (x + y) % 2 ? 0 : 255;
      uint8_t* texel = &texture.rgba8[(size_t(y) * width + x) * 4];
      texel[0] = texel[1] = texel[2] = value;
      texel[3] = 255;
    }
  return texture;
}

// Reading a level with a wrong extent would be a validation error, so a clean
// readback of every level at mipLevelSize proves the device's sizes.
void expectCompleteChain(Context& context, const GpuTexture& gpu, uint32_t expectedLevels) {
  EXPECT_EQ(gpu.levels, expectedLevels);
  EXPECT_EQ(gpu.image.desc().mipLevels, expectedLevels);
  for (uint32_t level = 0; level < gpu.levels; ++level) {
    glm::uvec2 size = mipLevelSize(gpu.width, gpu.height, level);
    EXPECT_EQ(readTextureLevel(context, gpu, level).size(), size_t(size.x) * size.y * 4);
  }
  EXPECT_EQ(mipLevelSize(gpu.width, gpu.height, gpu.levels - 1), glm::uvec2(1, 1));
}

TEST_F(TextureUpload, OddSizeGetsACompleteChainDownTo1x1) {
  GpuTexture gpu = upload(context(), checker(37, 23, true));
  expectCompleteChain(context(), gpu, 6);  // 37x23 18x11 9x5 4x2 2x1 1x1
}

TEST_F(TextureUpload, OneByOneHasOneLevelHoldingItsTexel) {
  GpuTexture gpu = upload(context(), solidTexture({10, 20, 30, 40}, TextureRole::Data, "1x1"));
  expectCompleteChain(context(), gpu, 1);
  EXPECT_EQ(readTextureLevel(context(), gpu, 0), (std::vector<uint8_t>{10, 20, 30, 40}));
}

TEST_F(TextureUpload, BaseLevelReadsBackAsUploaded) {
  Texture texture = heightColorTexture(proceduralHeight({HeightPattern::Bricks, 40, 4}),
                                       glm::vec3(0.1f), glm::vec3(0.9f, 0.4f, 0.2f), "bricks");
  EXPECT_EQ(readTextureLevel(context(), upload(context(), texture), 0), texture.rgba8);
}

// A black/white checker averages to half the light: linear 0.5, which sRGB
// encodes as 188. Averaging the codes (as a UNORM chain does) gives 128.
TEST_F(TextureUpload, LastLevelIsTheLinearAverageForSrgbAndTheCodeAverageForData) {
  std::vector<uint8_t> srgb =
      readTextureLevel(context(), upload(context(), checker(64, 64, true)), 6);
  std::vector<uint8_t> unorm =
      readTextureLevel(context(), upload(context(), checker(64, 64, false)), 6);
  std::printf("64x64 checker, 1x1 level: sRGB %d (expected 188), UNORM %d (expected 127-128)\n",
              srgb[0], unorm[0]);
  EXPECT_NEAR(srgb[0], 188, 1);
  EXPECT_NEAR(unorm[0], 127.5, 1);
  EXPECT_EQ(srgb[3], 255);
}

// Light rising linearly across a 37x23 texture averages to 0.5 (sRGB 188):
// bilinear taps reproduce a linear function, so the odd-size chain must too.
TEST_F(TextureUpload, OddSizeLastLevelIsTheAverageOfASmoothTexture) {
  Texture ramp{"ramp", 37, 23, std::vector<uint8_t>(37 * 23 * 4), true};
  double sum = 0.0;
  for (uint32_t y = 0; y < 23; ++y)
    for (uint32_t x = 0; x < 37; ++x) {
      float light = 0.5f * (float(x) / 36.0f + float(y) / 22.0f);
      uint8_t code = uint8_t(std::lround(linearToSrgb(light) * 255.0f));
      sum += srgbToLinear(float(code) / 255.0f);
      uint8_t* texel = &ramp.rgba8[(y * 37 + x) * 4];
      texel[0] = texel[1] = texel[2] = code;
      texel[3] = 255;
    }
  int expected = int(std::lround(linearToSrgb(float(sum / (37.0 * 23.0))) * 255.0f));
  std::vector<uint8_t> last = readTextureLevel(context(), upload(context(), ramp), 5);
  std::printf("37x23 linear ramp, 1x1 level: sRGB %d (average of the texels %d)\n", last[0],
              expected);
  EXPECT_NEAR(last[0], expected, 2);
}

// The worst case for any blit chain: a one-texel checker of odd size. Each
// halving tap lands at a different phase of the pattern, so the 1x1 level is
// off the true average (188); measured here so a change in it is seen.
TEST_F(TextureUpload, OddSizeCheckerShowsTheBlitChainsBias) {
  std::vector<uint8_t> last =
      readTextureLevel(context(), upload(context(), checker(37, 23, true)), 5);
  std::printf("37x23 one-texel checker, 1x1 level: sRGB %d (true average 188)\n", last[0]);
  EXPECT_NEAR(last[0], 188, 24);
}

TEST_F(TextureUpload, SamplersAreCreatedOncePerDescription) {
  LightSets lightSets;
  ForwardPass forward(context(), {}, lightSets);
  SceneTextures textures(context(), forward.materialSetLayout());
  Scene scene = builtinScene("bump");  // three maps, one sampler description
  for (int i = 0; i < 2; ++i) {
    GpuScene gpuScene = uploadScene(context(), scene);
    textures.upload(scene, gpuScene);
    textures.prepareFilter(std::nullopt);
    std::span<const VkDescriptorSet> sets = textures.materialSets(std::nullopt);
    for (const DrawItem& draw : gpuScene.draws) {
      ASSERT_LT(draw.material, sets.size());
      EXPECT_NE(sets[draw.material], VK_NULL_HANDLE);
    }
  }
  EXPECT_EQ(textures.samplerCount(), 1u);
  // Another filter is another set per material, and one more sampler.
  textures.prepareFilter(TextureFilter::Nearest);
  EXPECT_EQ(textures.samplerCount(), 2u);
  EXPECT_NE(textures.materialSets(TextureFilter::Nearest)[0],
            textures.materialSets(std::nullopt)[0]);
  // Prepared choices are kept: preparing one again writes nothing new.
  VkDescriptorSet nearest = textures.materialSets(TextureFilter::Nearest)[0];
  textures.prepareFilter(TextureFilter::Nearest);
  EXPECT_EQ(textures.materialSets(TextureFilter::Nearest)[0], nearest);
}

// The UV convention (core/scene/mesh.h): origin at the bottom left, v up, so an
// image's top row shows at the top of a plane facing the camera, unflipped.
Scene quadrantScene() {
  Scene scene;
  scene.camera.eye = {0.0f, 0.0f, 5.0f};
  scene.camera.projection = Projection::Orthographic;
  scene.ambient = glm::vec3(1.0f);
  Mesh plane = makePlane(2.0f, 1);
  for (Vertex& vertex : plane.vertices)  // rotate the XZ plane to face +z: -z becomes +y
    vertex = {{vertex.position.x, -vertex.position.z, 0.0f}, {0, 0, 1}, vertex.uv, {1, 0, 0, 1}};
  // Top left red, top right green, bottom left blue, bottom right white.
  scene.textures.push_back({"quadrants",
                            2,
                            2,
                            {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255},
                            true});
  Material material{glm::vec3(1.0f), glm::vec3(0.0f), glm::vec3(0.0f), 1.0f};
  material.diffuseMap.texture = 0;
  material.diffuseMap.sampler.filter = TextureFilter::Nearest;
  scene.objects.push_back({"plane", scene.addMesh(plane), glm::mat4(1.0f), material});
  return scene;
}

TEST_F(TextureUpload, ImagesAppearUnflippedOnAPlaneFacingTheCamera) {
  ImageU8 image = render(quadrantScene(), {32, 32, ShadingModel::Phong});
  EXPECT_EQ(image.at(8, 8), glm::u8vec4(255, 0, 0, 255));
  EXPECT_EQ(image.at(24, 8), glm::u8vec4(0, 255, 0, 255));
  EXPECT_EQ(image.at(8, 24), glm::u8vec4(0, 0, 255, 255));
  EXPECT_EQ(image.at(24, 24), glm::u8vec4(255, 255, 255, 255));
}

// Where a coordinate outside 0..1 lands (the Vulkan spec's wrap functions).
float wrapped(TextureWrap wrap, float x) {
  switch (wrap) {
    case TextureWrap::Repeat:
      return x - std::floor(x);
    case TextureWrap::ClampToEdge:
      return std::clamp(x, 0.0f, 0.999f);
    case TextureWrap::MirroredRepeat: {
      float m = x - 2.0f * std::floor(x / 2.0f);
      return m < 1.0f ? m : 2.0f - m;
    }
  }
  return x;
}

// The quadrant image tiled twice per axis with each wrap mode per axis: every
// pixel must show the texel the wrap functions pick.
TEST_F(TextureUpload, WrapModesApplyPerAxis) {
  const std::pair<TextureWrap, TextureWrap> cases[] = {
      {TextureWrap::Repeat, TextureWrap::Repeat},
      {TextureWrap::ClampToEdge, TextureWrap::MirroredRepeat},
      {TextureWrap::MirroredRepeat, TextureWrap::ClampToEdge}};
  const glm::u8vec4 texels[2][2] = {{{255, 0, 0, 255}, {0, 255, 0, 255}},
                                    {{0, 0, 255, 255}, {255, 255, 255, 255}}};
  for (auto [wrapU, wrapV] : cases) {
    Scene scene = quadrantScene();
    Material& material = scene.objects[0].material;
    material.uvScale = glm::vec2(2.0f);
    material.diffuseMap.sampler.wrapU = wrapU;
    material.diffuseMap.sampler.wrapV = wrapV;
    ImageU8 image = render(scene, {32, 32, ShadingModel::Phong});
    uint32_t wrong = 0;
    for (uint32_t y = 0; y < 32; ++y)
      for (uint32_t x = 0; x < 32; ++x) {
        float s = 2.0f * (float(x) + 0.5f) / 32.0f;
        float t = 1.0f - 2.0f * (1.0f - (float(y) + 0.5f) / 32.0f);  // t = 1 - v * scale
        int column = int(wrapped(wrapU, s) * 2.0f), row = int(wrapped(wrapV, t) * 2.0f);
        wrong += image.at(x, y) != texels[row][column];
      }
    EXPECT_EQ(wrong, 0u) << "wrap u " << int(wrapU) << ", v " << int(wrapV);
  }
}

// A planar S-mapping projects the image along -z: a sphere seen from +z shows
// it like the plane does, drawn from a projected copy of the shared mesh.
TEST_F(TextureUpload, PlanarProjectionShowsTheImageOnASphere) {
  Scene scene = quadrantScene();
  Object ball = scene.objects[0];
  ball.mesh = scene.addMesh(makeUvSphere(1.0f, 32, 16));
  ball.material.uvProjection = UvProjection::Planar;
  scene.objects = {ball};
  ImageU8 image = render(scene, {32, 32, ShadingModel::Phong});
  EXPECT_EQ(image.at(10, 10), glm::u8vec4(255, 0, 0, 255));
  EXPECT_EQ(image.at(21, 10), glm::u8vec4(0, 255, 0, 255));
  EXPECT_EQ(image.at(10, 21), glm::u8vec4(0, 0, 255, 255));
  EXPECT_EQ(image.at(21, 21), glm::u8vec4(255, 255, 255, 255));
  scene.objects.push_back(scene.objects[0]);
  scene.objects[1].material.uvProjection = UvProjection::Mesh;
  GpuScene gpuScene = uploadScene(context(), scene);
  EXPECT_NE(gpuScene.draws[0].vertexOffset, gpuScene.draws[1].vertexOffset);
}

}  // namespace
}  // namespace shadelab::test
