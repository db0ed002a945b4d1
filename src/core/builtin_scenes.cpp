#include <functional>
#include <map>

#include "core/errors.h"
#include "core/scene.h"
#include "core/transform.h"

namespace shadelab {
namespace {

Material material(glm::vec3 color, glm::vec3 specular, float shininess) {
  return {0.15f * color, color, specular, shininess};
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
  scene.lights.push_back({LightType::Point, {3.0f, 5.0f, 4.0f}, {}, glm::vec3(1.0f),
                          {1.0f, 0.0f, 0.01f}});
  scene.lights.push_back({LightType::Directional, {}, {1.0f, -1.0f, -0.6f},
                          glm::vec3(0.25f, 0.25f, 0.3f), {1.0f, 0.0f, 0.0f}});

  uint32_t floor = scene.addMesh(makePlane(12.0f, 8));
  uint32_t sphere = scene.addMesh(makeUvSphere(0.8f, 48, 24));
  uint32_t torus = scene.addMesh(makeTorus(0.6f, 0.22f, 48, 24));
  uint32_t box = scene.addMesh(makeBox(glm::vec3(0.6f)));
  uint32_t ico = scene.addMesh(makeIcosphere(0.7f, 2));

  scene.objects.push_back({"floor", floor, glm::mat4(1.0f),
                           material({0.45f, 0.45f, 0.42f}, glm::vec3(0.1f), 8.0f)});
  scene.objects.push_back({"sphere", sphere, translation({-2.2f, 0.8f, 0.0f}),
                           material({0.8f, 0.2f, 0.15f}, glm::vec3(0.6f), 64.0f)});
  scene.objects.push_back({"torus", torus,
                           translation({-0.1f, 0.8f, -0.6f}) * rotationX(glm::radians(60.0f)),
                           material({0.2f, 0.6f, 0.3f}, glm::vec3(0.5f), 32.0f)});
  scene.objects.push_back({"box", box,
                           translation({1.9f, 0.6f, 0.3f}) * rotationY(glm::radians(30.0f)),
                           material({0.25f, 0.35f, 0.8f}, glm::vec3(0.4f), 16.0f)});
  scene.objects.push_back({"icosphere", ico, translation({0.2f, 0.7f, 1.6f}),
                           material({0.85f, 0.75f, 0.3f}, glm::vec3(0.8f), 128.0f)});
  return scene;
}

const std::map<std::string, std::function<Scene()>>& registry() {
  static const std::map<std::string, std::function<Scene()>> scenes = {
      {"default", defaultScene},
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
