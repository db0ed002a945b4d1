// The glTF loader on the hand-made files of tests/data (one feature each,
// written by tests/data/make_test_gltf.py), on the broken ones of
// tests/data/bad, and on every model of shared/assets.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/base/errors.h"
#include "core/scene/frustum.h"
#include "core/scene/gltf_loader.h"
#include "core/scene/scene_json.h"
#include "core/scene/scene_loader.h"
#include "core/scene/transform.h"
#include "shared_assets.h"

namespace shadelab {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

std::filesystem::path data(const std::string& name) {
  return std::filesystem::path(SHADELAB_TEST_DATA_DIR) / name;
}

std::string loadError(const std::filesystem::path& path) {
  try {
    loadScene(path.string());
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no error)";
}

void expectNear(const glm::mat4& actual, const glm::mat4& expected) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(actual[c][r], expected[c][r], 1e-5f) << c << "," << r;
}

glm::vec3 faceNormal(const Mesh& mesh, size_t triangle) {
  glm::vec3 a = mesh.vertices[mesh.indices[3 * triangle]].position;
  glm::vec3 b = mesh.vertices[mesh.indices[3 * triangle + 1]].position;
  glm::vec3 c = mesh.vertices[mesh.indices[3 * triangle + 2]].position;
  return glm::cross(b - a, c - a);
}

TEST(GltfLoader, ComposesTheNodeHierarchyAsAMatrixStack) {
  Scene scene = loadScene(data("hierarchy.gltf").string());  // embedded base64 buffer
  ASSERT_EQ(scene.objects.size(), 3u);
  glm::mat4 root = translation({10, 0, 0});
  glm::mat4 child = root * rotationZ(glm::radians(90.0f)) * scaling(glm::vec3(2.0f));
  glm::mat4 grandchild = child * translation({0, 0, 5});
  expectNear(scene.objects[0].transform, root);
  expectNear(scene.objects[1].transform, child);
  expectNear(scene.objects[2].transform, grandchild);
  // One mesh shared by the three nodes; vertex (1, 0, 0) of the child lands
  // at (10, 2, 0): scaled to 2, turned onto +y, moved by the root.
  EXPECT_EQ(scene.meshes.size(), 1u);
  glm::vec4 moved = scene.objects[1].transform * glm::vec4(1, 0, 0, 1);
  EXPECT_NEAR(glm::distance(glm::vec3(moved), glm::vec3(10, 2, 0)), 0.0f, 1e-5f);
}

TEST(GltfLoader, NonIndexedPrimitiveFromAnExternalBufferGetsFlatNormals) {
  Scene scene = loadScene(data("non_indexed.gltf").string());
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& mesh = scene.meshes[0];
  EXPECT_EQ(mesh.triangleCount(), 2u);
  EXPECT_EQ(mesh.vertices.size(), 4u);  // the 6 listed vertices, duplicates merged
  for (const Vertex& vertex : mesh.vertices) EXPECT_EQ(vertex.normal, glm::vec3(0, 0, 1));
  for (size_t t = 0; t < 2; ++t) EXPECT_GT(faceNormal(mesh, t).z, 0.0f);
}

TEST(GltfLoader, StripsAndFansBecomeCounterClockwiseTrianglesAndLinesAreSkipped) {
  Scene scene = loadScene(data("strip_fan.gltf").string());
  ASSERT_EQ(scene.objects.size(), 2u);  // the third primitive draws lines
  const Mesh& strip = scene.meshes[scene.objects[0].mesh];
  const Mesh& fan = scene.meshes[scene.objects[1].mesh];
  EXPECT_EQ(strip.triangleCount(), 2u);
  EXPECT_EQ(fan.triangleCount(), 3u);
  // Every triangle faces +z, as the strip and fan were laid out: the strip's
  // alternating order keeps the winding.
  for (const Mesh* mesh : {&strip, &fan})
    for (size_t t = 0; t < mesh->triangleCount(); ++t)
      EXPECT_NEAR(faceNormal(*mesh, t).z, 1.0f, 1e-6f) << t;  // each has area 1/2
  // The fan's triangles all share its first vertex, (0, 0, 1).
  for (size_t t = 0; t < fan.triangleCount(); ++t) {
    bool hasCentre = false;
    for (int k = 0; k < 3; ++k)
      hasCentre |= fan.vertices[fan.indices[3 * t + k]].position == glm::vec3(0, 0, 1);
    EXPECT_TRUE(hasCentre) << t;
  }
}

TEST(GltfLoader, TexturesSamplersAndTheMaterialFormula) {
  Scene scene = loadScene(data("textured.gltf").string());
  ASSERT_EQ(scene.objects.size(), 1u);
  const Material& material = scene.objects[0].material;
  ASSERT_EQ(scene.textures.size(), 2u);
  ASSERT_TRUE(material.diffuseMap.present());
  const Texture& colour = scene.textures[size_t(material.diffuseMap.texture)];
  EXPECT_EQ(colour.width, 2u);
  EXPECT_EQ(colour.height, 2u);
  EXPECT_TRUE(colour.srgb);
  EXPECT_EQ(colour.rgba8, (std::vector<uint8_t>{255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255,
                                                255, 255, 255}));
  EXPECT_EQ(material.diffuseMap.sampler.wrapU, TextureWrap::ClampToEdge);
  EXPECT_EQ(material.diffuseMap.sampler.wrapV, TextureWrap::MirroredRepeat);
  EXPECT_EQ(material.diffuseMap.sampler.filter, TextureFilter::Nearest);
  ASSERT_TRUE(material.normalMap.present());
  const Texture& normal = scene.textures[size_t(material.normalMap.texture)];
  EXPECT_FALSE(normal.srgb);
  EXPECT_EQ(normal.rgba8, (std::vector<uint8_t>{128, 128, 255, 255}));
  EXPECT_EQ(material.normalMap.sampler, SamplerDesc{});  // no sampler: repeat, trilinear
  EXPECT_FLOAT_EQ(material.bumpScale, 0.5f);
  // baseColor 1, metallic 0, roughness 0.5: kd = ka = 1, ks = 0.04,
  // alpha = 0.25, n = 2 / alpha^2 - 2 = 30; BLEND with alpha 0.25.
  EXPECT_EQ(material.kd, glm::vec3(1.0f));
  EXPECT_EQ(material.ka, glm::vec3(1.0f));
  EXPECT_NEAR(material.ks.x, 0.04f, 1e-6f);
  EXPECT_NEAR(material.shininess, 30.0f, 1e-3f);
  EXPECT_NEAR(material.transparency, 0.75f, 1e-6f);
  EXPECT_NEAR(glm::distance(material.emissive, glm::vec3(0.1f, 0.2f, 0.3f)), 0.0f, 1e-6f);
  // glTF's v runs down the image, ours up: the corner at (0, 1, 0) with
  // glTF uv (0, 0), the image's first texel, has v = 1 here.
  for (const Vertex& vertex : scene.meshes[0].vertices)
    EXPECT_EQ(vertex.uv, glm::vec2(vertex.position.x, vertex.position.y));
  // The normal map needs tangents the file lacks: generated along +u (x),
  // perpendicular to the normal, unmirrored (the bitangent along +v is +y).
  for (const Vertex& vertex : scene.meshes[0].vertices) {
    EXPECT_NEAR(glm::distance(glm::vec3(vertex.tangent), glm::vec3(1, 0, 0)), 0.0f, 1e-5f);
    EXPECT_EQ(vertex.tangent.w, 1.0f);
  }
}

// alphaMode MASK keeps the cut-off and the factor's alpha (not translucent);
// doubleSided is kept per material; KHR_texture_transform per texture, and
// its texCoord override picks the TEXCOORD set the vertices get.
TEST(GltfLoader, AlphaMaskDoubleSidedAndTextureTransform) {
  Scene masked = loadScene(data("alpha_mask.gltf").string());
  ASSERT_EQ(masked.objects.size(), 2u);
  EXPECT_EQ(masked.objects[0].material.alphaCutoff, 0.0f);  // OPAQUE: no test
  EXPECT_FLOAT_EQ(masked.objects[1].material.alphaCutoff, 0.5f);
  EXPECT_FLOAT_EQ(masked.objects[1].material.alpha, 1.0f);
  EXPECT_EQ(masked.objects[1].material.transparency, 0.0f);
  Scene sided = loadScene(data("double_sided.gltf").string());
  ASSERT_EQ(sided.objects.size(), 2u);
  EXPECT_TRUE(sided.objects[0].material.doubleSided);
  EXPECT_FALSE(sided.objects[1].material.doubleSided);
  Scene moved = loadScene(data("texture_transform.gltf").string());
  ASSERT_EQ(moved.objects.size(), 3u);
  EXPECT_FALSE(moved.objects[0].material.diffuseMap.transform.identity());
  EXPECT_TRUE(moved.objects[0].material.normalMap.transform.identity());
  // The middle quad's TEXCOORD_0 is all (0, 0); TEXCOORD_1 spans the texture.
  const Mesh& middle = moved.meshes[moved.objects[1].mesh];
  glm::vec2 low(1.0f), high(0.0f);
  for (const Vertex& vertex : middle.vertices) {
    low = glm::min(low, vertex.uv);
    high = glm::max(high, vertex.uv);
  }
  EXPECT_EQ(low, glm::vec2(0.0f));
  EXPECT_EQ(high, glm::vec2(1.0f));
  EXPECT_TRUE(moved.objects[1].material.diffuseMap.present());
}

TEST(GltfLoader, MetalRoughnessAndEmissiveStrength) {
  // The hierarchy's triangles with a rough red metal that glows.
  std::ifstream in(data("hierarchy.gltf"));
  nlohmann::json document = nlohmann::json::parse(in);
  document["meshes"][0]["primitives"][0]["material"] = 0;
  document["materials"] = nlohmann::json::parse(R"([{
      "pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 0.5], "metallicFactor": 1,
                               "roughnessFactor": 1},
      "emissiveFactor": [1, 0.5, 0],
      "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4}}}])");
  std::string text = document.dump();
  Material material =
      parseGltfScene(std::vector<uint8_t>(text.begin(), text.end()), "metal").objects[0].material;
  EXPECT_EQ(material.kd, glm::vec3(0.0f));              // metals: no diffuse
  EXPECT_EQ(material.ks, glm::vec3(1.0f, 0.0f, 0.0f));  // ks = baseColor
  EXPECT_EQ(material.shininess, 1.0f);                  // 2 / 1 - 2 = 0, clamped to 1
  EXPECT_EQ(material.transparency, 0.0f);               // OPAQUE ignores alpha
  EXPECT_EQ(material.emissive, glm::vec3(4.0f, 2.0f, 0.0f));
}

TEST(GltfLoader, PunctualLightsAndAnOrthographicCamera) {
  Scene scene = loadScene(data("lights_camera.gltf").string());
  ASSERT_EQ(scene.lights.size(), 3u);
  const Light& point = scene.lights[0];
  EXPECT_EQ(point.type, LightType::Point);
  EXPECT_NEAR(glm::distance(point.position, glm::vec3(0, 3, 0)), 0.0f, 1e-6f);
  EXPECT_EQ(point.intensity, glm::vec3(20.0f, 10.0f, 5.0f));  // colour x candela
  EXPECT_EQ(point.attenuation, glm::vec3(0, 0, 1));           // 1 / d^2
  const Light& sun = scene.lights[1];
  EXPECT_EQ(sun.type, LightType::Directional);  // local -z turned -90 degrees about x
  EXPECT_NEAR(glm::distance(sun.direction, glm::vec3(0, -1, 0)), 0.0f, 1e-6f);
  EXPECT_EQ(sun.intensity, glm::vec3(2.0f));
  EXPECT_EQ(scene.lights[2].type, LightType::Point);  // the spot, cone not modelled
  EXPECT_NEAR(glm::distance(scene.lights[2].position, glm::vec3(1, 1, 1)), 0.0f, 1e-6f);
  const Camera& camera = scene.camera;
  EXPECT_EQ(camera.projection, Projection::Orthographic);
  EXPECT_EQ(camera.eye, glm::vec3(0, 0, 5));
  EXPECT_EQ(camera.at, glm::vec3(0, 0, 4));
  EXPECT_EQ(camera.up, glm::vec3(0, 1, 0));
  EXPECT_EQ(glm::vec4(camera.left, camera.right, camera.bottom, camera.top),
            glm::vec4(-2, 2, -1.5, 1.5));
  EXPECT_EQ(glm::vec2(camera.near, camera.far), glm::vec2(0.5, 20));
}

TEST(GltfLoader, PerspectiveCameraWithoutFarPlane) {
  std::ifstream in(data("lights_camera.gltf"));
  nlohmann::json document = nlohmann::json::parse(in);
  document["cameras"][0] = {{"type", "perspective"},
                            {"perspective", {{"yfov", 0.5}, {"znear", 0.25}}}};
  std::string text = document.dump();
  std::vector<uint8_t> bytes(text.begin(), text.end());
  Camera camera = parseGltfScene(bytes, "perspective.gltf").camera;
  EXPECT_EQ(camera.projection, Projection::Perspective);
  EXPECT_NEAR(camera.fovyDegrees, glm::degrees(0.5f), 1e-4f);
  EXPECT_EQ(camera.near, 0.25f);
  EXPECT_EQ(camera.far, 2500.0f);  // none given: 10^4 near
}

// Numbers and names the spec bounds, refused with the field named when a
// file breaks them (they used to be drawn: a 1e300 light as a white frame,
// a light of type "laser" as a point light, a wrap mode of 1234 as repeat);
// each file is loaded unchanged first, so only the one edit fails it.
TEST(GltfLoader, OutOfSpecLightsSamplersAndFactorsAreRefused) {
  auto parsed = [](const std::string& file) {
    std::ifstream in(data(file));
    return nlohmann::json::parse(in);
  };
  auto errorOf = [](const nlohmann::json& document) {
    std::string text = document.dump();
    try {
      parseGltfScene(std::vector<uint8_t>(text.begin(), text.end()), "edited.gltf");
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("loaded");
  };
  const nlohmann::json lights = parsed("lights_camera.gltf");
  const nlohmann::json textured = parsed("textured.gltf");
  ASSERT_EQ(errorOf(lights), "loaded");
  ASSERT_EQ(errorOf(textured), "loaded");
  nlohmann::json edited = lights;
  edited["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = 1e300;
  EXPECT_THAT(errorOf(edited),
              HasSubstr("edited.gltf: extensions.KHR_lights_punctual.lights[0]"
                        ".intensity: 1e+300; expected a number from 0 to 1000000"));
  edited = lights;
  edited["cameras"][0] = {{"type", "perspective"},
                          {"perspective", {{"yfov", 1e-10}, {"znear", 0.25}}}};
  EXPECT_THAT(errorOf(edited), AllOf(HasSubstr("edited.gltf: cameras[0]: fovy "),
                                     HasSubstr("degrees is too narrow, expected 0.001 to 180")));
  edited = lights;
  edited["extensions"]["KHR_lights_punctual"]["lights"][1]["type"] = "laser";
  EXPECT_THAT(errorOf(edited), HasSubstr("lights[1].type: 'laser'; expected directional, point "
                                         "or spot"));
  edited = textured;
  edited["samplers"][0]["wrapS"] = 1234;
  EXPECT_THAT(errorOf(edited), HasSubstr("samplers[0].wrapS: 1234; expected 33071"));
  edited = textured;
  edited["samplers"][0]["minFilter"] = 1;
  EXPECT_THAT(errorOf(edited), HasSubstr("samplers[0].minFilter: 1; expected 9728"));
  edited = textured;
  edited["materials"][0]["normalTexture"]["scale"] = 1e300;
  EXPECT_THAT(errorOf(edited), HasSubstr("materials[0].normalTexture.scale: 1e+300; expected a "
                                         "finite number"));
  edited = textured;
  edited["materials"][0]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = -2;
  edited["extensionsUsed"] = {"KHR_materials_emissive_strength"};
  EXPECT_THAT(errorOf(edited), HasSubstr("emissiveStrength: -2; expected a number from 0 to "
                                         "1000000"));
  edited["materials"][0]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = 1e7;
  EXPECT_THAT(errorOf(edited), HasSubstr("emissiveStrength: 1e+07; expected a number from 0"));
}

// Nodes share meshes, so a few kilobytes can place millions of objects:
// 1,000 nodes of a mesh of 300 primitives are 300,000, refused as they are
// placed (they used to be built first, gigabytes of them).
TEST(GltfLoader, FilesPlacingTooManyObjectsAreRefused) {
  std::ifstream in(data("hierarchy.gltf"));
  nlohmann::json document = nlohmann::json::parse(in);
  nlohmann::json primitive = document["meshes"][0]["primitives"][0];
  document["meshes"][0]["primitives"] = nlohmann::json::array();
  for (int p = 0; p < 300; ++p) document["meshes"][0]["primitives"].push_back(primitive);
  document["nodes"] = nlohmann::json::array();
  document["scenes"][0]["nodes"] = nlohmann::json::array();
  for (int n = 0; n < 1000; ++n) {
    document["nodes"].push_back({{"mesh", 0}});
    document["scenes"][0]["nodes"].push_back(n);
  }
  std::string text = document.dump();
  EXPECT_LT(text.size(), 200'000u);
  try {
    parseGltfScene(std::vector<uint8_t>(text.begin(), text.end()), "many.gltf");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("many.gltf: nodes[873]: the file's nodes place more than "
                                        "262144 objects"));
  }
}

TEST(GltfLoader, BinaryGlbLoads) {
  Scene scene = loadScene(data("triangle.glb").string());
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.triangleCount(), 1u);
}

// No camera: the view is framed on the bounding box (every corner of every
// object's box inside the frustum) and a directional key light is added.
TEST(GltfLoader, FramesAFileWithoutCameraAndLightsIt) {
  Scene scene = loadScene(data("hierarchy.gltf").string());
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].type, LightType::Directional);
  // From behind and above the camera: it travels into the view, downwards.
  EXPECT_GT(glm::dot(scene.lights[0].direction, scene.camera.at - scene.camera.eye), 0.0f);
  EXPECT_LT(glm::dot(scene.lights[0].direction, scene.camera.up), 0.0f);
  Frustum frustum =
      frustumFromMatrix(scene.camera.projectionMatrix(1.0f) * scene.camera.viewMatrix());
  Bounds box = sceneBounds(scene);
  for (int corner = 0; corner < 8; ++corner) {
    glm::vec3 p(corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                corner & 4 ? box.max.z : box.min.z);
    for (const Plane& plane : frustum.planes) EXPECT_GE(plane.signedDistance(p), 0.0f) << corner;
  }
}

struct BadFile {
  const char* file;
  const char* message;
};

class GltfBadInput : public ::testing::TestWithParam<BadFile> {};

TEST_P(GltfBadInput, IsAnInputErrorNamingTheFileAndTheProblem) {
  std::filesystem::path path = data(std::string("bad/") + GetParam().file);
  std::string message = loadError(path);
  EXPECT_THAT(message, HasSubstr(path.string() + ": "));
  EXPECT_THAT(message, HasSubstr(GetParam().message));
}

INSTANTIATE_TEST_SUITE_P(
    Files, GltfBadInput,
    ::testing::Values(
        BadFile{"truncated.glb",
                "invalid GLB: truncated, the header gives 788 bytes but the file has 394"},
        BadFile{"syntax_error.gltf", "parse error at line 73"},
        BadFile{"accessor_past_buffer.gltf", "POSITION (accessors[0]): 300 elements"},
        // Sizes whose arithmetic wraps 64 bits once passed the bounds checks
        // and read outside the buffer (ASan: heap-buffer-overflow).
        BadFile{"accessor_count_overflow.gltf",
                "6148914691236517206 elements from byte 0 need more than 2^64 bytes"},
        BadFile{"accessor_offset_overflow.gltf",
                "elements from byte 18446744073709551608 need more than 2^64 bytes"},
        BadFile{"bufferview_offset_overflow.gltf",
                "bufferViews[0] (byteOffset 18446744073709551615, byteLength 36) runs past the "
                "end of its buffer (78 bytes)"},
        BadFile{"missing_buffer.gltf", "does_not_exist.bin"},
        BadFile{"missing_image.gltf", "images[0] 'no_such_image.png'"},
        BadFile{"required_extension.gltf", "\"KHR_draco_mesh_compression\" is not supported"},
        BadFile{"zero_triangles.gltf", "meshes[0] primitives[0]: no triangles"},
        BadFile{"index_out_of_range.gltf", "index 7 at position 2 is out of range"},
        BadFile{"alpha_cutoff_negative.gltf",
                "materials[0].alphaCutoff: expected a number >= 0, got -0.5"},
        BadFile{"alpha_cutoff_not_a_number.gltf",
                "materials[0].alphaCutoff: expected a number >= 0, got \"half\""},
        BadFile{"texture_transform_infinite.gltf",
                "KHR_texture_transform.scale[0]: expected a finite number"},
        BadFile{"texture_transform_not_a_number.gltf",
                "KHR_texture_transform.rotation: expected a finite number"},
        BadFile{"texture_transform_1e999.gltf", "number overflow parsing '1e999'"}),
    [](const auto& info) {
      std::string name = info.param.file;
      name = name.substr(0, name.find('.'));
      std::replace(name.begin(), name.end(), '1', 'x');  // 1e999: gtest names are identifiers
      return name;
    });

// Every prefix of a valid GLB and of a valid .gltf is either a scene or an
// InputError: the loader never reads past what it was given.
TEST(GltfLoader, EveryTruncationIsAnErrorNotACrash) {
  for (const char* name : {"triangle.glb", "textured.gltf"}) {
    std::ifstream in(data(name), std::ios::binary);
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), {});
    // A .gltf is whole once its closing brace is there; trailing space is optional.
    size_t whole = bytes.size();
    while (whole > 0 && std::isspace(bytes[whole - 1])) --whole;
    size_t loaded = 0;
    for (size_t length = 0; length < whole; ++length) {
      try {
        parseGltfScene(std::span(bytes.data(), length), name);
        ++loaded;
      } catch (const InputError&) {
      }
    }
    EXPECT_EQ(loaded, 0u) << name;  // no proper prefix is a whole file
    EXPECT_NO_THROW(parseGltfScene(bytes, name)) << name;
  }
}

TEST(GltfInSceneJson, PlacesTheFileUnderTheObjectsTransform) {
  std::filesystem::path path = data("gltf_in_scene.json");
  Scene scene = loadScene(path.string());
  ASSERT_EQ(scene.objects.size(), 4u);  // a floor and the hierarchy's three triangles
  EXPECT_EQ(scene.lights.size(), 1u);   // the scene file's own; glTF lights are not added
  glm::mat4 placed = translation({0, 1, 0}) * scaling(glm::vec3(0.5f));
  expectNear(scene.objects[1].transform, placed * translation({10, 0, 0}));
}

TEST(GltfInSceneJson, AMissingFileNamesTheFieldAndTheResolvedPath) {
  std::string text = R"({"objects": [{"gltf": "nowhere.gltf"}]})";
  std::string source = (std::filesystem::path(SHADELAB_TEST_DATA_DIR) / "x.json").string();
  try {
    parseSceneJson(text, source);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("objects[0].gltf"));
    EXPECT_THAT(error.what(), HasSubstr(data("nowhere.gltf").string() + "' does not exist"));
  }
}

// The shared models (README of shared/assets gives their triangle counts).
TEST(SharedModels, EveryModelLoadsWithItsTriangleCount) {
  std::vector<std::filesystem::path> models = test::sharedModels();
  if (models.empty()) GTEST_SKIP() << "no models in " << test::sharedAssetsDir();
  const std::map<std::string, uint64_t> triangles = {
      {"teapot", 9128},   {"sphere", 4512},          {"torusknot", 2880},
      {"suzanne", 15744}, {"chinesedragon", 100960}, {"color_teapot_spheres", 11776},
      {"plane", 2}};
  for (const std::filesystem::path& model : models) {
    Scene scene = loadScene(model.string());
    EXPECT_FALSE(scene.objects.empty()) << model;
    auto expected = triangles.find(model.stem().string());
    if (expected != triangles.end()) {
      EXPECT_EQ(scene.triangleCount(), expected->second) << model;
    }
  }
}

TEST(SharedModels, CesiumManBringsItsEmbeddedJpegTexture) {
  std::filesystem::path path = test::sharedAssetsDir() / "models" / "CesiumMan.glb";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is absent";
  Scene scene = loadScene(path.string());
  ASSERT_EQ(scene.textures.size(), 1u);
  EXPECT_GT(scene.textures[0].width, 64u);
  EXPECT_EQ(scene.textures[0].rgba8.size(),
            size_t(scene.textures[0].width) * scene.textures[0].height * 4);
  EXPECT_TRUE(scene.objects[0].material.diffuseMap.present());
}

}  // namespace
}  // namespace shadelab
