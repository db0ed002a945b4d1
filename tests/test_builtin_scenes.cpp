// The built-in scenes are JSON files (assets/scenes/<name>.json) embedded in
// the binary: each file on disk must load to exactly the Scene the embedded
// copy gives (every mesh vertex, matrix entry and texel compared with ==),
// they must need no other file (a copy printed by `shadelab scenes --print`
// renders from any folder), and the constants other code keeps about them
// must agree with their files.
#define GLM_ENABLE_EXPERIMENTAL  // glm/gtx/string_cast.hpp is "experimental"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <glm/gtx/string_cast.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/base/errors.h"
#include "core/scene/scene.h"
#include "core/scene/scene_json.h"

namespace shadelab {
namespace {

using testing::HasSubstr;
using testing::IsEmpty;

// Collects "path: a vs b" for every field that differs, so a failure names them all.
class SceneDiff {
 public:
  template <typename T>
  void field(const std::string& path, const T& a, const T& b) {
    if (a == b) return;
    std::ostringstream line;
    line << path << ": " << text(a) << " vs " << text(b);
    differences.push_back(line.str());
  }
  // Same length first, then each element by `compare(path, a[i], b[i])`.
  template <typename T, typename Compare>
  void list(const std::string& path, const std::vector<T>& a, const std::vector<T>& b,
            Compare compare) {
    field(path + ".size()", a.size(), b.size());
    for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
      compare(path + "[" + std::to_string(i) + "]", a[i], b[i]);
  }
  std::vector<std::string> differences;

 private:
  template <typename T>
  static std::string text(const T& value) {
    if constexpr (std::is_enum_v<T>) {
      return std::to_string(int(value));
    } else if constexpr (std::is_same_v<T, std::string>) {
      return "\"" + value + "\"";
    } else if constexpr (std::is_arithmetic_v<T>) {
      std::ostringstream out;
      out.precision(9);
      out << value;
      return out.str();
    } else if constexpr (std::is_same_v<T, glm::vec2> || std::is_same_v<T, glm::vec3> ||
                         std::is_same_v<T, glm::mat4>) {
      return glm::to_string(value);
    } else {
      return "(differs)";
    }
  }
};

void compareCamera(SceneDiff& diff, const Camera& a, const Camera& b) {
  diff.field("camera.eye", a.eye, b.eye);
  diff.field("camera.at", a.at, b.at);
  diff.field("camera.up", a.up, b.up);
  diff.field("camera.projection", a.projection, b.projection);
  diff.field("camera.fovy", a.fovyDegrees, b.fovyDegrees);
  diff.field("camera.near", a.near, b.near);
  diff.field("camera.far", a.far, b.far);
  diff.field("camera.left", a.left, b.left);
  diff.field("camera.right", a.right, b.right);
  diff.field("camera.bottom", a.bottom, b.bottom);
  diff.field("camera.top", a.top, b.top);
}

void compareMaterial(SceneDiff& diff, const std::string& path, const Material& a,
                     const Material& b) {
  diff.field(path + ".ka", a.ka, b.ka);
  diff.field(path + ".kd", a.kd, b.kd);
  diff.field(path + ".ks", a.ks, b.ks);
  diff.field(path + ".shininess", a.shininess, b.shininess);
  diff.field(path + ".reflectivity", a.reflectivity, b.reflectivity);
  diff.field(path + ".transparency", a.transparency, b.transparency);
  diff.field(path + ".ior", a.ior, b.ior);
  diff.field(path + ".emissive", a.emissive, b.emissive);
  auto slot = [&](const std::string& name, const TextureSlot& x, const TextureSlot& y) {
    diff.field(path + "." + name + ".texture", x.texture, y.texture);
    diff.field(path + "." + name + ".sampler", x.sampler, y.sampler);
  };
  slot("diffuseMap", a.diffuseMap, b.diffuseMap);
  slot("normalMap", a.normalMap, b.normalMap);
  slot("heightMap", a.heightMap, b.heightMap);
  diff.field(path + ".bumpScale", a.bumpScale, b.bumpScale);
  diff.field(path + ".uvProjection", a.uvProjection, b.uvProjection);
  diff.field(path + ".uvScale", a.uvScale, b.uvScale);
}

std::vector<std::string> sceneDifferences(const Scene& a, const Scene& b) {
  SceneDiff diff;
  diff.field("name", a.name, b.name);
  diff.field("description", a.description, b.description);
  compareCamera(diff, a.camera, b.camera);
  diff.field("ambient", a.ambient, b.ambient);
  diff.field("background", a.background, b.background);
  diff.field("environment", a.environment, b.environment);
  diff.list("lights", a.lights, b.lights, [&](const std::string& path, auto& x, auto& y) {
    diff.field(path + ".type", x.type, y.type);
    diff.field(path + ".position", x.position, y.position);
    diff.field(path + ".direction", x.direction, y.direction);
    diff.field(path + ".intensity", x.intensity, y.intensity);
    diff.field(path + ".attenuation", x.attenuation, y.attenuation);
  });
  diff.list("shapes", a.shapes, b.shapes, [&](const std::string& path, auto& x, auto& y) {
    diff.field(path + ".kind", x.kind, y.kind);
    diff.field(path + ".size", x.size, y.size);
    diff.field(path + ".halfExtents", x.halfExtents, y.halfExtents);
    diff.field(path + ".radius", x.radius, y.radius);
    diff.field(path + ".majorRadius", x.majorRadius, y.majorRadius);
    diff.field(path + ".minorRadius", x.minorRadius, y.minorRadius);
    diff.field(path + ".tessellation", x.tessellation, y.tessellation);
    diff.field(path + ".creaseAngle", x.creaseAngleDegrees, y.creaseAngleDegrees);
  });
  diff.list("meshes", a.meshes, b.meshes, [&](const std::string& path, auto& x, auto& y) {
    diff.field(path + ".indices", x.indices, y.indices);
    diff.field(path + ".vertices.size()", x.vertices.size(), y.vertices.size());
    bool same =
        x.vertices.size() == y.vertices.size() &&
        std::memcmp(x.vertices.data(), y.vertices.data(), x.vertices.size() * sizeof(Vertex)) == 0;
    diff.field(path + ".vertices (bytes)", same, true);
  });
  diff.list("objects", a.objects, b.objects, [&](const std::string& path, auto& x, auto& y) {
    diff.field(path + ".name", x.name, y.name);
    diff.field(path + ".mesh", x.mesh, y.mesh);
    diff.field(path + ".transform", x.transform, y.transform);
    compareMaterial(diff, path + ".material", x.material, y.material);
  });
  diff.list("billboards", a.billboards, b.billboards,
            [&](const std::string& path, auto& x, auto& y) {
              diff.field(path + ".name", x.name, y.name);
              diff.field(path + ".kind", x.kind, y.kind);
              diff.field(path + ".anchor", x.anchor, y.anchor);
              diff.field(path + ".alpha", x.alpha, y.alpha);
              diff.field(path + ".size", x.size, y.size);
              diff.field(path + ".axis", x.axis, y.axis);
              diff.field(path + ".instances", x.instances, y.instances);
              compareMaterial(diff, path + ".material", x.material, y.material);
            });
  diff.list("textures", a.textures, b.textures, [&](const std::string& path, auto& x, auto& y) {
    diff.field(path + ".name", x.name, y.name);
    diff.field(path + ".width", x.width, y.width);
    diff.field(path + ".height", x.height, y.height);
    diff.field(path + ".srgb", x.srgb, y.srgb);
    diff.field(path + ".rgba8", x.rgba8, y.rgba8);
  });
  return diff.differences;
}

std::filesystem::path sceneFile(const std::string& name) {
  return std::filesystem::path(SHADELAB_ASSET_DIR) / "scenes" / (name + ".json");
}

TEST(BuiltinScenes, TheThirteenScenesOfTheCommandLine) {
  EXPECT_THAT(
      builtinSceneNames(),
      testing::ElementsAre("bump", "default", "dense", "env", "highlight", "lod", "mip-plane",
                           "shadows", "spheres", "teapot", "trees", "whitted", "zfight"));
}

TEST(BuiltinScenes, EachFileInAssetsLoadsToTheEmbeddedScene) {
  for (const std::string& name : builtinSceneNames()) {
    SCOPED_TRACE(name);
    Scene fromFile = loadSceneJson(sceneFile(name));
    Scene embedded = builtinScene(name);
    EXPECT_EQ(embedded.name, name);
    EXPECT_GT(embedded.triangleCount(), 0u);
    EXPECT_THAT(sceneDifferences(fromFile, embedded), IsEmpty());
  }
}

// What `shadelab scenes --print NAME > copy.json` writes parses to the same scene.
TEST(BuiltinScenes, PrintedTextParsesToTheSameScene) {
  for (const std::string& name : builtinSceneNames()) {
    SCOPED_TRACE(name);
    Scene copy = parseSceneJson(builtinSceneJson(name), "copy/" + name + ".json");
    EXPECT_THAT(sceneDifferences(copy, builtinScene(name)), IsEmpty());
  }
}

// No texture, panorama or glTF file: a printed copy renders the same from any folder.
TEST(BuiltinScenes, NeedNoOtherFile) {
  for (const std::string& name : builtinSceneNames()) {
    SCOPED_TRACE(name);
    Scene scene = builtinScene(name);
    EXPECT_TRUE(scene.environment.kind == EnvironmentKind::None ||
                scene.environment.kind == EnvironmentKind::Sky);
    for (const ShapeDesc& shape : scene.shapes) EXPECT_NE(shape.kind, ShapeKind::Custom);
    for (const Texture& texture : scene.textures)
      EXPECT_THAT(texture.name, testing::StartsWith("procedural "));
  }
}

TEST(BuiltinScenes, EachHasOneLineDescription) {
  for (const std::string& name : builtinSceneNames()) {
    SCOPED_TRACE(name);
    std::string description = builtinSceneDescription(name);
    EXPECT_FALSE(description.empty());
    EXPECT_EQ(description.find('\n'), std::string::npos);
    EXPECT_LE(description.size(), 90u) << "a line in `shadelab scenes` beside the name";
    EXPECT_EQ(builtinScene(name).description, description);
  }
}

TEST(BuiltinScenes, UnknownNameIsAnInputErrorListingTheNames) {
  for (auto lookup : {+[] { builtinSceneJson("no-such"); }, +[] { builtinScene("no-such"); },
                      +[] { builtinSceneDescription("no-such"); }}) {
    try {
      lookup();
      ADD_FAILURE() << "no InputError";
    } catch (const InputError& error) {
      EXPECT_THAT(error.what(), HasSubstr("'no-such'"));
      EXPECT_THAT(error.what(), HasSubstr("bump, default, dense"));
    }
  }
}

// measure/zfight.cpp counts the pixels of each plane's colour and reports the gap.
TEST(BuiltinScenes, ZFightFileAgreesWithItsConstants) {
  Scene scene = zfightScene(Projection::Orthographic, 2.0f);
  EXPECT_EQ(scene.camera.projection, Projection::Orthographic);
  EXPECT_EQ(scene.camera.near, 2.0f);
  ASSERT_EQ(scene.objects.size(), 2u);
  const Object& far = scene.objects[0];
  const Object& near = scene.objects[1];
  EXPECT_EQ(far.material.kd, kZFightFarColor);
  EXPECT_EQ(near.material.kd, kZFightNearColor);
  EXPECT_EQ(far.transform[3].y - near.transform[3].y, -kZFightGap);
  EXPECT_EQ(far.mesh, near.mesh);
  EXPECT_EQ(scene.background, glm::vec3(0.0f));
  Scene file = builtinScene("zfight");
  EXPECT_EQ(file.camera.projection, Projection::Perspective);
  EXPECT_EQ(file.camera.near, 0.1f);
}

TEST(BuiltinScenes, HighlightVariantOnlyCutsThePlane) {
  Scene base = builtinScene("highlight");
  Scene cut = highlightScene(4);
  EXPECT_EQ(base.meshes[0].triangleCount(), 2u);
  EXPECT_EQ(cut.meshes[0].triangleCount(), 32u);
  cut.shapes[0].tessellation = 1;
  cut.meshes[0] = base.meshes[0];
  EXPECT_THAT(sceneDifferences(cut, base), IsEmpty());
}

}  // namespace
}  // namespace shadelab
