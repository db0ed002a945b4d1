#pragma once
// Orbit, pan and zoom around the camera's target, driven by mouse motion in
// view coordinates (pixels, y up). Until moved, camera() is the scene's
// camera exactly, so an unmoved viewer matches a headless render.
#include <glm/glm.hpp>

#include "core/scene/scene.h"

namespace shadelab {

class CameraController {
 public:
  explicit CameraController(const Camera& initial) : camera_(initial) {}

  // A drag across the whole view height turns the camera by 180 degrees about
  // the target; right turns the scene right, up turns its front upwards (the
  // eye goes down). Elevation stays within 89 degrees of the up axis's equator.
  void orbit(glm::vec2 deltaPixels, float viewHeight);
  // Moves eye and target together so the point at the target's depth follows
  // the cursor.
  void pan(glm::vec2 deltaPixels, float viewHeight);
  // Positive steps move towards the target: distance x 0.9 per step.
  void zoom(float steps);

  const Camera& camera() const { return camera_; }
  void set(const Camera& camera) { camera_ = camera; }  // a camera path's next frame

 private:
  Camera camera_;
};

}  // namespace shadelab
