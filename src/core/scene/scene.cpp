#include "core/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/base/errors.h"
#include "core/scene/scene_json_fields.h"
#include "core/scene/transform.h"

namespace shadelab {

glm::mat4 Camera::viewMatrix() const {
  return lookAt(eye, at, up);
}

glm::mat4 Camera::projectionMatrix(float aspect, bool reversedZ) const {
  switch (projection) {
    case Projection::Perspective:
      return reversedZ ? perspectiveReversedZ(glm::radians(fovyDegrees), aspect, near, far)
                       : perspective(glm::radians(fovyDegrees), aspect, near, far);
    case Projection::Frustum:
      return reversedZ ? frustumReversedZ(left, right, bottom, top, near, far)
                       : frustum(left, right, bottom, top, near, far);
    case Projection::Orthographic:
      return reversedZ ? orthographicReversedZ(left, right, bottom, top, near, far)
                       : orthographic(left, right, bottom, top, near, far);
  }
  return glm::mat4(1.0f);
}

namespace {
// Squared, it stays within float range (3.4e38).
constexpr float kMaxCameraDistance = 1e18f;
}  // namespace

std::optional<CameraProblem> findCameraProblem(const Camera& camera) {
  using scene_json::formatNumber;
  if (!(camera.far > camera.near))
    return CameraProblem{"far",
                         "far (" + formatNumber(camera.far) + ") is not beyond near (" +
                             formatNumber(camera.near) + ")",
                         "0 < near < far"};
  if (!(camera.right > camera.left))
    return CameraProblem{"right",
                         "right (" + formatNumber(camera.right) + ") is not greater than left (" +
                             formatNumber(camera.left) + ")",
                         "left < right"};
  if (!(camera.top > camera.bottom))
    return CameraProblem{"top",
                         "top (" + formatNumber(camera.top) + ") is not greater than bottom (" +
                             formatNumber(camera.bottom) + ")",
                         "bottom < top"};
  // Narrower than this the projection's scale (1 / tan, 2 / width) leaves
  // float precision or range: a black or broken image, said here instead.
  if (camera.projection == Projection::Perspective && !(camera.fovyDegrees >= 1e-3f))
    return CameraProblem{"fovy",
                         "fovy " + formatNumber(camera.fovyDegrees) + " degrees is too narrow",
                         "0.001 to 180 degrees"};
  if (camera.projection != Projection::Perspective) {
    const float extent = std::max({std::abs(camera.left), std::abs(camera.right),
                                   std::abs(camera.bottom), std::abs(camera.top)});
    if (!(camera.right - camera.left >= std::max(1e-12f, 1e-6f * extent)) ||
        !(camera.top - camera.bottom >= std::max(1e-12f, 1e-6f * extent)))
      return CameraProblem{"right",
                           "the view window (" + formatNumber(camera.right - camera.left) + " x " +
                               formatNumber(camera.top - camera.bottom) + ") is too small",
                           "a width and height of at least 1e-12 and a millionth of its "
                           "largest coordinate"};
  }
  glm::vec3 view = camera.at - camera.eye;
  if (glm::length(view) == 0.0f)
    return CameraProblem{"at", "at equals eye, so there is no viewing direction",
                         "a point other than eye"};
  // Lengths beyond float range (a coordinate of 1e30 squared) would make
  // the directions below zero and the message blame up.
  if (!(glm::length(view) <= kMaxCameraDistance))
    return CameraProblem{"eye", "eye and at are farther apart than 1e18", "eye within 1e18 of at"};
  if (glm::length(camera.up) == 0.0f)
    return CameraProblem{"up", "zero-length up vector", "a non-zero vector"};
  if (!(glm::length(camera.up) <= kMaxCameraDistance))
    return CameraProblem{"up", "up is longer than 1e18", "a vector of length up to 1e18"};
  // lookAt needs up x (at - eye) to define the camera's x axis.
  if (glm::length(glm::cross(glm::normalize(view), glm::normalize(camera.up))) < 1e-6f)
    return CameraProblem{"up", "up is parallel to the viewing direction at - eye",
                         "a vector not parallel to at - eye"};
  return std::nullopt;
}

namespace {
std::string roundTrip(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}
std::string triple(const glm::vec3& v) {
  return roundTrip(v.x) + "," + roundTrip(v.y) + "," + roundTrip(v.z);
}
}  // namespace

std::string cameraOptionLine(const Camera& camera) {
  return "--eye " + triple(camera.eye) + " --at " + triple(camera.at) + " --up " +
         triple(camera.up) + " --fovy " + roundTrip(camera.fovyDegrees);
}

std::string cameraJson(const Camera& camera) {
  // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on
  // "[" + std::string.
  auto array = [](const glm::vec3& v) {
    std::string text = "[";
    text += roundTrip(v.x) + ", " + roundTrip(v.y) + ", " + roundTrip(v.z) + "]";
    return text;
  };
  std::string json = "{\"eye\": " + array(camera.eye) + ", \"at\": " + array(camera.at) +
                     ", \"up\": " + array(camera.up) + ", \"projection\": \"" +
                     std::string(nameOf(kProjectionNames, camera.projection)) + "\"";
  if (camera.projection == Projection::Perspective)
    json += ", \"fovy\": " + roundTrip(camera.fovyDegrees);
  else
    json += ", \"left\": " + roundTrip(camera.left) + ", \"right\": " + roundTrip(camera.right) +
            ", \"bottom\": " + roundTrip(camera.bottom) + ", \"top\": " + roundTrip(camera.top);
  return json + ", \"near\": " + roundTrip(camera.near) + ", \"far\": " + roundTrip(camera.far) +
         "}";
}

std::vector<std::string> sceneWarnings(const Scene& scene, bool rasteriser) {
  std::vector<std::string> warnings;
  if (scene.lights.empty() && !scene.objects.empty())
    warnings.push_back("scene '" + scene.name +
                       "' has no lights: only ambient light and emission will show");
  if (rasteriser && !scene.environment.present()) {
    size_t count = 0;
    std::string first;
    for (const Object& object : scene.objects)
      if (object.material.reflectivity > 0.0f || object.material.transparency > 0.0f)
        if (count++ == 0) first = object.name;
    if (count > 0)
      warnings.push_back(
          std::to_string(count) + " reflective or transparent object(s) (first: '" + first +
          "') in a scene without an environment: the rasteriser reflects and refracts only the "
          "environment, so they show their local shading alone (add an \"environment\" to the "
          "scene, or see them with `trace`)");
  }
  return warnings;
}

uint32_t Scene::addMesh(Mesh mesh) {
  meshes.push_back(std::move(mesh));
  shapes.push_back(ShapeDesc{});  // ShapeKind::Custom
  return uint32_t(meshes.size() - 1);
}

uint32_t Scene::addShape(const ShapeDesc& shape) {
  meshes.push_back(buildShape(shape));
  shapes.push_back(shape);
  return uint32_t(meshes.size() - 1);
}

void Scene::retessellate(float scale) {
  for (size_t i = 0; i < meshes.size(); ++i)
    if (shapes[i].kind != ShapeKind::Custom) meshes[i] = buildShape(shapes[i], scale);
  tessellationScale = scale;
}

Scene::Estimate Scene::estimate(float scale) const {
  std::vector<MeshSize> perMesh(meshes.size());
  Estimate total;
  for (size_t i = 0; i < meshes.size(); ++i) {
    perMesh[i] = shapes[i].kind == ShapeKind::Custom
                     ? MeshSize{meshes[i].triangleCount(), meshes[i].vertices.size()}
                     : estimateShape(shapes[i], scale);
    total.meshBytes += perMesh[i].bytes();
  }
  for (const Object& object : objects) total.drawnTriangles += perMesh[object.mesh].triangles;
  return total;
}

void checkTriangleBudget(const Scene& scene, float scale, uint64_t maxTriangles,
                         const std::string& request, const std::string& budgetName) {
  Scene::Estimate size = scene.estimate(scale);
  if (size.drawnTriangles <= maxTriangles) return;
  char text[256];
  std::snprintf(text, sizeof text,
                "scene '%s' at %s: an estimated %llu triangles drawn (%.1f MiB of meshes), more "
                "than %s %llu",
                scene.name.c_str(), request.c_str(),
                static_cast<unsigned long long>(size.drawnTriangles),
                double(size.meshBytes) / (1 << 20), budgetName.c_str(),
                static_cast<unsigned long long>(maxTriangles));
  throw InputError(text);
}

uint64_t Scene::triangleCount() const {
  uint64_t count = 0;
  for (const Object& object : objects) count += meshes[object.mesh].triangleCount();
  return count;
}

}  // namespace shadelab
