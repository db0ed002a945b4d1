#include "core/scene/shadows.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "core/scene/frustum.h"
#include "core/scene/transform.h"

namespace shadelab {
namespace {

std::array<glm::vec3, 8> corners(const Bounds& box) {
  std::array<glm::vec3, 8> points;
  for (int i = 0; i < 8; ++i)
    points[i] = {i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y,
                 i & 4 ? box.max.z : box.min.z};
  return points;
}

Bounds boundsOf(std::span<const glm::vec3> points, const glm::mat4& transform) {
  Bounds box{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
  for (glm::vec3 point : points) {
    glm::vec4 moved = transform * glm::vec4(point, 1.0f);
    glm::vec3 p = glm::vec3(moved) / moved.w;
    box.min = glm::min(box.min, p);
    box.max = glm::max(box.max, p);
  }
  return box;
}

// An up vector not parallel to `forward`.
glm::vec3 upFor(glm::vec3 forward) {
  return std::abs(forward.y) > 0.99f * glm::length(forward) ? glm::vec3(0.0f, 0.0f, 1.0f)
                                                            : glm::vec3(0.0f, 1.0f, 0.0f);
}

}  // namespace

ShadowView directionalShadowView(const Light& light, const Bounds& scene,
                                 const glm::mat4& cameraViewProjection, uint32_t mapSize) {
  glm::vec3 direction = glm::normalize(light.direction);
  glm::vec3 middle = centre(scene);
  float radius = std::max(boundingRadius(scene), 1e-3f);
  glm::mat4 view = lookAt(middle - direction * 2.0f * radius, middle, upFor(direction));
  std::array<glm::vec3, 8> sceneCorners = corners(scene);
  Bounds sceneBox = boundsOf(sceneCorners, view);
  // The camera's frustum: its NDC cube (depth 0..1) taken back to world space.
  std::array<glm::vec3, 8> ndc = corners(Bounds{{-1.0f, -1.0f, 0.0f}, {1.0f, 1.0f, 1.0f}});
  Bounds seen = boundsOf(ndc, view * glm::inverse(cameraViewProjection));
  // Sides: what both boxes hold; when they miss each other, the scene's.
  Bounds sides{glm::max(sceneBox.min, seen.min), glm::min(sceneBox.max, seen.max)};
  if (sides.min.x >= sides.max.x || sides.min.y >= sides.max.y) sides = sceneBox;
  // Depth: the whole scene (eye space looks down -z), with a little room.
  float pad = 0.01f * radius;
  float near = -sceneBox.max.z - pad, far = -sceneBox.min.z + pad;
  glm::mat4 projection =
      orthographic(sides.min.x, sides.max.x, sides.min.y, sides.max.y, near, far);
  float extent = std::max(sides.max.x - sides.min.x, sides.max.y - sides.min.y);
  return ShadowView{{projection * view}, extent / float(mapSize)};
}

ShadowView pointShadowView(const Light& light, const Bounds& scene, uint32_t mapSize,
                           float marginTexels) {
  float far = 0.0f;
  for (glm::vec3 corner : corners(scene)) far = std::max(far, glm::length(corner - light.position));
  far = std::max(far * 1.01f, 1.0f);
  float near = std::min(kPointShadowNear, 0.1f * far);
  // tan(half angle) = 1 plus the margin in the face's units (2 / mapSize per texel).
  float halfTangent = 1.0f + 2.0f * marginTexels / float(mapSize);
  glm::mat4 projection = perspective(2.0f * std::atan(halfTangent), 1.0f, near, far);
  static const glm::vec3 axes[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                    {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  ShadowView view;
  for (glm::vec3 axis : axes)
    view.viewProjection.push_back(projection *
                                  lookAt(light.position, light.position + axis, upFor(axis)));
  view.texelSize = 2.0f * halfTangent / float(mapSize);
  // perspective()'s rows, written out: depth = (far / (far - near)) -
  // (far near / (far - near)) / distance along the face's axis; xy scaled by
  // cot(half angle) = 1 / halfTangent.
  view.cube = glm::vec4(far / (far - near), far * near / (far - near), 1.0f / halfTangent, 0.0f);
  return view;
}

int cubeFace(glm::vec3 v) {
  glm::vec3 a = glm::abs(v);
  if (a.x >= a.y && a.x >= a.z) return v.x >= 0.0f ? 0 : 1;
  if (a.y >= a.z) return v.y >= 0.0f ? 2 : 3;
  return v.z >= 0.0f ? 4 : 5;
}

CubeMapPoint cubeFaceCoordinates(glm::vec3 v, glm::vec4 cube) {
  // Each face's (right, up) as lookAt(light, light + axis, upFor(axis))
  // builds them: +x (z, y), -x (-z, y), +y (x, z), -y (-x, z), +z (-x, y), -z (x, y).
  CubeMapPoint point;
  point.face = cubeFace(v);
  glm::vec3 a = glm::abs(v);
  float major = 0.0f, right = 0.0f, up = 0.0f;
  switch (point.face / 2) {
    case 0:
      major = a.x, right = v.x >= 0.0f ? v.z : -v.z, up = v.y;
      break;
    case 1:
      major = a.y, right = v.y >= 0.0f ? v.x : -v.x, up = v.z;
      break;
    default:
      major = a.z, right = v.z >= 0.0f ? -v.x : v.x, up = v.y;
      break;
  }
  // Vulkan's clip space runs y down: up is -y.
  point.ndc = glm::vec3(cube.z * right / major, -cube.z * up / major, cube.x - cube.y / major);
  return point;
}

}  // namespace shadelab
