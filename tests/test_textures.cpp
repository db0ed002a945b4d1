// Textures on the CPU: mip chain sizes, image files into Texture (sRGB for
// colour, linear for data), the procedural generators and the normal maps
// derived from them, and the S-mappings against their written formulas.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <numbers>

#include "core/base/errors.h"
#include "core/base/image.h"
#include "core/scene/environment.h"
#include "core/scene/gltf_loader.h"
#include "core/scene/procedural_textures.h"
#include "core/scene/texture.h"
#include "core/scene/uv_mapping.h"
#include "core/trace/trace_textures.h"
#include "test_folder.h"

namespace shadelab {
namespace {

namespace fs = std::filesystem;
constexpr float kPi = std::numbers::pi_v<float>;

TEST(MipChain, LevelCountIsFloorLog2OfTheLargerSidePlusOne) {
  EXPECT_EQ(mipLevelCount(1, 1), 1u);
  EXPECT_EQ(mipLevelCount(2, 1), 2u);
  EXPECT_EQ(mipLevelCount(37, 23), 6u);  // floor(log2 37) = 5
  EXPECT_EQ(mipLevelCount(256, 256), 9u);
  EXPECT_EQ(mipLevelCount(255, 3), 8u);
  EXPECT_EQ(mipLevelCount(1, 1024), 11u);
}

TEST(MipChain, SizesHalveRoundingDownAndStopAtOne) {
  const glm::uvec2 expected[] = {{37, 23}, {18, 11}, {9, 5}, {4, 2}, {2, 1}, {1, 1}};
  for (uint32_t level = 0; level < 6; ++level)
    EXPECT_EQ(mipLevelSize(37, 23, level), expected[level]) << "level " << level;
}

// Writes pixels with OpenImageIO directly, so the channel count and type are the test's.
template <typename T>
void writeRaw(const fs::path& path, int width, int height, int channels, OIIO::TypeDesc type,
              const std::vector<T>& pixels) {
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(path.string(), OIIO::ImageSpec(width, height, channels, type)));
  ASSERT_TRUE(out->write_image(type, pixels.data()));
  out->close();
}

TEST(TextureFile, EightBitPngKeepsItsValuesForColourAndData) {
  fs::path path = test::testFolder() / "rgb.png";
  writeRaw<uint8_t>(path, 2, 1, 3, OIIO::TypeDesc::UINT8, {10, 20, 30, 200, 100, 0});
  Texture color = loadTextureFile(path, TextureRole::Color);
  Texture data = loadTextureFile(path, TextureRole::Data);
  EXPECT_TRUE(color.srgb);
  EXPECT_FALSE(data.srgb);
  ASSERT_EQ(color.width, 2u);
  ASSERT_EQ(color.height, 1u);
  std::vector<uint8_t> expected = {10, 20, 30, 255, 200, 100, 0, 255};  // alpha added, opaque
  EXPECT_EQ(color.rgba8, expected);
  EXPECT_EQ(data.rgba8, expected);
}

TEST(TextureFile, GreyReplicatesIntoRgb) {
  fs::path path = test::testFolder() / "grey.png";
  writeRaw<uint8_t>(path, 1, 1, 1, OIIO::TypeDesc::UINT8, {77});
  EXPECT_EQ(loadTextureFile(path, TextureRole::Data).rgba8,
            (std::vector<uint8_t>{77, 77, 77, 255}));
}

TEST(TextureFile, FloatExrIsLinearLightEncodedToSrgbForColourOnly) {
  fs::path path = test::testFolder() / "half.exr";
  writeRaw<float>(path, 1, 1, 4, OIIO::TypeDesc::FLOAT, {0.5f, 0.2159f, 2.0f, 0.25f});
  Texture color = loadTextureFile(path, TextureRole::Color);
  Texture data = loadTextureFile(path, TextureRole::Data);
  // sRGB(0.5) = 0.7354 -> 188; sRGB(0.2159) = 0.502 -> 128; 2.0 clamps; alpha stays linear.
  EXPECT_EQ(color.rgba8, (std::vector<uint8_t>{188, 128, 255, 64}));
  EXPECT_EQ(data.rgba8, (std::vector<uint8_t>{128, 55, 255, 64}));
}

TEST(TextureFile, MissingAndUnreadableFilesNameTheFile) {
  fs::path folder = test::testFolder();
  fs::path missing = folder / "nothing.png";
  try {
    loadTextureFile(missing, TextureRole::Color);
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(missing.string()), std::string::npos) << error.what();
  }
  fs::path garbage = folder / "garbage.png";
  std::ofstream(garbage) << "not an image";
  EXPECT_THROW(loadTextureFile(garbage, TextureRole::Color), InputError);
}

// A float file's NaN texels are refused, naming the file, the count and the
// first one, as a texture and as a panorama (instead of black texels or a
// black sky); an infinity saturates (a sun stored as +inf), and finite
// values up to 3e38 load.
TEST(TextureFile, NonFiniteTexelsAreRefused) {
  fs::path folder = test::testFolder();
  fs::path path = folder / "nan.exr";
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  writeRaw<float>(path, 2, 2, 3, OIIO::TypeDesc::FLOAT,
                  {0.5f, 0.5f, 0.5f, 0.2f, 0.3f, 0.4f, 0.1f, nan, 0.1f, inf, 0.0f, 0.0f});
  for (auto load : {std::function<void()>([&] { loadTextureFile(path, TextureRole::Color); }),
                    std::function<void()>([&] { readLinearImage(path); })}) {
    try {
      load();
      ADD_FAILURE() << "no InputError";
    } catch (const InputError& error) {
      std::string what = error.what();
      EXPECT_NE(what.find(path.string()), std::string::npos) << what;
      EXPECT_NE(what.find("1 texel(s) NaN (the first at x, y = 0, 1)"), std::string::npos) << what;
    }
  }
  fs::path finite = folder / "finite.exr";
  writeRaw<float>(finite, 2, 1, 3, OIIO::TypeDesc::FLOAT, {3.0e38f, 0.0f, 1.0f, inf, 0.5f, 0.0f});
  EXPECT_NO_THROW(loadTextureFile(finite, TextureRole::Color));
  EXPECT_NO_THROW(readLinearImage(finite));
}

// A scene's textures are held to kMaxSceneTexels together, checked on each
// header before its texels are decoded: four 8192x8192 textures fit, a
// fifth is refused naming it and the totals. Texture files and glTF images
// go through it (a scene whose textures already declare the whole budget,
// with no texels behind them: a 4x4 image more is refused before decoding).
TEST(TextureFile, ScenesTexturesTogetherAreHeldToTheBudget) {
  const int64_t side = kMaxTextureSide;
  EXPECT_NO_THROW(checkSceneTexels("fourth", side, side, 3 * uint64_t(side * side)));
  try {
    checkSceneTexels("fifth.png", side, side, 4 * uint64_t(side * side));
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "fifth.png: 8192x8192 texels would bring the scene's textures to 335544320 texels, "
              "more than the 268435456 allowed (1 GiB of RGBA8)");
  }
  fs::path png = test::testFolder() / "small.png";
  writeRaw<uint8_t>(png, 4, 4, 4, OIIO::TypeDesc::UINT8, std::vector<uint8_t>(64, 200));
  EXPECT_NO_THROW(loadTextureFile(png, TextureRole::Color, kMaxSceneTexels - 16));
  EXPECT_THROW(loadTextureFile(png, TextureRole::Color, kMaxSceneTexels - 15), InputError);
  Scene full;
  full.textures.push_back(Texture{"declared only", 16384, 16384});
  ASSERT_EQ(sceneTexels(full), kMaxSceneTexels);
  try {
    appendGltf(full, std::string(SHADELAB_TEST_DATA_DIR) + "/alpha_mask.gltf");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what())
                  .find("images[0]: 4x4 texels would bring the scene's "
                        "textures to 268435472 texels"),
              std::string::npos)
        << error.what();
  }
  Scene empty;
  EXPECT_NO_THROW(appendGltf(empty, std::string(SHADELAB_TEST_DATA_DIR) + "/alpha_mask.gltf"));
}

TEST(Procedural, CheckerAlternatesPerCellAndTiles) {
  HeightField field = proceduralHeight({HeightPattern::Checker, 16, 4});  // 4x4-texel cells
  EXPECT_EQ(field.at(0, 0), 1.0f);
  EXPECT_EQ(field.at(3, 3), 1.0f);
  EXPECT_EQ(field.at(4, 0), 0.0f);
  EXPECT_EQ(field.at(0, 4), 0.0f);
  EXPECT_EQ(field.at(4, 4), 1.0f);
  EXPECT_EQ(field.at(-1, 0), field.at(15, 0));  // wraps
}

TEST(Procedural, EveryPatternIsInUnitRangeTilesAndIsDeterministic) {
  for (HeightPattern pattern : {HeightPattern::Checker, HeightPattern::Bricks,
                                HeightPattern::Dimples, HeightPattern::Waves}) {
    ProceduralTexture desc{pattern, 64, 4};
    HeightField field = proceduralHeight(desc);
    EXPECT_EQ(field.values, proceduralHeight(desc).values) << heightPatternName(pattern);
    float low = 1.0f, high = 0.0f;
    for (float h : field.values) low = std::min(low, h), high = std::max(high, h);
    EXPECT_GE(low, 0.0f) << heightPatternName(pattern);
    EXPECT_LE(high, 1.0f) << heightPatternName(pattern);
    EXPECT_GT(high - low, 0.5f) << heightPatternName(pattern) << " has no relief";
    // Period 64 / 4 = 16 texels: shifting by a cell (two for the running bond) changes nothing.
    int32_t period = pattern == HeightPattern::Bricks ? 32 : 16;
    for (int32_t y = 0; y < 64; y += 7)
      for (int32_t x = 0; x < 64; x += 5)
        EXPECT_NEAR(field.at(x, y), field.at(x + period, y + period), 1e-5f)
            << heightPatternName(pattern) << " at " << x << "," << y;
  }
}

TEST(Procedural, DimplesAreDeepestAtTheCellCentre) {
  HeightField field = proceduralHeight({HeightPattern::Dimples, 32, 1});
  EXPECT_LT(field.at(16, 16), 0.01f);  // the centre texel is half a texel off the dip
  EXPECT_EQ(field.at(0, 0), 1.0f);     // the corner is on the flat
}

TEST(Procedural, NormalFromHeightMatchesTheFormulaOnARamp) {
  // h = x / 64 rising to the right: dh/du = 1/64 per texel, no v slope.
  HeightField ramp{64, 4, std::vector<float>(64 * 4)};
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 64; ++x) ramp.values[y * 64 + x] = float(x) / 64.0f;
  float depth = 8.0f;
  glm::vec3 expected = glm::normalize(glm::vec3(-depth / 64.0f, 0.0f, 1.0f));
  glm::vec3 n = heightFieldNormal(ramp, 10, 2, depth);
  EXPECT_NEAR(glm::distance(n, expected), 0.0f, 1e-6f);
  // Height rising up the image (toward row 0) tilts the normal toward -v.
  HeightField up{4, 64, std::vector<float>(4 * 64)};
  for (uint32_t y = 0; y < 64; ++y)
    for (uint32_t x = 0; x < 4; ++x) up.values[y * 4 + x] = float(63 - y) / 64.0f;
  EXPECT_LT(heightFieldNormal(up, 1, 10, depth).y, -0.1f);
  Texture encoded = normalMapTexture(ramp, depth, "ramp");
  size_t p = (2 * 64 + 10) * 4;
  EXPECT_EQ(encoded.rgba8[p + 0], uint8_t(std::lround((expected.x * 0.5f + 0.5f) * 255.0f)));
  EXPECT_EQ(encoded.rgba8[p + 1], 128);
  EXPECT_FALSE(encoded.srgb);
}

TEST(Procedural, ColourTextureIsTheSrgbEncodedLinearMix) {
  HeightField half{1, 1, {0.5f}};
  Texture texture = heightColorTexture(half, glm::vec3(0.0f), glm::vec3(1.0f, 0.5f, 0.0f), "t");
  EXPECT_TRUE(texture.srgb);
  EXPECT_EQ(texture.rgba8[0], uint8_t(std::lround(linearToSrgb(0.5f) * 255.0f)));
  EXPECT_EQ(texture.rgba8[1], uint8_t(std::lround(linearToSrgb(0.25f) * 255.0f)));
  EXPECT_EQ(texture.rgba8[2], 0);
}

const Bounds kBox{{-1.0f, -2.0f, -4.0f}, {3.0f, 2.0f, 4.0f}};  // centre (1, 0, 0)

void expectUv(glm::vec2 actual, glm::vec2 expected) {
  EXPECT_NEAR(actual.x, expected.x, 1e-6f);
  EXPECT_NEAR(actual.y, expected.y, 1e-6f);
}

TEST(SMapping, PlanarFitsXyToTheBounds) {
  expectUv(projectUv(UvProjection::Planar, {0.0f, 1.0f, 3.0f}, {}, kBox),
           {(0.0f + 1.0f) / 4.0f, (1.0f + 2.0f) / 4.0f});
}

TEST(SMapping, CylindricalIsTheAngleAroundYAndTheHeight) {
  glm::vec3 p{1.0f + std::cos(0.3f), -1.0f, std::sin(0.3f)};  // d = (cos .3, sin .3) in xz
  expectUv(projectUv(UvProjection::Cylindrical, p, {}, kBox),
           {0.5f + std::atan2(std::cos(0.3f), std::sin(0.3f)) / (2.0f * kPi), 0.25f});
  expectUv(projectUv(UvProjection::Cylindrical, {1.0f, 2.0f, 1.0f}, {}, kBox), {0.5f, 1.0f});
}

TEST(SMapping, SphericalIsLongitudeAndLatitude) {
  glm::vec3 d = glm::normalize(glm::vec3(1.0f, 1.0f, -1.0f));
  glm::vec2 uv =
      projectUv(UvProjection::Spherical, glm::vec3(1.0f, 0.0f, 0.0f) + 2.0f * d, {}, kBox);
  expectUv(uv, {0.5f + std::atan2(d.x, d.z) / (2.0f * kPi), 0.5f + std::asin(d.y) / kPi});
  expectUv(projectUv(UvProjection::Spherical, {1.0f, 5.0f, 0.0f}, {}, kBox).y * glm::vec2(1.0f),
           glm::vec2(1.0f));  // the north pole
}

TEST(SMapping, BoxProjectsAlongTheDominantNormalAxisUnmirrored) {
  glm::vec3 p{2.0f, 1.0f, -2.0f};
  // +x face, seen from +x: u runs toward -z.
  expectUv(projectUv(UvProjection::Box, p, {1, 0.2f, 0}, kBox), {(4.0f - -2.0f) / 8.0f, 0.75f});
  expectUv(projectUv(UvProjection::Box, p, {-1, 0, 0}, kBox), {(-2.0f + 4.0f) / 8.0f, 0.75f});
  // +y face, seen from above: u along +x, v along -z.
  expectUv(projectUv(UvProjection::Box, p, {0, 1, 0}, kBox), {0.75f, 0.75f});
  // -z face, seen from -z: u runs toward -x.
  expectUv(projectUv(UvProjection::Box, p, {0, 0, -1}, kBox), {0.25f, 0.75f});
  expectUv(projectUv(UvProjection::Box, p, {0, 0, 1}, kBox), {0.75f, 0.75f});
}

TEST(SMapping, FlatBoundsMapToTheMiddle) {
  Bounds flat{{0.0f, 0.0f, 0.0f}, {2.0f, 0.0f, 1.0f}};
  expectUv(projectUv(UvProjection::Planar, {1.0f, 0.0f, 0.5f}, {}, flat), {0.5f, 0.5f});
}

TEST(SMapping, ApplyReplacesUvsAndRecomputesUnitTangents) {
  Mesh mesh = makeUvSphere(1.0f, 16, 8);
  applyUvProjection(mesh, UvProjection::Planar);
  Bounds bounds = computeBounds(mesh);
  for (const Vertex& vertex : mesh.vertices) {
    expectUv(vertex.uv, projectUv(UvProjection::Planar, vertex.position, vertex.normal, bounds));
    float length = glm::length(glm::vec3(vertex.tangent));
    EXPECT_NEAR(length, 1.0f, 1e-4f);
    EXPECT_NEAR(glm::dot(glm::vec3(vertex.tangent), vertex.normal), 0.0f, 1e-4f);
  }
}

// The tracer's address modes, as Vulkan defines them: repeat wraps,
// mirrored repeat reflects every other period, clamp-to-edge holds the edge.
TEST(TraceTextureSampling, WrapModesFollowVulkansAddressModes) {
  const int32_t repeat[] = {2, 3, 0, 1, 2, 3, 0, 1};
  const int32_t mirrored[] = {1, 0, 0, 1, 2, 3, 3, 2};
  const int32_t clamped[] = {0, 0, 0, 1, 2, 3, 3, 3};
  for (int32_t i = -2; i < 6; ++i) {
    EXPECT_EQ(wrapTexel(i, 4, TextureWrap::Repeat), repeat[i + 2]) << i;
    EXPECT_EQ(wrapTexel(i, 4, TextureWrap::MirroredRepeat), mirrored[i + 2]) << i;
    EXPECT_EQ(wrapTexel(i, 4, TextureWrap::ClampToEdge), clamped[i + 2]) << i;
  }
}

// A 4x2 data texture: its chain has 3 levels (4x2, 2x1, 1x1), the last the
// mean of the texels; level 0 returns a texel at its centre, and a
// fractional level mixes the two levels around it.
TEST(TraceTextureSampling, MipChainAveragesAndTrilinearMixes) {
  Texture texture{"ramp", 4, 2, std::vector<uint8_t>(4 * 2 * 4, 255), false};
  const uint8_t values[8] = {0, 40, 80, 120, 160, 200, 240, 0};
  for (size_t i = 0; i < 8; ++i) texture.rgba8[4 * i] = values[i];
  const TraceTexture traced(texture);
  ASSERT_EQ(traced.levelCount(), 3u);
  const SamplerDesc sampler{TextureWrap::Repeat, TextureWrap::Repeat};
  EXPECT_NEAR(traced.sample({0.375f, 0.25f}, 0.0f, sampler).r, 40.0f / 255.0f, 1e-6f);
  const float mean = 840.0f / 8.0f / 255.0f;
  EXPECT_NEAR(traced.sample({0.3f, 0.7f}, 2.0f, sampler).r, mean, 1e-6f);
  const float level1 = traced.sample({0.3f, 0.7f}, 1.0f, sampler).r;
  EXPECT_NEAR(traced.sample({0.3f, 0.7f}, 1.5f, sampler).r, 0.5f * (level1 + mean), 1e-6f);
  EXPECT_NEAR(traced.sample({0.3f, 0.7f}, 9.0f, sampler).r, mean, 1e-6f);  // clamped to the last
}

// A nearest sampler magnifies to the texel the point falls in; minifying,
// every sampler filters by area. A coordinate that is NaN or infinite (a
// hostile texture transform: inf x 0) gives a texel in range, never a NaN
// (which the bilinear blend gave) or an undefined conversion.
TEST(TraceTextureSampling, NearestMagnifiesToHardTexelsAndOddCoordinatesStayInRange) {
  Texture texture{"two", 2, 1, {0, 0, 0, 255, 255, 255, 255, 255}, false};
  const TraceTexture traced(texture);
  SamplerDesc nearest{TextureWrap::Repeat, TextureWrap::Repeat, TextureFilter::Nearest};
  SamplerDesc bilinear{TextureWrap::Repeat, TextureWrap::Repeat, TextureFilter::Bilinear};
  EXPECT_EQ(traced.sample({0.6f, 0.5f}, 0.0f, nearest).r, 1.0f);
  EXPECT_EQ(traced.sample({0.4f, 0.5f}, -1.0f, nearest).r, 0.0f);
  EXPECT_NEAR(traced.sample({0.6f, 0.5f}, 0.0f, bilinear).r, 0.7f, 1e-6f);  // x = 0.6 * 2 - 0.5
  EXPECT_NEAR(traced.sample({0.6f, 0.5f}, 1.0f, nearest).r, 0.5f, 1e-6f);   // minified: the mean
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  for (const SamplerDesc& sampler : {nearest, bilinear})
    for (glm::vec2 st : {glm::vec2(nan, 0.5f), glm::vec2(0.5f, nan), glm::vec2(inf, -inf)})
      for (float lod : {0.0f, 0.5f}) {
        const glm::vec4 texel = traced.sample(st, lod, sampler);
        EXPECT_TRUE(std::isfinite(texel.r) && texel.r >= 0.0f && texel.r <= 1.0f)
            << st.x << ", " << st.y << " lod " << lod;
      }
}

}  // namespace
}  // namespace shadelab
