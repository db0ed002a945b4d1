// The built-in scenes are scene files like any other: assets/scenes/<name>.json,
// embedded in the binary at build time (cmake/embed_scenes.cmake), so they
// need no files at run time and a user can print one, copy it and edit it.
#include <cassert>
#include <nlohmann/json.hpp>

#include "core/base/errors.h"
#include "core/scene/builtin_scene_files.h"
#include "core/scene/scene.h"
#include "core/scene/scene_json.h"

namespace shadelab {
namespace {

const EmbeddedSceneFile* findBuiltin(std::string_view name) {
  for (const EmbeddedSceneFile& file : builtinSceneFiles())
    if (file.name == name) return &file;
  return nullptr;
}

std::string joinedNames() {
  std::string names;
  for (const EmbeddedSceneFile& file : builtinSceneFiles())
    names += (names.empty() ? "" : ", ") + std::string(file.name);
  return names;
}

}  // namespace

std::vector<std::string> builtinSceneNames() {
  std::vector<std::string> names;
  for (const EmbeddedSceneFile& file : builtinSceneFiles()) names.emplace_back(file.name);
  return names;
}

std::string_view builtinSceneJson(const std::string& name) {
  const EmbeddedSceneFile* file = findBuiltin(name);
  if (!file)
    throw InputError("unknown built-in scene '" + name + "', expected one of " + joinedNames());
  return file->json;
}

std::string builtinSceneDescription(const std::string& name) {
  return nlohmann::json::parse(builtinSceneJson(name)).value("description", std::string());
}

// A relative file name in a built-in would be looked up from the working
// directory, as in a copy printed there; the built-ins use only procedural
// content, so they name none (tests/test_builtin_scenes.cpp checks).
Scene builtinScene(const std::string& name) {
  const EmbeddedSceneFile* file = findBuiltin(name);
  if (!file)
    throw InputError("unknown scene '" + name + "': not a file and not a built-in scene (" +
                     joinedNames() + ")");
  Scene scene = parseSceneJson(file->json, "built-in scene '" + name + "'");
  scene.name = name;
  return scene;
}

Scene highlightScene(uint32_t quadsPerSide) {
  Scene scene = builtinScene("highlight");
  assert(scene.shapes.size() == 1 && scene.shapes[0].kind == ShapeKind::Plane);
  scene.shapes[0].tessellation = quadsPerSide;
  scene.meshes[0] = buildShape(scene.shapes[0]);
  return scene;
}

Scene zfightScene(Projection projection, float near) {
  Scene scene = builtinScene("zfight");
  scene.camera.projection = projection;
  scene.camera.near = near;
  return scene;
}

}  // namespace shadelab
