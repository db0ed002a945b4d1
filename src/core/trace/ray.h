#pragma once
// Rays and the optics of the Whitted ray tracer: the mirror direction and
// Snell's law with total internal reflection, as the course writes them.
#include <glm/glm.hpp>
#include <optional>

namespace shadelab {

// A ray origin + t direction. The direction need not be unit length: moved
// into an object's space by an affine inverse, t keeps its meaning.
struct Ray {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 0.0f, -1.0f};
  glm::vec3 at(float t) const { return origin + t * direction; }
};

// Mirror direction of `incident` about unit `normal`: r = d - 2 (d.N) N.
glm::vec3 mirrorDirection(glm::vec3 incident, glm::vec3 normal);

// Snell's law, n1 sin(theta1) = n2 sin(theta2), for unit `incident` and unit
// `normal` facing against it (dot < 0); eta = n1 / n2. With
// cos(theta1) = -d.N and k = 1 - eta^2 (1 - cos^2(theta1)), the transmitted
// direction is eta d + (eta cos(theta1) - sqrt(k)) N, unit length. k < 0 is
// total internal reflection: no transmitted ray (nullopt).
std::optional<glm::vec3> refractDirection(glm::vec3 incident, glm::vec3 normal, float eta);

}  // namespace shadelab
