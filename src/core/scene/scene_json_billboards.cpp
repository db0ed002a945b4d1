#include "core/scene/scene_json_billboards.h"

#include <cmath>
#include <cstdint>
#include <optional>
#include <random>

#include "core/scene/scene_json_transform.h"
#include "core/scene/transform.h"
#include "interface.h"

namespace shadelab::scene_json {
namespace {

const std::string kLimitName = "MAX_INSTANCES_PER_OBJECT";

[[noreturn]] void failCount(const Field& field, const std::string& count) {
  field.fail(
      count + " instances is above the limit",
      "at most " + std::to_string(MAX_INSTANCES_PER_OBJECT) + " per object (" + kLimitName + ")");
}

// A count read as a JSON number before it is an integer, so that a value
// beyond uint32_t still gets the limit's message rather than a range one.
uint32_t instanceCount(const Field& field) {
  if (field.json().is_number() && field.json().get<double>() > MAX_INSTANCES_PER_OBJECT)
    failCount(field, describe(field.json()));
  return field.integer(1, MAX_INSTANCES_PER_OBJECT, "instances");
}

std::vector<glm::mat4> listInstances(const Field& field) {
  std::vector<Field> entries = field.elements(
      "an array of transforms, one per instance, e.g. [[{\"translate\": [1, 0, 0]}]]");
  if (entries.empty()) field.fail("no instances", "at least one transform");
  if (entries.size() > MAX_INSTANCES_PER_OBJECT) failCount(field, std::to_string(entries.size()));
  std::vector<glm::mat4> local;
  local.reserve(entries.size());
  for (const Field& entry : entries) local.push_back(parseTransform(entry));
  return local;
}

// nx x ny x nz copies `spacing` apart, centred on the object's origin.
std::vector<glm::mat4> gridInstances(const Field& field) {
  field.expectObject({"count", "spacing"});
  Field countField = field.required("count", "[nx, ny, nz], copies along each axis");
  std::vector<Field> counts = countField.elements("[nx, ny, nz]");
  if (counts.size() != 3) countField.wrongType("[nx, ny, nz]");
  uint64_t total = 1;
  glm::uvec3 n;
  for (int axis = 0; axis < 3; ++axis) {
    n[axis] = instanceCount(counts[size_t(axis)]);
    total *= n[axis];  // each <= 2^18, so the product of three fits in 64 bits
  }
  if (total > MAX_INSTANCES_PER_OBJECT) failCount(countField, std::to_string(total));
  glm::vec3 spacing(1.0f);
  if (auto f = field.optional("spacing")) spacing = f->vec3OrNumber();
  std::vector<glm::mat4> local;
  local.reserve(total);
  for (uint32_t k = 0; k < n.z; ++k)
    for (uint32_t j = 0; j < n.y; ++j)
      for (uint32_t i = 0; i < n.x; ++i) {
        glm::vec3 index{float(i), float(j), float(k)};
        local.push_back(translation((index - 0.5f * (glm::vec3(n) - 1.0f)) * spacing));
      }
  return local;
}

// A float in [0, 1) from the top 24 bits of a 32-bit draw: the same on every
// platform, unlike std::uniform_real_distribution.
float unitFloat(std::mt19937& random) {
  return float(random() >> 8) * (1.0f / 16777216.0f);
}

// `count` copies at uniformly random points of a width x depth rectangle in
// the object's xz plane (centred on its origin), each scaled by a factor
// uniform in [min, max] and, with "yaw", turned about y by an angle uniform
// in [min, max] degrees (from a generator of its own, so adding it moves no
// copy); the same seed gives the same copies everywhere (std::mt19937 is
// specified bit for bit).
std::vector<glm::mat4> scatterInstances(const Field& field) {
  field.expectObject({"count", "seed", "rectangle", "scale", "yaw"});
  uint32_t count = instanceCount(field.required(
      "count", "the number of copies (1.." + std::to_string(MAX_INSTANCES_PER_OBJECT) + ")"));
  uint32_t seed = 1;
  if (auto f = field.optional("seed")) seed = f->integer(0, UINT32_MAX, "the random seed");
  Field rectangleField = field.required("rectangle", "[width, depth] of the area in the xz plane");
  std::vector<Field> sides = rectangleField.elements("[width, depth]");
  if (sides.size() != 2) rectangleField.wrongType("[width, depth]");
  float width = sides[0].nonNegative(), depth = sides[1].nonNegative();
  if (!(width * depth > 0.0f))
    rectangleField.fail("[" + formatNumber(width) + ", " + formatNumber(depth) + "] has no area",
                        "a width and a depth > 0 to scatter over");
  float minScale = 1.0f, maxScale = 1.0f;
  if (auto f = field.optional("scale")) {
    std::vector<Field> range = f->elements("[min, max] scale factors");
    if (range.size() != 2) f->wrongType("[min, max] scale factors");
    minScale = range[0].positive();
    maxScale = range[1].positive();
    if (minScale > maxScale) f->fail("min is above max", "[min, max] with 0 < min <= max");
  }
  std::optional<glm::vec2> yaw;
  if (auto f = field.optional("yaw")) {
    std::vector<Field> range = f->elements("[min, max] degrees about y");
    if (range.size() != 2) f->wrongType("[min, max] degrees about y");
    yaw = glm::vec2(range[0].number(), range[1].number());
    if (!(yaw->x <= yaw->y) || !(yaw->y - yaw->x <= 360.0f) || std::abs(yaw->x) > 360.0f)
      f->fail("[" + formatNumber(yaw->x) + ", " + formatNumber(yaw->y) + "]",
              "[min, max] degrees with -360 <= min <= max <= min + 360");
  }
  std::mt19937 random(seed);
  std::mt19937 turns(seed ^ 0x9e3779b9u);
  std::vector<glm::mat4> local;
  local.reserve(count);
  for (uint32_t i = 0; i < count; ++i) {
    float x = (unitFloat(random) - 0.5f) * width;
    float z = (unitFloat(random) - 0.5f) * depth;
    float scale = minScale + (maxScale - minScale) * unitFloat(random);
    glm::mat4 copy = translation({x, 0.0f, z}) * scaling(glm::vec3(scale));
    if (yaw) copy = copy * rotationY(glm::radians(yaw->x + (yaw->y - yaw->x) * unitFloat(turns)));
    local.push_back(copy);
  }
  return local;
}

}  // namespace

const Names& billboardFields() {
  static const Names fields = {
      "kind", "size", "axis", "anchor", "alpha", "alpha_cutoff", "receives_shadows", "instances"};
  return fields;
}

std::vector<glm::mat4> parseInstances(const Field& field, const glm::mat4& world) {
  field.expectObject({"list", "grid", "scatter"});
  if (field.json().size() != 1)
    field.fail("it has " + std::to_string(field.json().size()) + " kinds of placement",
               "exactly one of \"list\", \"grid\", \"scatter\"");
  std::vector<glm::mat4> local;
  if (auto f = field.optional("list")) local = listInstances(*f);
  if (auto f = field.optional("grid")) local = gridInstances(*f);
  if (auto f = field.optional("scatter")) local = scatterInstances(*f);
  for (size_t i = 0; i < local.size(); ++i) {
    glm::mat4& matrix = local[i];
    matrix = world * matrix;
    // A grid's spacing or a scatter's rectangle can place copies past the
    // float range, where one transform alone would have been refused.
    for (int column = 0; column < 4; ++column)
      for (int row = 0; row < 4; ++row)
        if (!std::isfinite(matrix[column][row]))
          field.fail("copy " + std::to_string(i + 1) + " of " + std::to_string(local.size()) +
                         " lands outside the float range",
                     "copies whose transforms (with the object's own) stay finite");
  }
  return local;
}

Billboard parseBillboard(const Field& object, const std::string& name, const glm::mat4& world,
                         const Material& material) {
  Billboard billboard;
  billboard.name = name;
  billboard.material = material;
  if (!material.diffuseMap.present())
    object.at("material")
        .fail("a billboard without a diffuse_map",
              "a material with a \"diffuse_map\" (the quad's colour and its alpha cut-out)");
  if (auto f = object.optional("kind")) billboard.kind = f->choose("kind", kBillboardKindNames);
  if (auto f = object.optional("anchor"))
    billboard.anchor = f->choose("anchor", kBillboardAnchorNames);
  if (auto f = object.optional("alpha")) billboard.alpha = f->choose("alpha", kBillboardAlphaNames);
  if (auto f = object.optional("size")) {
    if (f->json().is_number()) {
      billboard.size = glm::vec2(f->positive());
    } else {
      std::vector<Field> sides = f->elements("[width, height] or one number");
      if (sides.size() != 2) f->wrongType("[width, height] or one number");
      billboard.size = {sides[0].positive(), sides[1].positive()};
    }
  }
  if (auto f = object.optional("axis")) {
    billboard.axis = f->vec3();
    if (glm::length(billboard.axis) == 0.0f) f->fail("zero-length axis", "a non-zero vector");
    billboard.axis = glm::normalize(billboard.axis);
  }
  // The cut-off applies to alpha test; 0.5 unless given.
  billboard.material.alphaCutoff = 0.5f;
  if (auto f = object.optional("alpha_cutoff")) {
    float cutoff = f->number();
    if (!(cutoff >= 0.0f && cutoff <= 1.0f))
      f->fail("alpha_cutoff " + formatNumber(cutoff) + " is outside 0..1",
              "a texel alpha from 0 to 1 below which the quad is cut away");
    billboard.material.alphaCutoff = cutoff;
  }
  if (auto f = object.optional("receives_shadows")) billboard.receivesShadows = f->boolean();
  if (auto f = object.optional("instances"))
    billboard.instances = parseInstances(*f, world);
  else
    billboard.instances = {world};
  return billboard;
}

}  // namespace shadelab::scene_json
