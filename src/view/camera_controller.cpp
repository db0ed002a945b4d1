#include "view/camera_controller.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>

namespace shadelab {

void CameraController::orbit(glm::vec2 deltaPixels, float viewHeight) {
  float radiansPerPixel = glm::pi<float>() / std::max(viewHeight, 1.0f);
  glm::vec3 up = glm::normalize(camera_.up);
  glm::vec3 offset = camera_.eye - camera_.at;
  // Turning the scene right moves the eye left about the up axis.
  offset = glm::angleAxis(-deltaPixels.x * radiansPerPixel, up) * offset;
  float distance = glm::length(offset);
  float elevation = std::asin(std::clamp(glm::dot(offset / distance, up), -1.0f, 1.0f));
  float limit = glm::radians(89.0f);
  float wanted = std::clamp(elevation - deltaPixels.y * radiansPerPixel, -limit, limit);
  glm::vec3 right = glm::cross(offset, up);  // a positive turn about it raises the eye
  if (glm::length(right) > 1e-6f)
    offset = glm::angleAxis(wanted - elevation, glm::normalize(right)) * offset;
  camera_.eye = camera_.at + offset;
}

void CameraController::pan(glm::vec2 deltaPixels, float viewHeight) {
  glm::vec3 forward = camera_.at - camera_.eye;
  float distance = glm::length(forward);
  forward /= distance;
  glm::vec3 right = glm::normalize(glm::cross(forward, camera_.up));
  glm::vec3 up = glm::cross(right, forward);
  // World units per pixel at the target's depth: the view height there over
  // the height in pixels.
  float worldHeight = camera_.projection == Projection::Perspective
                          ? 2.0f * distance * std::tan(glm::radians(camera_.fovyDegrees) * 0.5f)
                      : camera_.projection == Projection::Frustum
                          ? (camera_.top - camera_.bottom) * distance / camera_.near
                          : camera_.top - camera_.bottom;
  float scale = worldHeight / std::max(viewHeight, 1.0f);
  glm::vec3 move = -(right * deltaPixels.x + up * deltaPixels.y) * scale;
  camera_.eye += move;
  camera_.at += move;
}

void CameraController::zoom(float steps) {
  float factor = std::pow(0.9f, steps);
  glm::vec3 offset = camera_.eye - camera_.at;
  float distance = glm::length(offset);
  if (!(distance > 0.0f)) return;
  // No nearer than twice the near plane, no farther than half the far one:
  // the point looked at stays mid-way in the depth range, so what lies
  // around it is drawn (at the far plane half of it was clipped), and a long
  // zoom out does not reach infinity and a NaN camera.
  float wanted = std::clamp(distance * factor, camera_.near * 2.0f,
                            std::max(camera_.far * 0.5f, camera_.near * 2.0f));
  factor = wanted / distance;
  camera_.eye = camera_.at + offset * factor;
  // An orthographic view does not shrink with distance: scale its volume.
  if (camera_.projection == Projection::Orthographic) {
    camera_.left *= factor;
    camera_.right *= factor;
    camera_.bottom *= factor;
    camera_.top *= factor;
  }
}

}  // namespace shadelab
