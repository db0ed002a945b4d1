#include "core/trace/optics.h"

#include <algorithm>
#include <cmath>

namespace shadelab {

glm::vec3 reflectionDirection(glm::vec3 normal, glm::vec3 toViewer) {
  return 2.0f * glm::dot(normal, toViewer) * normal - toViewer;
}

Refraction refractionDirection(glm::vec3 normal, glm::vec3 toViewer, float eta) {
  float cosI = glm::dot(normal, toViewer);
  float radicand = 1.0f - eta * eta * (1.0f - cosI * cosI);
  Refraction result;
  if (radicand < 0.0f) {
    result.direction = reflectionDirection(normal, toViewer);
    result.totalInternalReflection = true;
    return result;
  }
  result.cosTransmitted = std::sqrt(radicand);
  result.direction = -eta * toViewer + (eta * cosI - result.cosTransmitted) * normal;
  return result;
}

float schlickFresnel(float cosIncident, float n1, float n2) {
  float cosI = std::clamp(cosIncident, 0.0f, 1.0f);
  float cosine = cosI;
  if (n1 > n2) {
    float eta = n1 / n2;
    float radicand = 1.0f - eta * eta * (1.0f - cosI * cosI);
    if (radicand < 0.0f) return 1.0f;
    cosine = std::sqrt(radicand);
  }
  float f0 = (n1 - n2) / (n1 + n2);
  f0 *= f0;
  return f0 + (1.0f - f0) * std::pow(1.0f - cosine, 5.0f);
}

glm::vec3 environmentContribution(float reflectivity, float transparency, float fresnel,
                                  const EnvironmentSample& sample) {
  return reflectivity * sample.reflected +
         transparency * (fresnel * sample.reflected + (1.0f - fresnel) * sample.transmitted);
}

}  // namespace shadelab
