// Environment mapping in the forward pass (mirrored in src/core/trace/optics.cpp):
//   R = 2 (N.V) N - V,
//   T by Snell's law with eta = 1 / ior (entering from air), T = R under
//     total internal reflection,
//   F = Schlick's F0 + (1 - F0) (1 - cos)^5, cos on the thinner side,
//   added colour = kr env(R) + kt [F env(R) + (1 - F) env(T)].
// N and V are in eye space like the rest of the lighting; R and T turn into
// world space (FrameData.viewToWorld) because the cube map is in world space.
#ifndef ENVIRONMENT_GLSL
#define ENVIRONMENT_GLSL
#include "lighting.glsl"

layout(set = 0, binding = BINDING_ENVIRONMENT) uniform samplerCube environmentMap;
layout(constant_id = SPEC_ENVIRONMENT) const bool environmentEnabled = false;
layout(constant_id = SPEC_ENVIRONMENT_REFRACTS) const bool environmentRefracts = false;

vec3 reflectionDirection(vec3 N, vec3 V) { return 2.0 * dot(N, V) * N - V; }

// Snell's law n1 sin(theta_i) = n2 sin(theta_t), eta = n1 / n2:
// T = -eta V + (eta cos_i - cos_t) N, cos_t = sqrt(1 - eta^2 (1 - cos_i^2)).
// A negative radicand is total internal reflection: cosT < 0 flags it.
vec3 refractionDirection(vec3 N, vec3 V, float eta, out float cosT) {
  float cosI = dot(N, V);
  float radicand = 1.0 - eta * eta * (1.0 - cosI * cosI);
  cosT = radicand >= 0.0 ? sqrt(radicand) : -1.0;
  return radicand >= 0.0 ? -eta * V + (eta * cosI - cosT) * N : reflectionDirection(N, V);
}

float schlickFresnel(float cosI, float cosT, float n1, float n2) {
  if (n1 > n2 && cosT < 0.0) return 1.0;  // total internal reflection
  float cosine = n1 > n2 ? cosT : clamp(cosI, 0.0, 1.0);
  float f0 = (n1 - n2) / (n1 + n2);
  f0 *= f0;
  return f0 + (1.0 - f0) * pow(1.0 - cosine, 5.0);
}

// What a surface point needs for its lookups: world-space R (xyz) with the
// Fresnel weight (w), and world-space T. Computed per fragment (Phong,
// Blinn-Phong), per vertex and interpolated (Gouraud) or per triangle (flat).
struct EnvironmentDirections {
  vec4 reflected;
  vec4 refracted;
};

EnvironmentDirections environmentDirections(vec3 position, vec3 normal, float ior) {
  vec3 N = safeNormalize(normal);
  vec3 V = safeNormalize(-position);
  mat3 toWorld = mat3(frame.viewToWorld);
  float cosT;
  vec3 T = refractionDirection(N, V, 1.0 / ior, cosT);
  float F = schlickFresnel(dot(N, V), cosT, 1.0, ior);
  return EnvironmentDirections(vec4(toWorld * reflectionDirection(N, V), F),
                               vec4(toWorld * T, 0.0));
}

vec3 environmentColor(EnvironmentDirections directions, float kr, float kt) {
  vec3 reflected = texture(environmentMap, directions.reflected.xyz).rgb;
  vec3 color = kr * reflected;
  // Opaque mirrors have no refraction code at all (SPEC_ENVIRONMENT_REFRACTS).
  if (environmentRefracts && kt > 0.0) {
    float F = directions.reflected.w;
    vec3 transmitted = texture(environmentMap, directions.refracted.xyz).rgb;
    color += kt * (F * reflected + (1.0 - F) * transmitted);
  }
  return color;
}
#endif
