#include "core/trace/ray.h"

#include <cmath>

namespace shadelab {

glm::vec3 mirrorDirection(glm::vec3 incident, glm::vec3 normal) {
  return incident - 2.0f * glm::dot(incident, normal) * normal;
}

std::optional<glm::vec3> refractDirection(glm::vec3 incident, glm::vec3 normal, float eta) {
  const float cosIncident = -glm::dot(incident, normal);
  const float k = 1.0f - eta * eta * (1.0f - cosIncident * cosIncident);
  // `!(k >= 0)` also turns a NaN input into "no transmitted ray".
  if (!(k >= 0.0f)) return std::nullopt;
  return eta * incident + (eta * cosIncident - std::sqrt(k)) * normal;
}

}  // namespace shadelab
