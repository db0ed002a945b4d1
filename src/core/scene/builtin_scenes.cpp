#include <functional>
#include <map>

#include "core/base/errors.h"
#include "core/scene/procedural_textures.h"
#include "core/scene/scene.h"
#include "core/scene/transform.h"

namespace shadelab {
namespace {

Material material(glm::vec3 color, glm::vec3 specular, float shininess) {
  return {0.15f * color, color, specular, shininess};
}

ShapeDesc plane(float size, uint32_t quadsPerSide) {
  return {ShapeKind::Plane, size, {}, 1.0f, 1.0f, 0.25f, quadsPerSide};
}
ShapeDesc uvSphere(float radius, uint32_t slices) {
  return {ShapeKind::UvSphere, 1.0f, {}, radius, 1.0f, 0.25f, slices};
}
ShapeDesc icosphere(float radius, uint32_t level) {
  return {ShapeKind::Icosphere, 1.0f, {}, radius, 1.0f, 0.25f, level};
}
ShapeDesc torus(float major, float minor, uint32_t segments) {
  return {ShapeKind::Torus, 1.0f, {}, 1.0f, major, minor, segments};
}
ShapeDesc box(glm::vec3 halfExtents) {
  return {ShapeKind::Box, 1.0f, halfExtents, 1.0f, 1.0f, 0.25f, 1};
}
ShapeDesc teapot(uint32_t level) {
  return {ShapeKind::Teapot, 1.0f, {}, 1.0f, 1.0f, 0.25f, level};
}

Light pointLight(glm::vec3 position, glm::vec3 intensity, glm::vec3 attenuation) {
  return {LightType::Point, position, {}, intensity, attenuation};
}
Light directionalLight(glm::vec3 direction, glm::vec3 intensity) {
  return {LightType::Directional, {}, direction, intensity, {1.0f, 0.0f, 0.0f}};
}

// The default scene: one of each procedural shape on a floor under a point
// light and a directional light, so depth testing, perspective and the
// illumination equation are all visible in one image.
Scene defaultScene() {
  Scene scene;
  scene.name = "default";
  scene.camera.eye = {0.0f, 3.2f, 7.5f};
  scene.camera.at = {0.0f, 0.6f, 0.0f};
  scene.camera.fovyDegrees = 40.0f;
  scene.ambient = glm::vec3(0.6f);
  scene.background = {0.02f, 0.025f, 0.035f};
  scene.lights.push_back(pointLight({3.0f, 5.0f, 4.0f}, glm::vec3(1.0f), {1.0f, 0.0f, 0.01f}));
  scene.lights.push_back(directionalLight({1.0f, -1.0f, -0.6f}, {0.25f, 0.25f, 0.3f}));

  uint32_t floor = scene.addShape(plane(12.0f, 8));
  uint32_t sphere = scene.addShape(uvSphere(0.8f, 48));
  uint32_t ring = scene.addShape(torus(0.6f, 0.22f, 48));
  uint32_t cube = scene.addShape(box(glm::vec3(0.6f)));
  uint32_t ico = scene.addShape(icosphere(0.7f, 2));

  scene.objects.push_back({"floor", floor, glm::mat4(1.0f),
                           material({0.45f, 0.45f, 0.42f}, glm::vec3(0.1f), 8.0f)});
  scene.objects.push_back({"sphere", sphere, translation({-2.2f, 0.8f, 0.0f}),
                           material({0.8f, 0.2f, 0.15f}, glm::vec3(0.6f), 64.0f)});
  scene.objects.push_back({"torus", ring,
                           translation({-0.1f, 0.8f, -0.6f}) * rotationX(glm::radians(60.0f)),
                           material({0.2f, 0.6f, 0.3f}, glm::vec3(0.5f), 32.0f)});
  scene.objects.push_back({"box", cube,
                           translation({1.9f, 0.6f, 0.3f}) * rotationY(glm::radians(30.0f)),
                           material({0.25f, 0.35f, 0.8f}, glm::vec3(0.4f), 16.0f)});
  scene.objects.push_back({"icosphere", ico, translation({0.2f, 0.7f, 1.6f}),
                           material({0.85f, 0.75f, 0.3f}, glm::vec3(0.8f), 128.0f)});
  return scene;
}

// Spheres of five materials (matte to mirror-like highlights) under two
// coloured point lights with attenuation and one directional light.
Scene spheresScene() {
  Scene scene;
  scene.name = "spheres";
  scene.camera.eye = {0.0f, 2.4f, 8.0f};
  scene.camera.at = {0.0f, 0.8f, 0.0f};
  scene.camera.fovyDegrees = 38.0f;
  scene.ambient = glm::vec3(0.5f);
  scene.background = {0.03f, 0.03f, 0.05f};
  scene.lights.push_back(pointLight({-4.0f, 4.0f, 3.0f}, {1.0f, 0.85f, 0.7f}, {1.0f, 0.05f, 0.01f}));
  scene.lights.push_back(pointLight({4.0f, 2.5f, 2.0f}, {0.35f, 0.45f, 0.9f}, {1.0f, 0.0f, 0.05f}));
  scene.lights.push_back(directionalLight({0.2f, -1.0f, -0.5f}, glm::vec3(0.3f)));
  uint32_t floor = scene.addShape(plane(14.0f, 8));
  uint32_t sphere = scene.addShape(uvSphere(0.75f, 32));
  scene.objects.push_back({"floor", floor, glm::mat4(1.0f),
                           material({0.5f, 0.5f, 0.5f}, glm::vec3(0.05f), 4.0f)});
  struct Ball {
    const char* name;
    glm::vec3 kd, ks;
    float shininess;
  };
  const Ball balls[] = {
      {"matte", {0.75f, 0.3f, 0.2f}, glm::vec3(0.0f), 1.0f},
      {"plastic", {0.2f, 0.55f, 0.25f}, glm::vec3(0.5f), 32.0f},
      {"glossy", {0.2f, 0.3f, 0.8f}, glm::vec3(0.8f), 128.0f},
      {"metal", {0.35f, 0.3f, 0.15f}, {0.9f, 0.8f, 0.5f}, 64.0f},
      {"chalk", {0.8f, 0.8f, 0.75f}, glm::vec3(0.15f), 8.0f},
  };
  for (int i = 0; i < 5; ++i)
    scene.objects.push_back({balls[i].name, sphere, translation({-3.4f + 1.7f * float(i), 0.75f, 0.0f}),
                             material(balls[i].kd, balls[i].ks, balls[i].shininess)});
  return scene;
}

// The Utah teapot from Newell's 32 bicubic Bezier patches.
Scene teapotScene() {
  Scene scene;
  scene.name = "teapot";
  scene.camera.eye = {0.0f, 3.6f, 7.0f};
  scene.camera.at = {0.0f, 1.1f, 0.0f};
  scene.camera.fovyDegrees = 40.0f;
  scene.ambient = glm::vec3(0.5f);
  scene.background = {0.04f, 0.04f, 0.05f};
  scene.lights.push_back(pointLight({-3.0f, 6.0f, 5.0f}, glm::vec3(1.0f), {1.0f, 0.0f, 0.005f}));
  scene.lights.push_back(directionalLight({1.0f, -0.5f, -1.0f}, {0.2f, 0.2f, 0.25f}));
  uint32_t pot = scene.addShape(teapot(8));
  uint32_t floor = scene.addShape(plane(12.0f, 4));
  scene.objects.push_back({"floor", floor, glm::mat4(1.0f),
                           material({0.35f, 0.4f, 0.45f}, glm::vec3(0.05f), 4.0f)});
  scene.objects.push_back({"teapot", pot, rotationY(glm::radians(-25.0f)),
                           material({0.8f, 0.45f, 0.2f}, glm::vec3(0.7f), 48.0f)});
  return scene;
}

}  // namespace

// A coarse plane (one quad, two triangles, at the base tessellation) under a
// point light whose highlight falls inside one large triangle: Gouraud, which
// lights only the vertices, cannot show it; subdividing brings it back.
Scene highlightScene(uint32_t quadsPerSide) {
  Scene scene;
  scene.name = "highlight";
  scene.camera.eye = {0.0f, 4.0f, 4.0f};
  scene.camera.at = {0.0f, 0.0f, 0.0f};
  scene.camera.fovyDegrees = 50.0f;
  scene.ambient = glm::vec3(0.2f);
  scene.background = {0.0f, 0.0f, 0.0f};
  scene.lights.push_back(pointLight({-0.5f, 1.0f, 0.9f}, glm::vec3(1.0f), {1.0f, 0.0f, 0.0f}));
  uint32_t floor = scene.addShape(plane(4.0f, quadsPerSide));
  scene.objects.push_back({"plane", floor, glm::mat4(1.0f),
                           material({0.2f, 0.25f, 0.6f}, glm::vec3(0.9f), 64.0f)});
  return scene;
}

// Both planes are horizontal, 240 units wide, seen from 117 units away at
// 31 degrees, so the view rays cross the gap between them over 0.07 to 0.2
// units of depth. The far clip plane is 10,000 in both projections: a
// perspective depth buffer spends its precision near the near plane, an
// orthographic one spreads it evenly over near..far.
Scene zfightScene(Projection projection, float near) {
  Scene scene;
  scene.name = "zfight";
  scene.camera.eye = {0.0f, 60.0f, 100.0f};
  scene.camera.at = {0.0f, 0.0f, 0.0f};
  scene.camera.projection = projection;
  scene.camera.fovyDegrees = 35.0f;
  scene.camera.near = near;
  scene.camera.far = 10000.0f;
  // The orthographic view volume frames what the perspective one shows at the planes' centre.
  scene.camera.top = 36.9f;
  scene.camera.bottom = -36.9f;
  scene.camera.right = 36.9f * 16.0f / 9.0f;
  scene.camera.left = -scene.camera.right;
  scene.ambient = glm::vec3(1.0f);
  uint32_t sheet = scene.addShape(plane(240.0f, 16));
  Material farMaterial{glm::vec3(0.0f), kZFightFarColor, glm::vec3(0.0f), 1.0f};
  Material nearMaterial{glm::vec3(0.0f), kZFightNearColor, glm::vec3(0.0f), 1.0f};
  scene.objects.push_back({"far plane", sheet, translation({0.0f, -kZFightGap, 0.0f}),
                           farMaterial});
  scene.objects.push_back({"near plane", sheet, glm::mat4(1.0f), nearMaterial});
  scene.lights.push_back(directionalLight({0.0f, -1.0f, 0.0f}, glm::vec3(1.0f)));
  return scene;
}

namespace {

// The speed benchmark's dense mesh: one torus of 102,400 triangles (320 x 160
// segments) filling most of a 16:9 frame, so per-vertex and per-fragment
// costs both show. No floor: the torus is the whole workload.
Scene denseScene() {
  Scene scene;
  scene.name = "dense";
  scene.camera.eye = {0.0f, 2.1f, 2.2f};
  scene.camera.at = {0.0f, -0.1f, 0.0f};
  scene.camera.fovyDegrees = 45.0f;
  scene.ambient = glm::vec3(0.15f);
  scene.background = {0.02f, 0.02f, 0.03f};
  scene.lights.push_back(pointLight({1.5f, 2.5f, 2.0f}, glm::vec3(0.9f), {1.0f, 0.0f, 0.0f}));
  scene.lights.push_back(directionalLight({-0.3f, -1.0f, 0.4f}, {0.25f, 0.25f, 0.3f}));
  uint32_t ring = scene.addShape(torus(1.2f, 0.55f, 320));
  scene.objects.push_back({"torus", ring, glm::mat4(1.0f),
                           material({0.75f, 0.45f, 0.2f}, glm::vec3(0.6f), 48.0f)});
  return scene;
}

// Environment mapping: a mirror sphere, a glass sphere (refraction with
// Fresnel) and a chrome-like teapot under the procedural sky, on a matte
// floor. The sun, low ahead on the left, and the directional light agree;
// a point light behind the camera fills the fronts.
Scene environmentScene() {
  Scene scene;
  scene.name = "env";
  scene.camera.eye = {0.0f, 2.2f, 8.5f};
  scene.camera.at = {0.0f, 1.3f, 0.0f};
  scene.camera.fovyDegrees = 40.0f;
  scene.ambient = glm::vec3(0.4f);
  scene.background = {0.5f, 0.6f, 0.75f};       // with --env off
  glm::vec3 sunlight{0.416f, -0.174f, 0.893f};  // from 10 degrees up, 25 degrees left of ahead
  scene.environment.kind = EnvironmentKind::Sky;
  scene.environment.sky.sunDirection = sunlight;
  scene.environment.source = "procedural sky";
  scene.lights.push_back(directionalLight(sunlight, {1.0f, 0.95f, 0.85f}));
  scene.lights.push_back(pointLight({-3.0f, 4.0f, 9.0f}, glm::vec3(0.6f), {1.0f, 0.0f, 0.0f}));

  uint32_t floor = scene.addShape(plane(16.0f, 8));
  uint32_t sphere = scene.addShape(uvSphere(1.0f, 64));
  uint32_t pot = scene.addShape(teapot(8));
  scene.objects.push_back(
      {"floor", floor, glm::mat4(1.0f), material({0.45f, 0.42f, 0.38f}, glm::vec3(0.05f), 8.0f)});
  Material mirror = material(glm::vec3(0.02f), glm::vec3(0.8f), 256.0f);
  mirror.reflectivity = 0.9f;
  scene.objects.push_back({"mirror", sphere, translation({-2.6f, 1.0f, 0.3f}), mirror});
  Material glass = material(glm::vec3(0.0f), glm::vec3(0.9f), 256.0f);
  glass.transparency = 0.95f;
  glass.ior = 1.5f;
  scene.objects.push_back({"glass", sphere, translation({2.6f, 1.0f, 0.3f}), glass});
  Material chrome = material({0.3f, 0.22f, 0.12f}, glm::vec3(0.9f), 128.0f);
  chrome.reflectivity = 0.6f;
  scene.objects.push_back({"teapot", pot,
                           translation({0.0f, 0.0f, -0.8f}) * rotationY(glm::radians(-30.0f)) *
                               scaling(glm::vec3(0.6f)),
                           chrome});
  return scene;
}

// The ray tracer's showcase (Whitted 1980): a mirror sphere and a glass
// sphere (ior 1.5) over a plain floor, a matte box and sphere behind them to
// be seen in the mirror and through the glass, under a point light and a
// directional light, against a sky-blue background.
Scene whittedScene() {
  Scene scene;
  scene.name = "whitted";
  scene.camera.eye = {0.0f, 1.6f, 6.5f};
  scene.camera.at = {0.0f, 0.8f, 0.0f};
  scene.camera.fovyDegrees = 40.0f;
  scene.ambient = glm::vec3(0.4f);
  scene.background = {0.35f, 0.5f, 0.75f};
  scene.lights.push_back(pointLight({-3.0f, 5.0f, 4.0f}, glm::vec3(0.9f), {1.0f, 0.0f, 0.005f}));
  scene.lights.push_back(directionalLight({0.5f, -1.0f, -0.4f}, glm::vec3(0.35f)));
  uint32_t floor = scene.addShape(plane(16.0f, 8));
  uint32_t ball = scene.addShape(uvSphere(0.8f, 48));
  uint32_t cube = scene.addShape(box(glm::vec3(0.5f)));
  scene.objects.push_back({"floor", floor, glm::mat4(1.0f),
                           material({0.55f, 0.5f, 0.45f}, glm::vec3(0.1f), 8.0f)});
  Material mirror = material({0.05f, 0.05f, 0.05f}, glm::vec3(0.9f), 256.0f);
  mirror.reflectivity = 0.85f;
  scene.objects.push_back({"mirror", ball, translation({-1.0f, 0.8f, -0.4f}), mirror});
  Material glass = material({0.02f, 0.02f, 0.02f}, glm::vec3(0.9f), 256.0f);
  glass.reflectivity = 0.1f;
  glass.transparency = 0.85f;
  glass.ior = 1.5f;
  scene.objects.push_back({"glass", ball, translation({0.9f, 0.8f, 1.0f}), glass});
  scene.objects.push_back({"box", cube,
                           translation({1.6f, 0.5f, -1.8f}) * rotationY(glm::radians(25.0f)),
                           material({0.8f, 0.3f, 0.2f}, glm::vec3(0.3f), 32.0f)});
  scene.objects.push_back({"ball", ball,
                           translation({-0.2f, 0.45f, -2.6f}) * scaling(glm::vec3(0.56f)),
                           material({0.2f, 0.6f, 0.3f}, glm::vec3(0.4f), 32.0f)});
  return scene;
}

int32_t addTexture(Scene& scene, Texture texture) {
  scene.textures.push_back(std::move(texture));
  return int32_t(scene.textures.size() - 1);
}

// A checkerboard plane receding to the horizon: from large checks at the
// bottom of the frame to many checks per pixel near the top, where a texture
// without mipmaps aliases into moire. The mipmapping tests' scene.
Scene mipPlaneScene() {
  Scene scene;
  scene.name = "mip-plane";
  scene.camera.eye = {0.0f, 1.0f, 0.0f};
  scene.camera.at = {0.0f, -0.2f, -10.0f};
  scene.camera.fovyDegrees = 50.0f;
  scene.camera.far = 400.0f;
  scene.ambient = glm::vec3(0.35f);
  scene.background = {0.45f, 0.55f, 0.7f};
  scene.lights.push_back(directionalLight({0.3f, -1.0f, -0.4f}, glm::vec3(0.75f)));
  uint32_t ground = scene.addShape(plane(400.0f, 4));
  HeightField checks = proceduralHeight({HeightPattern::Checker, 256, 8});
  Material board = material(glm::vec3(1.0f), glm::vec3(0.0f), 1.0f);
  board.ka = glm::vec3(1.0f);
  board.diffuseMap.texture =
      addTexture(scene, heightColorTexture(checks, glm::vec3(0.04f), glm::vec3(0.85f),
                                           "procedural checker"));
  board.uvScale = glm::vec2(200.0f);  // 2 units per repeat: checks 0.25 units wide
  scene.objects.push_back({"plane", ground, glm::mat4(1.0f), board});
  return scene;
}

// Bump mapping: a wall with a normal map derived from bricks (and their
// colour), and a sphere whose height map of dimples perturbs its normals,
// under a light that grazes the wall so the relief shows.
Scene bumpScene() {
  Scene scene;
  scene.name = "bump";
  scene.camera.eye = {0.0f, 1.2f, 5.5f};
  scene.camera.at = {0.0f, 1.0f, 0.0f};
  scene.camera.fovyDegrees = 45.0f;
  scene.ambient = glm::vec3(0.25f);
  scene.background = {0.03f, 0.03f, 0.04f};
  scene.lights.push_back(pointLight({-3.5f, 3.0f, 2.5f}, glm::vec3(1.0f), {1.0f, 0.0f, 0.01f}));
  scene.lights.push_back(directionalLight({0.6f, -0.3f, -1.0f}, glm::vec3(0.25f)));

  HeightField bricks = proceduralHeight({HeightPattern::Bricks, 256, 8});
  Material wall = material({0.75f, 0.75f, 0.75f}, glm::vec3(0.15f), 16.0f);
  wall.diffuseMap.texture = addTexture(
      scene, heightColorTexture(bricks, {0.35f, 0.33f, 0.3f}, {0.55f, 0.16f, 0.08f},
                                "procedural bricks"));
  wall.normalMap.texture =
      addTexture(scene, normalMapTexture(bricks, 4.0f, "procedural bricks (normal map)"));
  wall.uvScale = glm::vec2(2.0f);
  uint32_t wallMesh = scene.addShape(plane(8.0f, 1));
  scene.objects.push_back({"wall", wallMesh,
                           translation({0.0f, 2.0f, -1.5f}) * rotationX(glm::radians(90.0f)),
                           wall});

  HeightField dimples = proceduralHeight({HeightPattern::Dimples, 128, 4});
  Material ball = material({0.2f, 0.45f, 0.8f}, glm::vec3(0.6f), 48.0f);
  ball.heightMap.texture = addTexture(scene, heightMapTexture(dimples, "procedural dimples"));
  ball.bumpScale = 3.0f;
  ball.uvScale = glm::vec2(4.0f, 2.0f);  // square dimples: the equator is twice a meridian
  uint32_t sphere = scene.addShape(uvSphere(1.0f, 64));
  scene.objects.push_back({"sphere", sphere, translation({0.0f, 1.0f, 0.5f}), ball});
  return scene;
}

const std::map<std::string, std::function<Scene()>>& registry() {
  static const std::map<std::string, std::function<Scene()>> scenes = {
      {"bump", bumpScene},
      {"default", defaultScene},
      {"dense", denseScene},
      {"env", environmentScene},
      {"highlight", [] { return highlightScene(1); }},
      {"mip-plane", mipPlaneScene},
      {"spheres", spheresScene},
      {"teapot", teapotScene},
      {"whitted", whittedScene},
      {"zfight", [] { return zfightScene(Projection::Perspective, 0.1f); }},
  };
  return scenes;
}

}  // namespace

std::vector<std::string> builtinSceneNames() {
  std::vector<std::string> names;
  for (const auto& [name, make] : registry()) names.push_back(name);
  return names;
}

Scene builtinScene(const std::string& name) {
  auto found = registry().find(name);
  if (found == registry().end()) {
    std::string known;
    for (const std::string& candidate : builtinSceneNames())
      known += (known.empty() ? "" : ", ") + candidate;
    throw InputError("unknown scene '" + name + "': not a file and not a built-in scene (" +
                     known + ")");
  }
  return found->second();
}

}  // namespace shadelab
