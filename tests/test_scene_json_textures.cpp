// The texture fields of JSON materials: files relative to the scene file
// (colour sRGB, data linear, each loaded once), procedural generators, the
// sampler, bump scale and UV mapping, and every error naming its field and,
// for files, the file and the material.
#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/base/errors.h"
#include "core/scene/procedural_textures.h"
#include "core/scene/scene_json.h"

namespace shadelab {
namespace {

namespace fs = std::filesystem;
using testing::AllOf;
using testing::HasSubstr;

// A folder holding a scene file and a 2x2 PNG beside it.
fs::path sceneDir() {
  static fs::path dir = [] {
    // Per process: two suites of this file run at once under ctest -j and
    // must not write the same texture while the other reads it.
    fs::path path = fs::path(testing::TempDir()) /
                    ("shadelab-json-textures-" + std::to_string(getpid()));
    fs::create_directories(path / "maps");
    auto out = OIIO::ImageOutput::create("png");
    std::vector<uint8_t> texels = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
    out->open((path / "maps" / "tile.png").string(),
              OIIO::ImageSpec(2, 2, 3, OIIO::TypeDesc::UINT8));
    out->write_image(OIIO::TypeDesc::UINT8, texels.data());
    out->close();
    return path;
  }();
  static const struct RemoveAtExit {
    ~RemoveAtExit() {
      std::error_code error;
      fs::remove_all(dir, error);
    }
  } removeAtExit;
  return dir;
}

Scene load(const std::string& materialFields) {
  fs::path file = sceneDir() / "scene.json";
  std::ofstream(file)
      << R"({"materials": {"brick": {)" << materialFields
      << R"(}}, "objects": [{"name": "wall", "shape": "plane", "material": "brick"}]})";
  return loadSceneJson(file);
}

std::string errorOf(const std::string& materialFields) {
  try {
    load(materialFields);
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no InputError thrown)";
}

TEST(SceneJsonTextures, FileMapsLoadRelativeToTheSceneOnceEachAsColourOrData) {
  Scene scene = load(R"("diffuse_map": "maps/tile.png", "height_map": "maps/tile.png",
                        "normal_map": "maps/tile.png", "bump_scale": 0.5)");
  const Material& material = scene.objects[0].material;
  ASSERT_EQ(scene.textures.size(), 2u);  // colour once, data once (shared by normal and height)
  EXPECT_TRUE(scene.textures[size_t(material.diffuseMap.texture)].srgb);
  EXPECT_FALSE(scene.textures[size_t(material.heightMap.texture)].srgb);
  EXPECT_EQ(material.normalMap.texture, material.heightMap.texture);
  EXPECT_EQ(scene.textures[0].width, 2u);
  EXPECT_EQ(scene.textures[0].rgba8[0], 255);
  EXPECT_EQ(material.bumpScale, 0.5f);
}

TEST(SceneJsonTextures, ProceduralMapsMatchTheGenerators) {
  Scene scene = load(R"("diffuse_map": {"procedural": "checker", "size": 16, "repeats": 2,
                                        "colors": [0, [1, 1, 1]]},
                        "normal_map": {"procedural": "dimples", "size": 32, "depth": 2},
                        "height_map": {"procedural": "waves", "size": 8, "repeats": 1})");
  const Material& material = scene.objects[0].material;
  const Texture& diffuse = scene.textures[size_t(material.diffuseMap.texture)];
  EXPECT_EQ(diffuse.width, 16u);
  EXPECT_EQ(diffuse.rgba8[0], 255);    // the first check is the high colour
  EXPECT_EQ(diffuse.rgba8[8 * 4], 0);  // the next check along the row is low
  HeightField dimples = proceduralHeight({HeightPattern::Dimples, 32, 8});
  EXPECT_EQ(scene.textures[size_t(material.normalMap.texture)].rgba8,
            normalMapTexture(dimples, 2.0f, "").rgba8);
  HeightField waves = proceduralHeight({HeightPattern::Waves, 8, 1});
  EXPECT_EQ(scene.textures[size_t(material.heightMap.texture)].rgba8,
            heightMapTexture(waves, "").rgba8);
}

TEST(SceneJsonTextures, SamplerUvMappingAndScale) {
  Scene scene = load(R"("diffuse_map": {"procedural": "checker"},
                        "sampler": {"wrap_u": "clamp_to_edge", "wrap_v": "mirrored_repeat",
                                    "filter": "aniso", "anisotropy": 4},
                        "uv_mapping": "spherical", "uv_scale": [4, 2])");
  const Material& material = scene.objects[0].material;
  EXPECT_EQ(material.diffuseMap.sampler.wrapU, TextureWrap::ClampToEdge);
  EXPECT_EQ(material.diffuseMap.sampler.wrapV, TextureWrap::MirroredRepeat);
  EXPECT_EQ(material.diffuseMap.sampler.filter, TextureFilter::Anisotropic);
  EXPECT_EQ(material.diffuseMap.sampler.maxAnisotropy, 4.0f);
  EXPECT_EQ(material.normalMap.sampler, material.diffuseMap.sampler);
  EXPECT_EQ(material.uvProjection, UvProjection::Spherical);
  EXPECT_EQ(material.uvScale, glm::vec2(4.0f, 2.0f));
  EXPECT_EQ(load(R"("uv_scale": 3)").objects[0].material.uvScale, glm::vec2(3.0f));
}

TEST(SceneJsonTextures, DefaultsWithoutTextureFields) {
  Scene scene = load(R"("kd": 0.5)");
  const Material& material = scene.objects[0].material;
  EXPECT_TRUE(scene.textures.empty());
  EXPECT_FALSE(material.diffuseMap.present());
  EXPECT_EQ(material.diffuseMap.sampler.filter, TextureFilter::Trilinear);
  EXPECT_EQ(material.uvProjection, UvProjection::Mesh);
  EXPECT_EQ(material.bumpScale, 1.0f);
}

TEST(SceneJsonTextures, MissingFileNamesTheFileAndTheMaterial) {
  EXPECT_THAT(errorOf(R"("diffuse_map": "maps/nothing.png")"),
              AllOf(HasSubstr("scene.json: materials.brick.diffuse_map"),
                    HasSubstr((sceneDir() / "maps" / "nothing.png").string()),
                    HasSubstr("does not exist"), HasSubstr("material 'brick'")));
  fs::path garbage = sceneDir() / "maps" / "garbage.png";
  std::ofstream(garbage) << "not a png";
  EXPECT_THAT(errorOf(R"("normal_map": "maps/garbage.png")"),
              AllOf(HasSubstr("materials.brick.normal_map"), HasSubstr(garbage.string()),
                    HasSubstr("cannot be read"), HasSubstr("material 'brick'")));
}

TEST(SceneJsonTextures, InlineMaterialErrorsNameTheObject) {
  fs::path file = sceneDir() / "inline.json";
  std::ofstream(file) << R"({"objects": [{"name": "ball", "shape": "sphere",
                              "material": {"height_map": "gone.png"}}]})";
  try {
    loadSceneJson(file);
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(),
                AllOf(HasSubstr("objects[0].material.height_map"), HasSubstr("gone.png"),
                      HasSubstr("the material of object 'ball'")));
  }
}

struct TextureErrorCase {
  const char* fields;
  const char* message;
};

class SceneJsonTextureError : public testing::TestWithParam<TextureErrorCase> {};

TEST_P(SceneJsonTextureError, NamesTheFieldAndTheProblem) {
  EXPECT_THAT(errorOf(GetParam().fields), HasSubstr(GetParam().message));
}

const TextureErrorCase kTextureErrors[] = {
    {R"("diffuse_map": 3)", "materials.brick.diffuse_map: expected an image file name"},
    {R"("diffuse_map": {"procedural": "marble"})",
     "materials.brick.diffuse_map.procedural: unknown generator \"marble\""},
    {R"("diffuse_map": {"size": 4})", "materials.brick.diffuse_map.procedural: missing"},
    {R"("height_map": {"procedural": "waves", "colors": [0, 1]})",
     "materials.brick.height_map.colors: unknown field \"colors\""},
    {R"("normal_map": {"procedural": "waves", "size": 0})",
     "materials.brick.normal_map.size: 0 is out of range"},
    {R"("diffuse_map": {"procedural": "checker", "colors": [0]})",
     "materials.brick.diffuse_map.colors: expected two colours"},
    {R"("bump_scale": -1)", "materials.brick.bump_scale"},
    {R"("sampler": {"filter": "cubic"})", "materials.brick.sampler.filter: unknown filter"},
    {R"("sampler": {"wrap_u": "clamp"})", "materials.brick.sampler.wrap_u: unknown wrap mode"},
    {R"("sampler": {"wrap": "repeat"})", "materials.brick.sampler.wrap: unknown field \"wrap\""},
    {R"("sampler": {"filter": "aniso", "anisotropy": 32})",
     "materials.brick.sampler.anisotropy: anisotropy 32 is out of range"},
    {R"("sampler": {"anisotropy": 4})", "anisotropy without \"filter\": \"aniso\""},
    {R"("uv_mapping": "cubic")", "materials.brick.uv_mapping: unknown uv mapping"},
    {R"("uv_scale": [1, 0])", "materials.brick.uv_scale[1]"},
    {R"("uv_scale": [1, 2, 3])", "materials.brick.uv_scale: expected a number or [u, v]"},
    {R"("diffuse": "a.png")", "materials.brick.diffuse: unknown field \"diffuse\""},
};

INSTANTIATE_TEST_SUITE_P(Validation, SceneJsonTextureError, testing::ValuesIn(kTextureErrors));

}  // namespace
}  // namespace shadelab
