#pragma once
#include <string>

#include "core/scene/scene.h"

namespace shadelab {

// SCENE on the command line: empty for the default scene, a built-in scene
// name, or a scene file. Throws InputError naming what was wrong.
Scene loadScene(const std::string& nameOrPath);

}  // namespace shadelab
