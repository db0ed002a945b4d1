#pragma once
// Billboard objects and "instances" blocks of the JSON scene format
// (documented at the top of scene_json.cpp). Private to scene_json*.cpp.
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "core/scene/scene.h"
#include "core/scene/scene_json_fields.h"

namespace shadelab::scene_json {

// The fields a billboard object takes besides "name", "shape", "transform",
// "children" and "material".
const Names& billboardFields();

// An "instances" block: {"list": [...]}, {"grid": {...}} or {"scatter": {...}},
// as world matrices (`world` times each copy's own). Fails naming the field
// for a count above MAX_INSTANCES_PER_OBJECT or a scatter area of zero.
std::vector<glm::mat4> parseInstances(const Field& field, const glm::mat4& world);

// A billboard object; `material` is its parsed material, which must have a
// diffuse map (the quad's colour and alpha).
Billboard parseBillboard(const Field& object, const std::string& name, const glm::mat4& world,
                         const Material& material);

}  // namespace shadelab::scene_json
