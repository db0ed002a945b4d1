#pragma once
// The "transform" of the JSON scene format (documented at the top of
// scene_json.cpp): a list of translate / rotate / scale / shear steps, their
// product in list order. Private to scene_json*.cpp.
#include <glm/glm.hpp>

#include "core/scene/scene_json_fields.h"

namespace shadelab::scene_json {

// M = T1 T2 ... Tn (the last step acts on the points first); fails unless M
// is finite and invertible.
glm::mat4 parseTransform(const Field& field);

}  // namespace shadelab::scene_json
