#pragma once
#include <string>

#include "core/scene/scene.h"
#include "core/scene/scene_json.h"  // TriangleBudget

namespace shadelab {

// SCENE on the command line: empty for the default scene, a built-in scene
// name, or a scene file. Throws InputError naming what was wrong, and for a
// scene JSON whose meshes would exceed `budget`, before they are built.
Scene loadScene(const std::string& nameOrPath, const TriangleBudget& budget = {});

}  // namespace shadelab
