// The JSON scene format: every field's value, the defaults, the transform order and the
// matrix stack, one test per validation error (message names the file, the JSON path and
// what was wrong), syntax error positions, and the example scenes in assets/scenes.

#define GLM_ENABLE_EXPERIMENTAL  // glm/gtx/string_cast.hpp is "experimental"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/gtx/string_cast.hpp>
#include <string>
#include <vector>

#include "core/base/errors.h"
#include "core/scene/scene_json.h"
#include "core/scene/scene_loader.h"
#include "core/scene/transform.h"
#include "test_folder.h"

namespace shadelab {
namespace {

using testing::AllOf;
using testing::HasSubstr;

constexpr float kTolerance = 1e-5f;

Scene parse(std::string_view text) {
  return parseSceneJson(text, "scene.json");
}

// The InputError message of `run`, or a marker that makes any HasSubstr expectation fail.
template <typename Function>
std::string errorFrom(Function run) {
  try {
    run();
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no InputError thrown)";
}

std::string errorOf(std::string_view text) {
  return errorFrom([&] { parse(text); });
}

testing::AssertionResult vec3Near(glm::vec3 actual, glm::vec3 expected) {
  if (glm::distance(actual, expected) <= kTolerance) return testing::AssertionSuccess();
  return testing::AssertionFailure()
         << glm::to_string(actual) << " vs " << glm::to_string(expected);
}

testing::AssertionResult mat4Near(const glm::mat4& actual, const glm::mat4& expected) {
  for (glm::length_t column = 0; column < 4; ++column)
    if (glm::distance(actual[column], expected[column]) > kTolerance)
      return testing::AssertionFailure()
             << glm::to_string(actual) << " vs " << glm::to_string(expected);
  return testing::AssertionSuccess();
}

glm::vec3 apply(const glm::mat4& m, glm::vec3 p) {
  return glm::vec3(m * glm::vec4(p, 1.0f));
}

const Object& objectNamed(const Scene& scene, const std::string& name) {
  for (const Object& object : scene.objects)
    if (object.name == name) return object;
  ADD_FAILURE() << "no object named " << name;
  static const Object none;
  return none;
}

// Compares every field, so a description also shows which fields kept their defaults.
testing::AssertionResult sameShape(const ShapeDesc& actual, const ShapeDesc& expected) {
  if (actual.kind == expected.kind && actual.size == expected.size &&
      actual.halfExtents == expected.halfExtents && actual.radius == expected.radius &&
      actual.majorRadius == expected.majorRadius && actual.minorRadius == expected.minorRadius &&
      actual.tessellation == expected.tessellation)
    return testing::AssertionSuccess();
  return testing::AssertionFailure() << "the " << shapeKindName(actual.kind) << " differs from the "
                                     << shapeKindName(expected.kind) << " expected";
}

constexpr const char* kFullScene = R"({
  "camera": {"eye": [1, 2, 3], "at": [0, 1, 0], "up": [0, 0, 1], "projection": "frustum",
             "fovy": 60, "near": 0.5, "far": 50, "left": -2, "right": 3, "bottom": -1.5, "top": 1},
  "ambient": 0.25, "background": [0.1, 0.2, 0.3],
  "lights": [{"type": "point", "position": [4, 5, 6], "intensity": [0.9, 0.8, 0.7],
              "attenuation": [1, 0.5, 0.25]},
             {"type": "directional", "direction": [0, -1, 0], "intensity": 0.5}],
  "materials": {
    "red": {"ka": [0.1, 0, 0], "kd": [0.8, 0.1, 0.1], "ks": 0.4, "shininess": 12},
    "dark wood": {"kd": 0.3},
    "glass": {"reflectivity": 0.1, "transparency": 0.9, "ior": 1.33, "emissive": [0, 0.1, 0]}
  },
  "objects": [
    {"name": "floor", "shape": "plane", "size": 8, "tessellation": 4, "material": "dark wood"},
    {"name": "crate", "shape": "box", "size": [2, 4, 6]},
    {"name": "ball", "shape": "sphere", "radius": 0.5, "tessellation": 24, "material": "red"},
    {"name": "gem", "shape": "icosphere", "radius": 2, "tessellation": 1,
     "material": {"ka": 0.2, "kd": [0, 0.5, 1], "ks": [1, 1, 0], "shininess": 7}},
    {"name": "ring", "shape": "torus", "major_radius": 2, "minor_radius": 0.5, "tessellation": 12},
    {"name": "pot", "shape": "teapot", "tessellation": 3, "material": "glass"}
  ]
})";

TEST(SceneJson, FullSceneCameraEnvironmentAndLights) {
  Scene scene = parseSceneJson(kFullScene, "scenes/full.json");
  EXPECT_EQ(scene.name, "full");
  const Camera& camera = scene.camera;
  EXPECT_TRUE(vec3Near(camera.eye, {1, 2, 3}));
  EXPECT_TRUE(vec3Near(camera.at, {0, 1, 0}));
  EXPECT_TRUE(vec3Near(camera.up, {0, 0, 1}));
  EXPECT_EQ(camera.projection, Projection::Frustum);
  EXPECT_FLOAT_EQ(camera.fovyDegrees, 60.0f);
  EXPECT_FLOAT_EQ(camera.near, 0.5f);
  EXPECT_FLOAT_EQ(camera.far, 50.0f);
  EXPECT_FLOAT_EQ(camera.left, -2.0f);
  EXPECT_FLOAT_EQ(camera.right, 3.0f);
  EXPECT_FLOAT_EQ(camera.bottom, -1.5f);
  EXPECT_FLOAT_EQ(camera.top, 1.0f);
  EXPECT_TRUE(vec3Near(scene.ambient, glm::vec3(0.25f)));
  EXPECT_TRUE(vec3Near(scene.background, {0.1f, 0.2f, 0.3f}));
  ASSERT_EQ(scene.lights.size(), 2u);
  EXPECT_EQ(scene.lights[0].type, LightType::Point);
  EXPECT_TRUE(vec3Near(scene.lights[0].position, {4, 5, 6}));
  EXPECT_TRUE(vec3Near(scene.lights[0].intensity, {0.9f, 0.8f, 0.7f}));
  EXPECT_TRUE(vec3Near(scene.lights[0].attenuation, {1.0f, 0.5f, 0.25f}));
  EXPECT_EQ(scene.lights[1].type, LightType::Directional);
  EXPECT_TRUE(vec3Near(scene.lights[1].direction, {0, -1, 0}));
  EXPECT_TRUE(vec3Near(scene.lights[1].intensity, glm::vec3(0.5f)));
}

// The viewer's screenshot sidecar writes the camera as the format's "camera"
// object: read back, it is the same camera, float for float.
TEST(SceneJson, CameraJsonReadsBackToTheSameCamera) {
  Camera perspectiveCamera;
  perspectiveCamera.eye = {0.1f, 2.0f / 3.0f, -7.25f};
  perspectiveCamera.at = {1e-3f, 0.5f, 3.0f};
  perspectiveCamera.up = {0.0f, 1.0f, 0.1f};
  perspectiveCamera.fovyDegrees = 33.3f;
  perspectiveCamera.far = 250.0f;
  Camera orthographicCamera = perspectiveCamera;
  orthographicCamera.projection = Projection::Orthographic;
  orthographicCamera.left = -4.5f;
  orthographicCamera.right = 4.5f;
  orthographicCamera.bottom = -2.53125f;
  orthographicCamera.top = 2.53125f;
  for (const Camera& camera : {perspectiveCamera, orthographicCamera}) {
    Scene scene = parseSceneJson(R"({"camera": )" + cameraJson(camera) + R"(, "objects": []})",
                                 "camera.json");
    EXPECT_EQ(scene.camera.eye, camera.eye);
    EXPECT_EQ(scene.camera.at, camera.at);
    EXPECT_EQ(scene.camera.up, camera.up);
    EXPECT_EQ(scene.camera.projection, camera.projection);
    EXPECT_EQ(scene.camera.near, camera.near);
    EXPECT_EQ(scene.camera.far, camera.far);
    if (camera.projection == Projection::Perspective) {
      EXPECT_EQ(scene.camera.fovyDegrees, camera.fovyDegrees);
    } else {
      EXPECT_EQ(scene.camera.left, camera.left);
      EXPECT_EQ(scene.camera.top, camera.top);
    }
  }
}

TEST(SceneJson, FullSceneMaterialsByNameAndInline) {
  Scene scene = parse(kFullScene);
  const Material& red = objectNamed(scene, "ball").material;
  EXPECT_TRUE(vec3Near(red.ka, {0.1f, 0, 0}));
  EXPECT_TRUE(vec3Near(red.kd, {0.8f, 0.1f, 0.1f}));
  EXPECT_TRUE(vec3Near(red.ks, glm::vec3(0.4f)));
  EXPECT_FLOAT_EQ(red.shininess, 12.0f);
  // Fields a named material leaves out keep the Material defaults.
  const Material& wood = objectNamed(scene, "floor").material;
  EXPECT_TRUE(vec3Near(wood.kd, glm::vec3(0.3f)));
  EXPECT_TRUE(vec3Near(wood.ka, Material{}.ka));
  EXPECT_FLOAT_EQ(wood.shininess, Material{}.shininess);
  const Material& gem = objectNamed(scene, "gem").material;
  EXPECT_TRUE(vec3Near(gem.ka, glm::vec3(0.2f)));
  EXPECT_TRUE(vec3Near(gem.kd, {0, 0.5f, 1}));
  EXPECT_TRUE(vec3Near(gem.ks, {1, 1, 0}));
  EXPECT_FLOAT_EQ(gem.shininess, 7.0f);
  EXPECT_TRUE(vec3Near(objectNamed(scene, "crate").material.kd, Material{}.kd));
  const Material& glass = objectNamed(scene, "pot").material;
  EXPECT_FLOAT_EQ(glass.reflectivity, 0.1f);
  EXPECT_FLOAT_EQ(glass.transparency, 0.9f);
  EXPECT_FLOAT_EQ(glass.ior, 1.33f);
  EXPECT_TRUE(vec3Near(glass.emissive, {0, 0.1f, 0}));
  EXPECT_FLOAT_EQ(red.reflectivity, 0.0f);
  EXPECT_FLOAT_EQ(red.ior, Material{}.ior);
}

TEST(SceneJson, FullSceneShapes) {
  Scene scene = parse(kFullScene);
  ASSERT_EQ(scene.objects.size(), 6u);
  ASSERT_EQ(scene.shapes.size(), scene.meshes.size());
  auto shapeOf = [&](const std::string& name) {
    return scene.shapes[objectNamed(scene, name).mesh];
  };
  EXPECT_TRUE(
      sameShape(shapeOf("floor"), {.kind = ShapeKind::Plane, .size = 8, .tessellation = 4}));
  EXPECT_TRUE(sameShape(shapeOf("crate"), {.kind = ShapeKind::Box, .halfExtents = {1, 2, 3}}));
  EXPECT_TRUE(sameShape(shapeOf("ball"),
                        {.kind = ShapeKind::UvSphere, .radius = 0.5f, .tessellation = 24}));
  EXPECT_TRUE(
      sameShape(shapeOf("gem"), {.kind = ShapeKind::Icosphere, .radius = 2, .tessellation = 1}));
  EXPECT_TRUE(sameShape(
      shapeOf("ring"),
      {.kind = ShapeKind::Torus, .majorRadius = 2, .minorRadius = 0.5f, .tessellation = 12}));
  EXPECT_TRUE(sameShape(shapeOf("pot"), {.kind = ShapeKind::Teapot, .tessellation = 3}));
  // The meshes were built from those descriptions: 12 box triangles, 20 * 4 icosphere ones.
  EXPECT_EQ(scene.meshes[objectNamed(scene, "crate").mesh].triangleCount(), 12u);
  EXPECT_EQ(scene.meshes[objectNamed(scene, "gem").mesh].triangleCount(), 80u);
}

TEST(SceneJson, DefaultsFromSceneAndShapeHeaders) {
  Scene scene = parseSceneJson(R"({"lights": [{"position": [1, 2, 3]}], "objects": [
      {"shape": "sphere"}, {"shape": "icosphere"}, {"shape": "box"}, {"shape": "torus"}]})",
                               "dir/my-scene.json");
  EXPECT_EQ(scene.name, "my-scene");
  // Eye, at, up, projection, fovy, near and far all enter these two matrices.
  EXPECT_TRUE(mat4Near(scene.camera.viewMatrix(), Camera{}.viewMatrix()));
  EXPECT_TRUE(mat4Near(scene.camera.projectionMatrix(1.5f), Camera{}.projectionMatrix(1.5f)));
  EXPECT_TRUE(vec3Near(scene.ambient, glm::vec3(1.0f)));
  EXPECT_TRUE(vec3Near(scene.background, glm::vec3(0.0f)));
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].type, LightType::Point);
  EXPECT_TRUE(vec3Near(scene.lights[0].intensity, glm::vec3(1.0f)));
  EXPECT_TRUE(vec3Near(scene.lights[0].attenuation, {1, 0, 0}));
  ASSERT_EQ(scene.objects.size(), 4u);
  const Object& sphere = scene.objects[0];
  EXPECT_EQ(sphere.name, "objects[0]");
  EXPECT_TRUE(mat4Near(sphere.transform, glm::mat4(1.0f)));
  EXPECT_TRUE(vec3Near(sphere.material.kd, Material{}.kd));
  EXPECT_TRUE(sameShape(scene.shapes[sphere.mesh], {.kind = ShapeKind::UvSphere}));
  EXPECT_TRUE(sameShape(scene.shapes[scene.objects[1].mesh],
                        {.kind = ShapeKind::Icosphere, .tessellation = 3}));
  EXPECT_TRUE(sameShape(scene.shapes[scene.objects[2].mesh], {.kind = ShapeKind::Box}));
  EXPECT_TRUE(sameShape(scene.shapes[scene.objects[3].mesh], {.kind = ShapeKind::Torus}));
}

glm::mat4 transformOf(const std::string& steps) {
  Scene scene = parse(R"({"objects": [{"shape": "box", "transform": )" + steps + "}]}");
  return scene.objects.at(0).transform;
}

TEST(SceneJson, TransformListIsMultipliedInOrderSoTheLastStepActsFirst) {
  // [translate, scale]: M = T S, so p -> T(S(p)) = 2 (1,1,1) + (1,2,3).
  glm::mat4 ts = transformOf(R"([{"translate": [1, 2, 3]}, {"scale": 2}])");
  EXPECT_TRUE(vec3Near(apply(ts, {1, 1, 1}), {3, 4, 5}));
  // [scale, translate]: p -> S(T(p)) = 2 ((1,1,1) + (1,2,3)).
  glm::mat4 st = transformOf(R"([{"scale": 2}, {"translate": [1, 2, 3]}])");
  EXPECT_TRUE(vec3Near(apply(st, {1, 1, 1}), {4, 6, 8}));
}

TEST(SceneJson, EachTransformStep) {
  EXPECT_TRUE(mat4Near(transformOf(R"([{"scale": [1, 2, 3]}])"), scaling({1, 2, 3})));
  // 90 degrees about z through (1, 0, 0): (2, 0, 0) is 1 to the right of the pivot, ends 1 above.
  glm::mat4 about =
      transformOf(R"([{"rotate": {"axis": [0, 0, 1], "degrees": 90, "about": [1, 0, 0]}}])");
  EXPECT_TRUE(vec3Near(apply(about, {2, 0, 0}), {1, 1, 0}));
  glm::mat4 rotate = transformOf(R"([{"rotate": {"axis": [0, 2, 0], "degrees": 90}}])");
  EXPECT_TRUE(vec3Near(apply(rotate, {1, 0, 0}), {0, 0, -1}));
  // x' = x + xy y, z' = z + zy y.
  glm::mat4 shear = transformOf(R"([{"shear": {"xy": 0.5, "zy": -1}}])");
  EXPECT_TRUE(vec3Near(apply(shear, {0, 2, 0}), {1, 2, -2}));
  EXPECT_TRUE(mat4Near(transformOf("[]"), glm::mat4(1.0f)));
}

// Named axes are the elementary rotations bit for bit (the built-in scenes rely on it): at 90
// degrees Rodrigues' formula about [1, 0, 0] gives 0.99999994, not 1, on the diagonal.
TEST(SceneJson, NamedAxisIsTheExactElementaryRotation) {
  float angle = glm::radians(90.0f);
  EXPECT_EQ(transformOf(R"([{"rotate": {"axis": "x", "degrees": 90}}])"), rotationX(angle));
  EXPECT_EQ(transformOf(R"([{"rotate": {"axis": "y", "degrees": 90}}])"), rotationY(angle));
  EXPECT_EQ(transformOf(R"([{"rotate": {"axis": "z", "degrees": 90}}])"), rotationZ(angle));
  EXPECT_NE(transformOf(R"([{"rotate": {"axis": [1, 0, 0], "degrees": 90}}])"), rotationX(angle));
  glm::mat4 about =
      transformOf(R"([{"rotate": {"axis": "z", "degrees": 90, "about": [1, 0, 0]}}])");
  EXPECT_TRUE(vec3Near(apply(about, {2, 0, 0}), {1, 1, 0}));
}

TEST(SceneJson, DescriptionIsKept) {
  EXPECT_EQ(parse(R"({"description": "a one-line summary", "objects": []})").description,
            "a one-line summary");
  EXPECT_EQ(parse(R"({"objects": []})").description, "");
}

TEST(SceneJson, ChildWorldMatrixIsParentWorldTimesLocal) {
  Scene scene = parse(R"({"objects": [
    {"name": "sun", "shape": "sphere",
     "transform": [{"translate": [10, 0, 0]}, {"rotate": {"axis": [0, 1, 0], "degrees": 90}}],
     "children": [
       {"name": "planet group", "transform": [{"translate": [1, 0, 0]}],
        "children": [{"name": "moon", "shape": "icosphere", "transform": [{"scale": 2}]}]}]}]})");
  ASSERT_EQ(scene.objects.size(), 2u);  // the group itself draws nothing
  glm::mat4 sun = translation({10, 0, 0}) * rotationY(glm::radians(90.0f));
  glm::mat4 moon = sun * translation({1, 0, 0}) * scaling(glm::vec3(2));
  EXPECT_TRUE(mat4Near(objectNamed(scene, "sun").transform, sun));
  EXPECT_TRUE(mat4Near(objectNamed(scene, "moon").transform, moon));
  // (1,0,0) -> scale (2,0,0) -> translate (3,0,0) -> rotate y 90 (0,0,-3) -> translate.
  EXPECT_TRUE(vec3Near(apply(objectNamed(scene, "moon").transform, {1, 0, 0}), {10, 0, -3}));
}

TEST(SceneJson, IdenticalShapesShareOneMesh) {
  Scene scene = parse(R"({"objects": [
    {"shape": "sphere", "radius": 2}, {"shape": "sphere", "radius": 2},
    {"shape": "sphere", "radius": 3}, {"shape": "box"}, {"shape": "box", "size": 1}]})");
  ASSERT_EQ(scene.objects.size(), 5u);
  EXPECT_EQ(scene.objects[0].mesh, scene.objects[1].mesh);
  EXPECT_NE(scene.objects[0].mesh, scene.objects[2].mesh);
  EXPECT_EQ(scene.objects[3].mesh, scene.objects[4].mesh);
  EXPECT_EQ(scene.meshes.size(), 3u);
}

TEST(SceneJson, SyntaxErrorReportsLineAndColumn) {
  std::string text = "{\n  \"objects\": [\n    {\"shape\": \"sphere\",}\n  ]\n}";
  EXPECT_THAT(errorOf(text), AllOf(HasSubstr("scene.json: line 3, column 24: invalid JSON"),
                                   HasSubstr("expected string literal")));
  EXPECT_THAT(errorOf(""), HasSubstr("scene.json: line 1, column 1: invalid JSON"));
  EXPECT_THAT(errorOf("{\"objects\": []}\n]"), HasSubstr("line 2, column 1"));
  // nlohmann reports a number overflow without a position: the loader finds the literal.
  EXPECT_THAT(errorOf("{\"objects\": [],\n \"ambient\": 1e999}"),
              AllOf(HasSubstr("scene.json: line 2, column 13: invalid JSON"), HasSubstr("1e999")));
}

struct ErrorCase {
  const char* name;
  std::string json;
  std::vector<std::string> fragments;  // each must appear in the message
};

// A scene whose only object has `fields`.
std::string oneObject(const std::string& fields) {
  return R"({"objects": [{)" + fields + "}]}";
}
// A scene with no objects and `fields` at the top level.
std::string noObjects(const std::string& fields) {
  return "{" + fields + R"(, "objects": []})";
}
// A scene whose only light has `fields`.
std::string oneLight(const std::string& fields) {
  return noObjects(R"("lights": [{)" + fields + "}]");
}
// A scene whose only object is a box with these transform steps.
std::string boxSteps(const std::string& steps) {
  return oneObject(R"("shape": "box", "transform": [)" + steps + "]");
}

// Names the case in failure output instead of dumping its bytes.
void PrintTo(const ErrorCase& errorCase, std::ostream* out) {
  *out << errorCase.name;
}

class SceneJsonError : public testing::TestWithParam<ErrorCase> {};

// crease_angle replaces a shape's exact normals by creased averages: a box
// smoothed at 180 degrees has every normal leaning into all three axes
// (area-weighted, so not exactly along the diagonal: a face's two triangles
// meet at only two of its corners); an icosphere at 0 degrees is split into
// one vertex per triangle corner.
TEST(SceneJson, CreaseAngleRecomputesNormals) {
  Scene scene = parse(R"({"objects": [
    {"shape": "box", "crease_angle": 180}, {"shape": "box"},
    {"shape": "icosphere", "tessellation": 1, "crease_angle": 0}]})");
  ASSERT_EQ(scene.meshes.size(), 3u);
  const Mesh& smoothBox = scene.meshes[scene.objects[0].mesh];
  const Mesh& box = scene.meshes[scene.objects[1].mesh];
  for (const Vertex& v : smoothBox.vertices) {
    EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
    EXPECT_GT(glm::dot(v.normal, glm::normalize(v.position)), 0.94f);
    EXPECT_GT(glm::min(glm::abs(v.normal.x), glm::min(glm::abs(v.normal.y), glm::abs(v.normal.z))),
              0.3f);
  }
  for (const Vertex& v : box.vertices)
    EXPECT_NEAR(glm::dot(v.normal, glm::normalize(v.position)), 1.0f / std::sqrt(3.0f), 1e-5f);
  const Mesh& faceted = scene.meshes[scene.objects[2].mesh];
  EXPECT_EQ(faceted.vertices.size(), 3 * faceted.triangleCount());
}

TEST_P(SceneJsonError, ThrowsInputErrorNamingPathAndProblem) {
  std::string message = errorOf(GetParam().json);
  for (const std::string& fragment : GetParam().fragments)
    EXPECT_THAT(message, HasSubstr(fragment));
}

// clang-format off
const ErrorCase kErrorCases[] = {
  {"NestedWrongType", oneObject(R"("children": [{"shape": "box", "material": {"kd": "red"}}])"),
   {R"(scene.json: objects[0].children[0].material.kd: expected a number or an array of 3)"
    R"( numbers, got "red")"}},
  {"RootNotAnObject", "[1, 2]", {"scene.json: top level: expected an object, got [1,2]"}},
  {"MissingObjects", "{}", {"scene.json: objects: missing, expected an array of objects"}},
  {"ObjectsNotAnArray", R"({"objects": {}})", {"objects: expected an array of objects, got {}"}},
  {"UnknownTopLevelField", noObjects(R"("colour": 1)"),
   {"scene.json: colour: unknown field \"colour\", expected one of description, camera, ambient,"
    " background, environment, lights, materials, objects"}},
  {"UnknownObjectField", oneObject(R"("shape": "sphere", "colour": [1, 0, 0])"),
   {"objects[0].colour: unknown field \"colour\"", "material", "radius", "tessellation"}},
  {"MaterialOnAGroup", oneObject(R"("material": "x", "children": [{"shape": "box"}])"),
   {"objects[0].material: unknown field", "one of name, shape, transform, children"}},
  {"CreaseAngleOutOfRange", oneObject(R"("shape": "sphere", "crease_angle": 200)"),
   {"objects[0].crease_angle: crease_angle 200 is out of range", "from 0 to 180"}},
  {"CreaseAngleOnAGroup", oneObject(R"("crease_angle": 30, "children": [{"shape": "box"}])"),
   {"objects[0].crease_angle: unknown field"}},
  {"TessellationOnABox", oneObject(R"("shape": "box", "tessellation": 4)"),
   {"objects[0].tessellation: unknown field"}},
  {"UnknownShape", oneObject(R"("shape": "cube")"), {"objects[0].shape: unknown shape \"cube\","
   " expected one of plane, box, sphere, icosphere, torus, teapot"}},
  {"UnknownProjection", noObjects(R"("camera": {"projection": "fisheye"})"), {"camera.projection:"
   " unknown projection \"fisheye\", expected one of perspective, frustum, orthographic"}},
  {"UnknownLightType", oneLight(R"("type": "spot", "position": [0, 1, 0])"),
   {"lights[0].type: unknown light type \"spot\", expected one of point, directional"}},
  {"UnknownMaterial", R"({"materials": {"gold": {}, "wood": {}}, "objects": [{"shape": "box",)"
   R"( "material": "x"}]})", {"objects[0].material: unknown material \"x\", expected one of gold,"
   " wood"}},
  {"UnknownMaterialNoneDefined", oneObject(R"("shape": "box", "material": "steel")"),
   {"objects[0].material: unknown material \"steel\"", "there are none"}},
  {"MaterialWrongType", oneObject(R"("shape": "box", "material": 3)"),
   {"objects[0].material: expected a material name or a material object, got 3"}},
  {"NumberTooLargeForFloat", oneObject(R"("shape": "sphere", "radius": 1e39)"),
   {"objects[0].radius: 1e+39 is too large for a float, expected a finite number"}},
  {"NegativeRadius", oneObject(R"("shape": "sphere", "radius": -1)"),
   {"objects[0].radius: -1 is not positive, expected a number > 0"}},
  {"ZeroPlaneSize", oneObject(R"("shape": "plane", "size": 0)"),
   {"objects[0].size: 0 is not positive"}},
  {"ZeroBoxEdge", oneObject(R"("shape": "box", "size": [1, 0, 1])"),
   {"objects[0].size[1]: 0 is not positive"}},
  {"TorusMinorTooBig", oneObject(R"("shape": "torus", "major_radius": 1, "minor_radius": 1)"),
   {"objects[0].minor_radius: minor_radius (1) is not less than major_radius (1), expected"
    " minor_radius < major_radius"}},
  {"TorusMajorBelowDefaultMinor", oneObject(R"("shape": "torus", "major_radius": 0.2)"),
   {"objects[0].major_radius: minor_radius (0.25) is not less than major_radius (0.2)"}},
  {"SphereTessellationTooHigh", oneObject(R"("shape": "sphere", "tessellation": 2000)"),
   {"objects[0].tessellation: 2000 is out of range, expected an integer in 3..1024"}},
  {"SphereTessellationTooLow", oneObject(R"("shape": "sphere", "tessellation": 2)"),
   {"objects[0].tessellation: 2 is out of range", "3..1024 (sphere slices)"}},
  {"IcosphereLevelTooHigh", oneObject(R"("shape": "icosphere", "tessellation": 8)"),
   {"objects[0].tessellation: 8 is out of range", "0..7 (icosphere subdivision level)"}},
  {"TeapotTessellationTooHigh", oneObject(R"("shape": "teapot", "tessellation": 65)"),
   {"objects[0].tessellation: 65 is out of range", "1..64"}},
  {"TessellationNotWhole", oneObject(R"("shape": "torus", "tessellation": 2.5)"),
   {"objects[0].tessellation: 2.5 is not a whole number, expected an integer in 3..1024"}},
  {"NearZero", noObjects(R"("camera": {"near": 0})"),
   {"camera.near: 0 is not positive, expected a number > 0"}},
  {"FarNotBeyondNear", noObjects(R"("camera": {"near": 2, "far": 1})"),
   {"camera.far: far (1) is not beyond near (2), expected 0 < near < far"}},
  {"NearBeyondDefaultFar", noObjects(R"("camera": {"near": 200})"),
   {"camera.near: far (100) is not beyond near (200)"}},
  {"FovyOutOfRange", noObjects(R"("camera": {"fovy": 180})"),
   {"camera.fovy: 180 degrees is not a field of view"}},
  {"RightNotGreaterThanLeft", noObjects(R"("camera": {"left": 1, "right": 1})"),
   {"camera.right: right (1) is not greater than left (1)"}},
  {"ZeroUpVector", noObjects(R"("camera": {"up": [0, 0, 0]})"),
   {"camera.up: zero-length up vector, expected a non-zero vector"}},
  {"UpParallelToView", noObjects(R"("camera": {"eye": [0, 5, 0], "at": [0, 0, 0]})"),
   {"camera.up: up is parallel to the viewing direction"}},
  {"EyeEqualsAt", noObjects(R"("camera": {"eye": [1, 2, 3], "at": [1, 2, 3]})"),
   {"camera.at: at equals eye"}},
  {"EyeWrongLength", noObjects(R"("camera": {"eye": [1, 2]})"),
   {"camera.eye: expected an array of 3 numbers, got [1,2]"}},
  {"ZeroRotationAxis", boxSteps(R"({"scale": 2}, {"rotate": {"axis": [0, 0, 0], "degrees": 5}})"),
   {"objects[0].transform[1].rotate.axis: zero-length rotation axis"}},
  {"UnknownAxisName", boxSteps(R"({"rotate": {"axis": "w", "degrees": 5}})"),
   {R"(objects[0].transform[0].rotate.axis: unknown axis "w", expected one of x, y, z)"}},
  {"DescriptionNotAString", R"({"description": 3, "objects": []})",
   {"scene.json: description: expected a string, got 3"}},
  {"RotationWithoutDegrees", boxSteps(R"({"rotate": {"axis": [0, 1, 0]}})"),
   {"objects[0].transform[0].rotate.degrees: missing"}},
  {"ZeroScale", boxSteps(R"({"scale": [1, 0, 1]})"),
   {"objects[0].transform[0].scale: a scale factor of 0 flattens the object"}},
  {"SingularShear", boxSteps(R"({"shear": {"xy": 1, "yx": 1}})"),
   {"objects[0].transform: the matrix is singular", "expected an invertible transform"}},
  {"UnknownShearFactor", boxSteps(R"({"shear": {"xw": 1}})"),
   {"objects[0].transform[0].shear.xw: unknown field", "xy, xz, yx, yz, zx, zy"}},
  {"StepWithTwoKeys", boxSteps(R"({"translate": [1, 0, 0], "scale": 2})"),
   {"objects[0].transform[0]: expected an object with exactly one of translate, rotate, scale,"
    " shear"}},
  {"UnknownTransformStep", boxSteps(R"({"move": [1, 0, 0]})"),
   {"objects[0].transform[0].move: unknown transform \"move\""}},
  {"TooManyLights", noObjects(R"("lights": [{"position": [0, 1, 0]}, {"position": [0, 1, 0]},
    {"position": [0, 1, 0]}, {"position": [0, 1, 0]}, {"position": [0, 1, 0]},
    {"position": [0, 1, 0]}, {"position": [0, 1, 0]}, {"position": [0, 1, 0]},
    {"position": [0, 1, 0]}])"), {"scene.json: lights: 9 lights, expected at most 8"}},
  {"PointLightWithoutPosition", oneLight(R"("intensity": 1)"),
   {"lights[0].position: missing"}},
  {"DirectionalLightWithoutDirection", oneLight(R"("type": "directional")"),
   {"lights[0].direction: missing"}},
  {"ZeroLightDirection", oneLight(R"("type": "directional", "direction": [0, 0, 0])"),
   {"lights[0].direction: zero-length direction"}},
  {"DirectionalAttenuation", oneLight(R"("type": "directional", "direction": [1, 1, 1], )"
                                      R"("attenuation": [1, 0, 0])"),
   {"lights[0].attenuation: unknown field", "one of type, direction, intensity"}},
  {"AttenuationAllZero", oneLight(R"("position": [0, 1, 0], "attenuation": [0, 0, 0])"),
   {"lights[0].attenuation: all coefficients are 0"}},
  {"AttenuationNegative", oneLight(R"("position": [0, 1, 0], "attenuation": [1, -1, 0])"),
   {"lights[0].attenuation[1]: -1 is negative"}},
  {"NegativeShininess", noObjects(R"("materials": {"shiny": {"shininess": -1}})"),
   {"materials.shiny.shininess: -1 is negative, expected a number >= 0"}},
  {"MaterialNameWithSpaceIsQuotedInPath", noObjects(R"("materials": {"dark wood": {"kd": true}})"),
   {R"(materials["dark wood"].kd: expected a number or an array of 3 numbers, got true)"}},
  {"ReflectivityAboveOne", noObjects(R"("materials": {"m": {"reflectivity": 1.5}})"),
   {"materials.m.reflectivity: value 1.5 is outside 0..1, expected a fraction from 0 to 1"}},
  {"ZeroIor", noObjects(R"("materials": {"m": {"ior": 0}})"), {"materials.m.ior"}},
  {"NegativeAmbient", noObjects(R"("ambient": [-1, 0, 0])"), {"ambient[0]: -1 is negative"}},
  {"GroupWithoutChildren", oneObject(R"("name": "empty")"),
   {"scene.json: objects[0]: a group (an object without \"shape\" or \"gltf\") with no children"}},
  {"GroupWithEmptyChildren", oneObject(R"("children": [])"),
   {"objects[0].children: a group", "a non-empty \"children\" array"}},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Validation, SceneJsonError, testing::ValuesIn(kErrorCases),
                         [](const testing::TestParamInfo<ErrorCase>& info) {
                           return std::string(info.param.name);
                         });

TEST(SceneJson, NestingDepthIsLimited) {
  std::string text = R"({"shape": "box"})";
  for (int level = 0; level < 70; ++level) text = R"({"children": [)" + text + "]}";
  EXPECT_THAT(errorOf(R"({"objects": [)" + text + "]}"),
              HasSubstr("objects nested more than 64 levels deep"));
}

// The file's procedural meshes are estimated before any is built: above the
// budget the file is refused naming the option; within it every mesh is
// built as Scene::addShape builds it, shared meshes once.
TEST(SceneJson, TriangleBudgetIsCheckedBeforeMeshesAreBuilt) {
  const char* text = R"({"objects": [{"shape": "plane", "tessellation": 64},
    {"shape": "sphere", "tessellation": 32}, {"shape": "plane", "tessellation": 64}]})";
  // planes: 2 * 64 * 64 = 8192 triangles each; the sphere 2 * 32 * 15 = 960.
  EXPECT_THAT(errorFrom([&] {
                parseSceneJson(text, "s.json", {17343, "--budget"});
              }),
              HasSubstr("scene 's' at its own tessellation (before building): an estimated 17344 "
                        "triangles drawn"));
  EXPECT_THAT(errorFrom([&] {
                parseSceneJson(text, "s.json", {17343, "--budget"});
              }),
              HasSubstr("more than --budget 17343"));
  Scene scene = parseSceneJson(text, "s.json", {17344, "--budget"});
  ASSERT_EQ(scene.meshes.size(), 2u);
  EXPECT_EQ(scene.objects[0].mesh, scene.objects[2].mesh);
  EXPECT_EQ(scene.triangleCount(), 17344u);
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    Mesh built = buildShape(scene.shapes[i]);
    EXPECT_EQ(scene.meshes[i].indices, built.indices) << i;
    EXPECT_EQ(scene.meshes[i].vertices.size(), built.vertices.size()) << i;
  }
}

std::filesystem::path writeFile(const std::filesystem::path& path, const std::string& contents) {
  std::ofstream(path) << contents;
  return path;
}

std::string loadError(const std::filesystem::path& path) {
  return errorFrom([&] { loadScene(path.string()); });
}

TEST(SceneJsonFile, LoadsThroughLoadSceneAndReportsBadFiles) {
  std::filesystem::path folder = test::testFolder();
  std::filesystem::path good = writeFile(folder / "shadelab-good.json", R"({"objects": []})");
  EXPECT_EQ(loadScene(good.string()).name, "shadelab-good");
  std::filesystem::path bad = writeFile(folder / "shadelab-bad.json", R"({"objects": [{}]})");
  EXPECT_THAT(loadError(bad), HasSubstr(bad.string() + ": objects[0]: a group"));
  std::filesystem::path missing = folder / "no-such.json";
  EXPECT_THAT(loadError(missing),
              HasSubstr("scene file '" + missing.string() + "' does not exist"));
  EXPECT_THAT(errorFrom([&] { loadSceneJson(missing); }),
              HasSubstr("scene file '" + missing.string() + "' does not exist"));
  EXPECT_THAT(loadError(folder), HasSubstr("is a directory, expected a .json, .gltf or .glb file"));
  std::filesystem::path emptyModel = writeFile(folder / "shadelab-model.gltf", "{}");
  EXPECT_THAT(loadError(emptyModel), HasSubstr(emptyModel.string() + ": invalid glTF"));
  std::filesystem::path directory = folder / "dir.json";
  std::filesystem::create_directories(directory);
  EXPECT_THAT(loadError(directory), HasSubstr("is a directory"));
}

TEST(SceneJsonFile, EveryAssetSceneLoads) {
  std::filesystem::path directory = std::filesystem::path(SHADELAB_ASSET_DIR) / "scenes";
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    ++count;
    Scene scene;
    ASSERT_NO_THROW(scene = loadScene(entry.path().string()));
    EXPECT_EQ(scene.name, entry.path().stem().string());
    EXPECT_FALSE(scene.objects.empty());
    EXPECT_GT(scene.triangleCount(), 0u);
  }
  EXPECT_GE(count, 2);
}

TEST(SceneJsonFile, ExampleScenesHaveWhatTheyPromise) {
  std::filesystem::path directory = std::filesystem::path(SHADELAB_ASSET_DIR) / "scenes";
  Scene spheres = loadSceneJson(directory / "three-spheres.json");
  EXPECT_EQ(spheres.objects.size(), 4u);  // three spheres on a floor
  ASSERT_EQ(spheres.lights.size(), 2u);
  EXPECT_NE(spheres.lights[0].attenuation, glm::vec3(1, 0, 0));

  Scene nested = loadSceneJson(directory / "nested.json");
  const Object& teapot = objectNamed(nested, "teapot");
  EXPECT_EQ(nested.shapes[teapot.mesh].kind, ShapeKind::Teapot);
  // The table is turned 20 degrees, so the teapot's world matrix includes that turn.
  EXPECT_TRUE(vec3Near(apply(teapot.transform, {0, 0, 0}),
                       apply(rotationY(glm::radians(20.0f)), {-0.6f, 1.0f, 0.1f})));
}

}  // namespace
}  // namespace shadelab
