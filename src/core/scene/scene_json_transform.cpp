#include "core/scene/scene_json_transform.h"

#include <cmath>
#include <string>

#include "core/scene/transform.h"

namespace shadelab::scene_json {
namespace {

// A coordinate axis named "x", "y" or "z" gives the textbook's R_x, R_y, R_z,
// exact where Rodrigues' formula for [1, 0, 0] may round c + (1 - c) below 1.
glm::mat4 parseRotation(const Field& field) {
  field.expectObject({"axis", "degrees", "about"});
  Field axisField = field.required("axis", "the rotation axis [x, y, z] or \"x\", \"y\", \"z\"");
  float angle = glm::radians(field.required("degrees", "the angle in degrees").number());
  glm::mat4 rotation;
  if (axisField.json().is_string()) {
    size_t index = axisField.choice("axis", {"x", "y", "z"});
    rotation = index == 0 ? rotationX(angle) : index == 1 ? rotationY(angle) : rotationZ(angle);
  } else {
    glm::vec3 axis = axisField.vec3();
    if (glm::length(axis) == 0.0f) axisField.fail("zero-length rotation axis", "a non-zero vector");
    rotation = rotationAxis(axis, angle);
  }
  if (auto about = field.optional("about")) {
    glm::vec3 point = about->vec3();
    return translation(point) * rotation * translation(-point);
  }
  return rotation;
}

glm::mat4 parseScale(const Field& field) {
  glm::vec3 factors = field.vec3OrNumber();
  if (factors.x == 0.0f || factors.y == 0.0f || factors.z == 0.0f)
    field.fail("a scale factor of 0 flattens the object", "non-zero factors");
  return scaling(factors);
}

glm::mat4 parseShear(const Field& field) {
  field.expectObject({"xy", "xz", "yx", "yz", "zx", "zy"});
  Shear shear;
  const std::pair<const char*, float*> factors[] = {{"xy", &shear.xy}, {"xz", &shear.xz},
                                                    {"yx", &shear.yx}, {"yz", &shear.yz},
                                                    {"zx", &shear.zx}, {"zy", &shear.zy}};
  for (auto [key, factor] : factors)
    if (auto f = field.optional(key)) *factor = f->number();
  return shearing(shear);
}

glm::mat4 parseStep(const Field& step) {
  if (!step.json().is_object() || step.json().size() != 1)
    step.wrongType("an object with exactly one of translate, rotate, scale, shear");
  const std::string& key = step.json().begin().key();
  Field value = step.at(key);
  if (key == "translate") return translation(value.vec3());
  if (key == "rotate") return parseRotation(value);
  if (key == "scale") return parseScale(value);
  if (key == "shear") return parseShear(value);
  value.fail("unknown transform \"" + key + "\"", "one of translate, rotate, scale, shear");
}

bool isFinite(const glm::mat4& m) {
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row)
      if (!std::isfinite(m[column][row])) return false;
  return true;
}

}  // namespace

// M = T1 T2 ... Tn: the last step acts on the points first.
glm::mat4 parseTransform(const Field& field) {
  glm::mat4 matrix(1.0f);
  for (const Field& step : field.elements("an array of steps such as {\"translate\": [x, y, z]}"))
    matrix = matrix * parseStep(step);
  float det = glm::determinant(glm::mat3(matrix));
  if (!isFinite(matrix) || !std::isfinite(det))
    field.fail("the matrix overflows a float", "a transform with finite entries");
  // Normals are transformed by the inverse transpose, which needs det != 0.
  if (std::abs(det) < 1e-12f)
    field.fail("the matrix is singular (determinant " + formatNumber(det) + ")",
               "an invertible transform");
  return matrix;
}

}  // namespace shadelab::scene_json
