#include "core/scene/impostor.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include "core/scene/transform.h"

namespace shadelab {
namespace {

float signNotZero(float value) {
  return value < 0.0f ? -1.0f : 1.0f;
}

}  // namespace

ImpostorSphere impostorSphere(const Mesh& mesh) {
  Bounds box = computeBounds(mesh);
  ImpostorSphere sphere{0.5f * (box.min + box.max), 0.0f};
  for (const Vertex& vertex : mesh.vertices)
    sphere.radius = std::max(sphere.radius, glm::length(vertex.position - sphere.centre));
  return sphere;
}

bool impostorRadiusUsable(float radius) {
  return std::isfinite(radius) && radius > 0.0f;
}

bool impostorTransformUsable(const glm::mat4& transform) {
  glm::mat3 linear(transform);
  float scale = std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])});
  if (!(std::isfinite(scale) && scale > 0.0f) || mirrors(transform)) return false;
  constexpr float kTolerance = 1e-4f;
  for (int i = 0; i < 3; ++i) {
    if (!(glm::length(linear[i]) >= scale * (1.0f - kTolerance))) return false;
    if (!(std::abs(glm::dot(linear[i], linear[(i + 1) % 3])) <= kTolerance * scale * scale))
      return false;
  }
  return true;
}

glm::vec2 octahedralEncode(glm::vec3 direction) {
  float l1 = std::abs(direction.x) + std::abs(direction.y) + std::abs(direction.z);
  if (!(l1 > 0.0f)) return glm::vec2(0.0f);  // no direction (or NaN): the +y cell's corner
  glm::vec2 point(direction.x / l1, direction.z / l1);
  if (direction.y < 0.0f)
    point = glm::vec2((1.0f - std::abs(point.y)) * signNotZero(point.x),
                      (1.0f - std::abs(point.x)) * signNotZero(point.y));
  return point;
}

glm::vec3 octahedralDecode(glm::vec2 point) {
  glm::vec3 d(point.x, 1.0f - std::abs(point.x) - std::abs(point.y), point.y);
  if (d.y < 0.0f) {
    float x = (1.0f - std::abs(d.z)) * signNotZero(d.x);
    float z = (1.0f - std::abs(d.x)) * signNotZero(d.z);
    d.x = x;
    d.z = z;
  }
  return glm::normalize(d);
}

ImpostorCell impostorCell(glm::vec3 direction, uint32_t cells) {
  glm::vec2 point = octahedralEncode(direction);
  auto index = [&](float coordinate) {
    float cell = std::floor((coordinate + 1.0f) * 0.5f * float(cells));
    return uint32_t(std::clamp(cell, 0.0f, float(cells - 1)));
  };
  return {index(point.x), index(point.y)};
}

glm::vec3 impostorCellDirection(ImpostorCell cell, uint32_t cells) {
  auto centre = [&](uint32_t index) { return (float(index) + 0.5f) / float(cells) * 2.0f - 1.0f; };
  return octahedralDecode(glm::vec2(centre(cell.column), centre(cell.row)));
}

ImpostorFrame impostorFrame(glm::vec3 direction) {
  glm::vec3 right = glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), direction);
  // Only a direction along y has no frame; no cell of an even count has one.
  right = glm::dot(right, right) > 1e-12f ? glm::normalize(right) : glm::vec3(1.0f, 0.0f, 0.0f);
  return {right, glm::cross(direction, right)};
}

ImpostorBlend impostorBlend(glm::vec3 direction, uint32_t cells) {
  // Grid coordinates in which cell (c, r)'s centre is the point (c, r).
  glm::vec2 grid = (octahedralEncode(direction) + 1.0f) * 0.5f * float(cells) - 0.5f;
  glm::vec2 base = glm::floor(grid);
  glm::vec2 f = grid - base;
  auto cell = [&](float dx, float dy) {
    auto clamped = [&](float index) { return uint32_t(std::clamp(index, 0.0f, float(cells - 1))); };
    return ImpostorCell{clamped(base.x + dx), clamped(base.y + dy)};
  };
  // The grid square's lower-left or upper-right triangle.
  if (f.x + f.y <= 1.0f)
    return {{cell(0, 0), cell(1, 0), cell(0, 1)}, {1.0f - f.x - f.y, f.x, f.y}};
  return {{cell(1, 1), cell(1, 0), cell(0, 1)}, {f.x + f.y - 1.0f, 1.0f - f.y, 1.0f - f.x}};
}

namespace {
// The largest of `angle(direction)` over a grid 16 times finer than the
// cells on the octahedral square, corners included.
template <typename Angle>
float largestOverDirections(uint32_t cells, Angle angle) {
  uint32_t samples = cells * 16;
  float largest = 0.0f;
  for (uint32_t j = 0; j <= samples; ++j)
    for (uint32_t i = 0; i <= samples; ++i) {
      glm::vec2 point(float(i) / float(samples) * 2.0f - 1.0f,
                      float(j) / float(samples) * 2.0f - 1.0f);
      largest = std::max(largest, angle(octahedralDecode(point)));
    }
  return largest;
}

float angleBetween(glm::vec3 a, glm::vec3 b) {
  return std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f));
}
}  // namespace

float impostorParallaxAngle(uint32_t cells) {
  return largestOverDirections(cells, [&](glm::vec3 direction) {
    return angleBetween(direction, impostorCellDirection(impostorCell(direction, cells), cells));
  });
}

float impostorBlendAngle(uint32_t cells) {
  return largestOverDirections(cells, [&](glm::vec3 direction) {
    ImpostorBlend blend = impostorBlend(direction, cells);
    float angle = 0.0f;
    for (size_t k = 0; k < 3; ++k)
      angle +=
          blend.weights[k] * angleBetween(direction, impostorCellDirection(blend.cells[k], cells));
    return angle;
  });
}

namespace {
// The larger of the two angles, found once per cell count: the scans take
// ~11 ms at 16 cells, and every mesh with an impostor asks at upload.
float boundAngle(uint32_t cells) {
  static std::mutex mutex;
  static std::map<uint32_t, float> angles;
  std::lock_guard lock(mutex);
  auto [found, fresh] = angles.try_emplace(cells, 0.0f);
  if (fresh) found->second = std::max(impostorParallaxAngle(cells), impostorBlendAngle(cells));
  return found->second;
}
}  // namespace

float impostorHalfSize(float radius, uint32_t cellTexels) {
  uint32_t inner =
      cellTexels > 2 * kImpostorCellMargin + 1 ? cellTexels - 2 * kImpostorCellMargin : cellTexels;
  return radius * float(cellTexels) / float(inner);
}

float impostorError(float radius, uint32_t cells, uint32_t cellTexels) {
  float texel = 2.0f * impostorHalfSize(radius, cellTexels) / float(cellTexels);
  return radius * std::sin(boundAngle(cells)) + 0.5f * texel;
}

}  // namespace shadelab
