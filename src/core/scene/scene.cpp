#include "core/scene/scene.h"

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
}

uint64_t Scene::triangleCount() const {
  uint64_t count = 0;
  for (const Object& object : objects) count += meshes[object.mesh].triangleCount();
  return count;
}

}  // namespace shadelab
