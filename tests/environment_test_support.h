#pragma once
// Environments whose colour tells the direction it came from, and the
// camera ray through a pixel: what the environment tests measure with.
#include <cmath>
#include <functional>
#include <memory>

#include "core/base/image.h"
#include "core/scene/environment.h"
#include "core/scene/scene.h"

namespace shadelab::test {

// Colour = 0.5 + 0.5 d for a unit direction d: linear in d, so bilinear
// filtering keeps it, and decodeDirection() reads the direction back.
inline glm::vec3 encodeDirection(glm::vec3 d) {
  return 0.5f + 0.5f * glm::normalize(d);
}
inline glm::vec3 decodeDirection(glm::vec4 colour) {
  return glm::normalize(2.0f * glm::vec3(colour) - 1.0f);
}
inline float angleBetweenDegrees(glm::vec3 a, glm::vec3 b) {
  float c = glm::dot(glm::normalize(a), glm::normalize(b));
  return glm::degrees(std::acos(std::clamp(c, -1.0f, 1.0f)));
}

// A sky of one colour in every direction, sun off.
inline Environment constantSky(glm::vec3 colour) {
  Environment environment;
  environment.kind = EnvironmentKind::Sky;
  environment.sky.zenith = environment.sky.horizon = environment.sky.ground = colour;
  environment.sky.sunSizeDegrees = 0.0f;
  environment.resolution = 32;
  return environment;
}

// A panorama of `colour(direction)` at each texel centre.
inline Environment panoramaOf(uint32_t width, uint32_t height, uint32_t resolution,
                              const std::function<glm::vec3(glm::vec3)>& colour) {
  auto image = std::make_shared<ImageRgba>(width, height);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      glm::vec2 uv((float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height));
      image->set(x, y, glm::vec4(colour(equirectDirection(uv)), 1.0f));
    }
  Environment environment;
  environment.kind = EnvironmentKind::Panorama;
  environment.panorama = image;
  environment.resolution = resolution;
  environment.source = "test panorama";
  return environment;
}

// Smooth but with a gradient everywhere: what seams show up in.
inline glm::vec3 wavyColour(glm::vec3 d) {
  glm::vec3 n = glm::normalize(d);
  return 0.5f + 0.4f * glm::sin(3.0f * n + glm::vec3(0.0f, 1.0f, 2.0f));
}

// The world-space direction of the camera ray through pixel (x, y)'s centre.
inline glm::vec3 pixelRay(const Camera& camera, uint32_t width, uint32_t height, uint32_t x,
                          uint32_t y) {
  glm::mat4 toWorld =
      glm::inverse(camera.projectionMatrix(float(width) / float(height)) * camera.viewMatrix());
  glm::vec2 ndc((float(x) + 0.5f) / float(width) * 2.0f - 1.0f,
                (float(y) + 0.5f) / float(height) * 2.0f - 1.0f);
  glm::vec4 near = toWorld * glm::vec4(ndc, 0.0f, 1.0f);
  glm::vec4 far = toWorld * glm::vec4(ndc, 1.0f, 1.0f);
  return glm::normalize(glm::vec3(far) / far.w - glm::vec3(near) / near.w);
}

}  // namespace shadelab::test
