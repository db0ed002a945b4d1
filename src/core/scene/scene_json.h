#pragma once
// Scene files in JSON: the format is documented at the top of scene_json.cpp.
#include <filesystem>
#include <string>
#include <string_view>

#include "core/scene/scene.h"

namespace shadelab {

// Reads and parses a scene file; Scene::name is the file's stem. Throws
// InputError naming the file when it is missing or unreadable, and
// "<file>: <json path>: <what was wrong>, expected <what>" for every problem in it.
Scene loadSceneJson(const std::filesystem::path& path);

// The same for text already in memory; `sourceName` starts every message and
// its stem becomes Scene::name.
Scene parseSceneJson(std::string_view text, const std::string& sourceName);

}  // namespace shadelab
