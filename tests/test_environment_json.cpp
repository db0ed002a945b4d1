// The scene file's "environment" field and environment images: every kind
// parses into what it says, files are found beside the scene file, and every
// mistake names the file, the field and what was expected.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/base/errors.h"
#include "core/base/image.h"
#include "core/scene/scene_json.h"
#include "test_folder.h"

namespace shadelab {
namespace {
namespace fs = std::filesystem;
using test::testFolder;
using testing::HasSubstr;

void writeSolidPng(const fs::path& path, uint32_t width, uint32_t height, glm::u8vec4 value) {
  ImageU8 image(width, height);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) image.set(x, y, value);
  writeImage(image, path);
}

Scene parseIn(const fs::path& folder, const std::string& environment) {
  return parseSceneJson(R"({"environment": )" + environment + R"(, "objects": []})",
                        (folder / "scene.json").string());
}

std::string errorIn(const fs::path& folder, const std::string& environment) {
  try {
    parseIn(folder, environment);
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no InputError)";
}

TEST(EnvironmentJson, DefaultIsNone) {
  Scene scene = parseSceneJson(R"({"objects": []})", "scene.json");
  EXPECT_FALSE(scene.environment.present());
  EXPECT_FALSE(parseIn(testFolder(), R"({"type": "none"})").environment.present());
}

TEST(EnvironmentJson, SkyFields) {
  Environment env = parseIn(testFolder(), R"({"type": "sky", "zenith": [0, 0, 1],
      "horizon": 0.5, "ground": [0.1, 0.2, 0.3], "sun_direction": [0, -1, 0], "sun_size": 5,
      "sun_intensity": [10, 9, 8], "intensity": 2, "resolution": 64})")
                        .environment;
  EXPECT_EQ(env.kind, EnvironmentKind::Sky);
  EXPECT_EQ(env.sky.zenith, glm::vec3(0, 0, 1));
  EXPECT_EQ(env.sky.horizon, glm::vec3(0.5f));
  EXPECT_EQ(env.sky.ground, glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(env.sky.sunDirection, glm::vec3(0, -1, 0));
  EXPECT_FLOAT_EQ(env.sky.sunSizeDegrees, 5.0f);
  EXPECT_EQ(env.sky.sunIntensity, glm::vec3(10, 9, 8));
  EXPECT_FLOAT_EQ(env.intensity, 2.0f);
  EXPECT_EQ(env.resolution, 64u);
}

TEST(EnvironmentJson, PanoramaIsReadRelativeToTheSceneFileAndDecodedFromSrgb) {
  fs::path folder = testFolder();
  fs::create_directories(folder / "images");
  writeSolidPng(folder / "images" / "pano.png", 16, 8, {128, 255, 0, 255});
  Environment env =
      parseIn(folder, R"({"type": "equirect", "file": "images/pano.png", "rotation": 90})")
          .environment;
  ASSERT_EQ(env.kind, EnvironmentKind::Panorama);
  ASSERT_TRUE(env.panorama);
  EXPECT_EQ(env.panorama->width, 16u);
  glm::vec4 texel = env.panorama->at(3, 5);
  EXPECT_NEAR(texel.r, srgbToLinear(128.0f / 255.0f), 1e-4f);  // 0.2158, not 0.502
  EXPECT_NEAR(texel.g, 1.0f, 1e-6f);
  EXPECT_FLOAT_EQ(env.rotationDegrees, 90.0f);
  EXPECT_EQ(cubeResolution(env), 64u);  // the smallest automatic size
}

TEST(EnvironmentJson, FloatImagesAreLinear) {
  fs::path folder = testFolder();
  ImageRgba bright(4, 2);
  for (uint32_t x = 0; x < 4; ++x)
    for (uint32_t y = 0; y < 2; ++y) bright.set(x, y, {2.5f, 0.25f, 0.0f, 1.0f});
  writeImage(bright, folder / "bright.exr");
  ImageRgba read = readLinearImage(folder / "bright.exr");
  EXPECT_NEAR(read.at(1, 1).r, 2.5f, 1e-3f);  // HDR kept, not clamped or re-decoded
  EXPECT_NEAR(read.at(1, 1).g, 0.25f, 1e-3f);
}

TEST(EnvironmentJson, CubeFacesInLayerOrder) {
  fs::path folder = testFolder();
  const char* names[6] = {"px.png", "nx.png", "py.png", "ny.png", "pz.png", "nz.png"};
  for (int i = 0; i < 6; ++i) writeSolidPng(folder / names[i], 8, 8, {uint8_t(40 * i), 0, 0, 255});
  Environment env = parseIn(folder, R"({"type": "cube", "faces": ["px.png", "nx.png", "py.png",
      "ny.png", "pz.png", "nz.png"], "intensity": 0.5})")
                        .environment;
  ASSERT_EQ(env.kind, EnvironmentKind::CubeFaces);
  for (int i = 0; i < 6; ++i)
    EXPECT_NEAR(env.faces[i]->at(2, 2).r, srgbToLinear(float(40 * i) / 255.0f), 1e-4f);
  EXPECT_EQ(cubeResolution(env), 8u);
  EXPECT_FLOAT_EQ(env.intensity, 0.5f);
}

TEST(EnvironmentJson, MissingFileNamesFieldAndFile) {
  fs::path folder = testFolder();
  std::string message = errorIn(folder, R"({"type": "equirect", "file": "nowhere.hdr"})");
  EXPECT_THAT(message, HasSubstr((folder / "scene.json").string() + ": environment.file: image '" +
                                 (folder / "nowhere.hdr").string() + "' does not exist"));
  EXPECT_THAT(message, HasSubstr("expected an image file (JPEG, PNG, HDR or EXR)"));
}

TEST(EnvironmentJson, UnreadableFileNamesIt) {
  fs::path folder = testFolder();
  std::ofstream(folder / "broken.jpg") << "not a jpeg";
  EXPECT_THAT(
      errorIn(folder, R"({"type": "equirect", "file": "broken.jpg"})"),
      HasSubstr("environment.file: cannot read image '" + (folder / "broken.jpg").string()));
}

TEST(EnvironmentJson, CubeFaceErrors) {
  fs::path folder = testFolder();
  writeSolidPng(folder / "square.png", 8, 8, {0, 0, 0, 255});
  writeSolidPng(folder / "wide.png", 8, 4, {0, 0, 0, 255});
  writeSolidPng(folder / "big.png", 16, 16, {0, 0, 0, 255});
  EXPECT_THAT(errorIn(folder, R"({"type": "cube", "faces": ["square.png"]})"),
              HasSubstr("environment.faces: 1 files, expected an array of 6 image files in the "
                        "order +x, -x, +y, -y, +z, -z"));
  EXPECT_THAT(errorIn(folder, R"({"type": "cube", "faces": ["square.png", "square.png",
      "wide.png", "square.png", "square.png", "square.png"]})"),
              HasSubstr("environment.faces[2]: the face is 8x4, expected a square image"));
  EXPECT_THAT(errorIn(folder, R"({"type": "cube", "faces": ["square.png", "square.png",
      "square.png", "square.png", "square.png", "big.png"]})"),
              HasSubstr("environment.faces[5]: the face is 16 texels wide but the first is 8"));
  EXPECT_THAT(errorIn(folder, R"({"type": "cube", "faces": ["square.png", "square.png",
      "square.png", "square.png", "square.png", "gone.png"]})"),
              HasSubstr("environment.faces[5]: image '" + (folder / "gone.png").string() +
                        "' does not exist"));
}

TEST(EnvironmentJson, FieldErrors) {
  fs::path folder = testFolder();
  EXPECT_THAT(errorIn(folder, R"("sky")"),
              HasSubstr("environment: expected an object with a \"type\", got \"sky\""));
  EXPECT_THAT(errorIn(folder, R"({"type": "spherical"})"),
              HasSubstr("environment.type: unknown environment type \"spherical\""));
  EXPECT_THAT(errorIn(folder, R"({"zenith": 1})"), HasSubstr("environment.type: missing"));
  EXPECT_THAT(errorIn(folder, R"({"type": "sky", "file": "a.png"})"),
              HasSubstr("environment.file: unknown field"));
  EXPECT_THAT(errorIn(folder, R"({"type": "sky", "resolution": 100})"),
              HasSubstr("environment.resolution: 100 is not a power of two"));
  EXPECT_THAT(errorIn(folder, R"({"type": "sky", "resolution": 4096})"),
              HasSubstr("environment.resolution"));
  EXPECT_THAT(errorIn(folder, R"({"type": "sky", "sun_direction": [0, 0, 0]})"),
              HasSubstr("environment.sun_direction: zero-length direction"));
  EXPECT_THAT(errorIn(folder, R"({"type": "sky", "sun_size": 120})"),
              HasSubstr("environment.sun_size: 120 degrees is out of range"));
  EXPECT_THAT(errorIn(folder, R"({"type": "sky", "intensity": -1})"),
              HasSubstr("environment.intensity: -1 is negative"));
  EXPECT_THAT(errorIn(folder, R"({"type": "equirect"})"),
              HasSubstr("environment.file: missing, expected an image file"));
  EXPECT_THAT(errorIn(folder, R"({"type": "equirect", "file": 3})"),
              HasSubstr("environment.file: expected an image file"));
}

}  // namespace
}  // namespace shadelab
