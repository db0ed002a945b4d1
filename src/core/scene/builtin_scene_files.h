#pragma once
// The built-in scenes' JSON text, embedded at build time from
// assets/scenes/<name>.json (cmake/embed_scenes.cmake). Private to the scene
// library: the rest of the program asks scene.h's builtinScene*() functions.
#include <span>
#include <string_view>

namespace shadelab {

struct EmbeddedSceneFile {
  std::string_view name;  // the built-in's name, the file's stem
  std::string_view json;  // the file's bytes
};

// Sorted by name.
std::span<const EmbeddedSceneFile> builtinSceneFiles();

}  // namespace shadelab
