#pragma once
// Scene files in JSON: the format is documented at the top of scene_json.cpp.
#include <filesystem>
#include <string>
#include <string_view>

#include "core/scene/scene.h"

namespace shadelab {

// The budget a scene file is held to while it loads, before its procedural
// meshes are built (a file of many distinct shapes at tessellation 1024
// would otherwise allocate gigabytes first): the drawn triangles at the
// file's own tessellation, refused above `maxTriangles` naming `option`.
struct TriangleBudget {
  uint64_t maxTriangles = kDefaultMaxTriangles;
  std::string option = "--max-triangles";
};

// Reads and parses a scene file; Scene::name is the file's stem. Throws
// InputError naming the file when it is missing or unreadable, and
// "<file>: <json path>: <what was wrong>, expected <what>" for every problem in it.
// The procedural meshes are built last, once the whole file is read and its
// estimated cost is within `budget` (checkTriangleBudget at scale 1).
Scene loadSceneJson(const std::filesystem::path& path, const TriangleBudget& budget = {});

// The same for text already in memory; `sourceName` starts every message and
// its stem becomes Scene::name.
Scene parseSceneJson(std::string_view text, const std::string& sourceName,
                     const TriangleBudget& budget = {});

}  // namespace shadelab
