#include "core/scene/lighting.h"

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

namespace {

// What one light adds: f_att Ip [kd (N.L) + ks (R.V)^n], nothing where N.L <= 0.
glm::vec3 lightTerm(glm::vec3 N, glm::vec3 V, glm::vec3 L, float attenuation, glm::vec3 intensity,
                    const Material& material, bool blinn) {
  const float NdotL = glm::dot(N, L);
  float specular;
  if (blinn) {
    specular = specularPower(glm::dot(N, safeNormalize(L + V)), material.shininess);
  } else {
    specular = specularPower(glm::dot(reflectAbout(L, N), V), material.shininess);
  }
  const float facing = NdotL > 0.0f ? attenuation : 0.0f;
  return facing * intensity * (material.kd * NdotL + material.ks * specular);
}

}  // namespace

glm::vec3 illuminate(glm::vec3 ambient, std::span<const Light> lights, glm::vec3 position,
                     glm::vec3 normal, const Material& material, bool blinn,
                     std::span<const float> shadowCoefficients) {
  assert(shadowCoefficients.empty() || shadowCoefficients.size() == lights.size());
  // Zero-length, NaN or infinite normals (bad input) light as ambient only,
  // never NaN: a NaN length fails both comparisons.
  const float lengthN2 = glm::dot(normal, normal);
  const glm::vec3 N =
      lengthN2 > 1e-40f && lengthN2 < 1e30f ? normal / std::sqrt(lengthN2) : glm::vec3(0.0f);
  const glm::vec3 V = safeNormalize(-position);
  glm::vec3 color = ambient * material.ka;
  // Lights in any order, each by its type (the shader relies on makeFrameData
  // putting point lights first; the equation does not care).
  for (size_t i = 0; i < lights.size(); ++i) {
    const Light& light = lights[i];
    glm::vec3 L;
    float attenuation = 1.0f;
    if (light.type == LightType::Point) {
      const glm::vec3 toLight = light.position - position;
      const float d = glm::length(toLight);
      // A light exactly at the surface point has no direction: it lights nothing.
      L = safeNormalize(toLight);
      const float denom =
          light.attenuation.x + light.attenuation.y * d + light.attenuation.z * d * d;
      attenuation = denom > 0.0f ? 1.0f / denom : 0.0f;
    } else {
      L = safeNormalize(-light.direction);
    }
    glm::vec3 term = lightTerm(N, V, L, attenuation, light.intensity, material, blinn);
    // k_shadow,i scales the light's whole term, as shaders/lighting.glsl does.
    if (!shadowCoefficients.empty()) term *= shadowCoefficients[i];
    color += term;
  }
  return color;
}

Light lightInView(const Light& light, const glm::mat4& view) {
  Light moved = light;
  moved.position = glm::vec3(view * glm::vec4(light.position, 1.0f));
  // Directions transform without translation. Worked out towards the light,
  // the vector the shaders and illuminate() use, then negated: negating it
  // back (makeFrameData, illuminate) is exact, zero components included, so
  // GPU and CPU light with the same bits.
  const glm::vec3 toward = glm::mat3(view) * -light.direction;
  const float length = glm::length(toward);
  moved.direction = -(length > 0.0f ? toward / length : glm::vec3(0.0f));
  return moved;
}

}  // namespace shadelab
