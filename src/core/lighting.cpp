#include "core/lighting.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace shadelab {

namespace {

// GLSL's max(x, y) is "x < y ? y : x", so a NaN cosine stays NaN here as it
// does on the GPU; pow(0, 0) is undefined there, hence shininess <= 0 means
// "specular everywhere it is lit".
float specularPower(float cosine, float shininess) {
  return shininess <= 0.0f ? 1.0f : std::pow(std::max(cosine, 0.0f), shininess);
}

// glm::normalize of a zero vector is NaN; this gives the zero vector, which
// contributes nothing, exactly as safeNormalize in the shader.
glm::vec3 safeNormalize(glm::vec3 v) {
  const float len = glm::length(v);
  return len > 1e-20f ? v / len : glm::vec3(0.0f);
}

}  // namespace

glm::vec3 reflectAbout(glm::vec3 towardLight, glm::vec3 normal) {
  return 2.0f * glm::dot(normal, towardLight) * normal - towardLight;
}

glm::vec3 illuminate(const gpu::FrameData& frame, uint32_t lightCount, glm::vec3 position,
                     glm::vec3 normal, const Material& material, bool blinn) {
  assert(lightCount <= MAX_LIGHTS);
  lightCount = std::min<uint32_t>(lightCount, MAX_LIGHTS);
  glm::vec3 N = normal;
  const float lengthN = glm::length(N);
  // Zero-length or NaN normals (bad input) light as ambient only, never NaN.
  const bool validNormal = lengthN > 1e-20f && !std::isnan(lengthN) && !std::isinf(lengthN);
  N = validNormal ? N / lengthN : glm::vec3(0.0f);
  const glm::vec3 V = safeNormalize(-position);
  glm::vec3 color = glm::vec3(frame.ambient) * material.ka;
  for (uint32_t i = 0; i < lightCount; ++i) {
    const gpu::GpuLight& light = frame.lights[i];
    glm::vec3 L;
    float attenuation = 1.0f;
    if (light.type.x == LIGHT_POINT) {
      const glm::vec3 toLight = glm::vec3(light.position) - position;
      const float d = glm::length(toLight);
      // A light exactly at the surface point has no direction: it lights nothing.
      L = safeNormalize(toLight);
      const float denom =
          light.attenuation.x + light.attenuation.y * d + light.attenuation.z * d * d;
      attenuation = denom > 0.0f ? 1.0f / denom : 0.0f;
    } else {
      L = safeNormalize(glm::vec3(light.position));
    }
    const float NdotL = glm::dot(N, L);
    if (NdotL <= 0.0f) continue;
    float specular;
    if (blinn) {
      specular = specularPower(glm::dot(N, safeNormalize(L + V)), material.shininess);
    } else {
      const glm::vec3 R = reflectAbout(L, N);
      specular = specularPower(glm::dot(R, V), material.shininess);
    }
    color +=
        attenuation * glm::vec3(light.intensity) * (material.kd * NdotL + material.ks * specular);
  }
  return color;
}

}  // namespace shadelab
