#pragma once
// Reflection and refraction directions and the Fresnel weight, as the course
// states them. The GLSL twin is shaders/environment.glsl; tests check both.
// N is the unit surface normal, V the unit direction from the surface towards
// the viewer (both on the same side for a front face).
#include <glm/glm.hpp>

namespace shadelab {

// The mirror direction R = 2 (N.V) N - V.
glm::vec3 reflectionDirection(glm::vec3 normal, glm::vec3 toViewer);

struct Refraction {
  glm::vec3 direction{0.0f};  // unit transmitted direction; R when totally reflected
  float cosTransmitted = 0.0f;
  bool totalInternalReflection = false;
};

// Snell's law n1 sin(theta_i) = n2 sin(theta_t) with eta = n1 / n2:
// T = -eta V + (eta cos_i - cos_t) N, cos_t = sqrt(1 - eta^2 (1 - cos_i^2)).
// When the radicand is negative the light is totally reflected: T = R.
Refraction refractionDirection(glm::vec3 normal, glm::vec3 toViewer, float eta);

// Schlick's approximation F = F0 + (1 - F0) (1 - cos)^5, F0 = ((n1 - n2) / (n1 + n2))^2,
// with cos the angle on the optically thinner side (cos_i entering a denser
// medium, cos_t leaving one); 1 under total internal reflection.
float schlickFresnel(float cosIncident, float n1, float n2);

// What the environment adds to the local Phong colour at a surface point
// (README "Environment mapping"):
//   kr env(R) + kt [F env(R) + (1 - F) env(T)],  eta = 1 / ior entering from air.
struct EnvironmentSample {
  glm::vec3 reflected{0.0f};    // env(R)
  glm::vec3 transmitted{0.0f};  // env(T)
};
glm::vec3 environmentContribution(float reflectivity, float transparency, float fresnel,
                                  const EnvironmentSample& sample);

}  // namespace shadelab
