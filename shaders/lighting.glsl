// The Phong illumination equation, the one implementation every pass uses:
//   I = Ia ka + sum_i f_att,i Ip,i [ kd (N.L_i) + ks (R_i.V)^n ]
// with f_att = 1 / (a + b d + c d^2) for point lights and 1 for directional
// ones. Blinn-Phong replaces (R.V)^n with (N.H)^n, H = normalize(L + V).
// There is no specular term where N.L <= 0 (the light is behind the surface).
// Everything is in eye space, so V = normalize(-position).
// With shadows, each light's term is scaled by its shadow coefficient:
//   I = Ia ka + sum_i k_shadow,i f_att,i Ip,i [ ... ],  k_shadow in 0..1
// (shadows.glsl). Only the fragment stage looks the maps up (SHADOW_LOOKUP):
// flat and Gouraud keep each light's term apart (illuminateEach) and their
// fragment stage applies k_shadow per light, per fragment, since a shadow
// edge runs through triangles and does not follow their vertices.
#ifndef LIGHTING_GLSL
#define LIGHTING_GLSL
#include "common.glsl"
#include "shadows.glsl"

struct SurfaceMaterial {
  vec3 ka;
  vec3 kd;
  vec3 ks;
  float shininess;
};

// The draw's material: compiled in, or from its push constants (common.glsl).
SurfaceMaterial drawMaterial() {
  if (materialConstants)
    return SurfaceMaterial(vec3(materialKaR, materialKaG, materialKaB),
                           vec3(materialKdR, materialKdG, materialKdB),
                           vec3(materialKsR, materialKsG, materialKsB), materialShininess);
  return SurfaceMaterial(draw.ka.rgb, draw.kd.rgb, draw.ks.rgb, draw.ks.w);
}

// The draw's emission, added unlit to every lit model's colour: compiled in,
// or from its push constants (RGB9E5 bits, interface.h).
vec3 drawEmissive() {
  uint bits = materialConstants ? materialEmissive : uint(draw.object.w);
  int exponent = int(bits >> 27u) - 15 - 9;
  return vec3(ldexp(float(bits & 511u), exponent), ldexp(float((bits >> 9u) & 511u), exponent),
              ldexp(float((bits >> 18u) & 511u), exponent));
}

// pow(0, 0) is undefined in GLSL; shininess 0 means "specular everywhere it is lit".
float specularPower(float cosine, float shininess) {
  return shininess <= 0.0 ? 1.0 : pow(max(cosine, 0.0), shininess);
}

// normalize() of a zero vector is NaN; here it is the zero vector, which
// contributes nothing (an eye exactly at the point, L = -V for Blinn, a
// directional light with no direction).
vec3 safeNormalize(vec3 v) {
  float len2 = dot(v, v);
  return len2 > 1e-40 ? v * inversesqrt(len2) : vec3(0.0);
}

// What one light adds at a point: f_att Ip [kd (N.L) + ks (R.V)^n], and
// nothing where N.L <= 0 (the light is behind the surface). L is the unit
// direction towards the light, or zero for a light with no direction.
vec3 lightTerm(vec3 N, vec3 V, vec3 L, float attenuation, vec3 intensity,
               SurfaceMaterial material, bool blinn) {
  float NdotL = dot(N, L);
  float specular;
  if (blinn) {
    specular = specularPower(dot(N, safeNormalize(L + V)), material.shininess);
  } else {
    vec3 R = 2.0 * NdotL * N - L;  // reflection of L about N
    specular = specularPower(dot(R, V), material.shininess);
  }
  // A select, not a branch: lavapipe runs SIMD lanes in lockstep.
  float facing = NdotL > 0.0 ? attenuation : 0.0;
  return facing * intensity * (material.kd * NdotL + material.ks * specular);
}

vec3 illuminate(vec3 position, vec3 normal, SurfaceMaterial material, bool blinn) {
  // Zero-length, NaN or infinite normals (bad input) light as ambient only,
  // never NaN: a NaN length fails both comparisons.
  float lengthN2 = dot(normal, normal);
  vec3 N = lengthN2 > 1e-40 && lengthN2 < 1e30 ? normal * inversesqrt(lengthN2) : vec3(0.0);
  vec3 V = safeNormalize(-position);
  vec3 color = frameAmbient() * material.ka;
  // frameLight(i): the point lights first, then the directional ones.
  for (int i = 0; i < pointLightCount; ++i) {
    GpuLight light = frameLight(i);
    vec3 toLight = light.position.xyz - position;
    float d2 = dot(toLight, toLight);
    // A light exactly at the surface point has no direction: it lights nothing.
    float inverseD = d2 > 1e-40 ? inversesqrt(d2) : 0.0;
    float attenuation = 1.0;  // f_att of (a, b, c) = (1, 0, 0)
    if (pointLightsAttenuate) {
      float d = d2 * inverseD;
      float denom = light.attenuation.x + light.attenuation.y * d + light.attenuation.z * d2;
      attenuation = denom > 0.0 ? 1.0 / denom : 0.0;
    }
    vec3 L = toLight * inverseD;
    vec3 term = lightTerm(N, V, L, attenuation, light.intensity.rgb, material, blinn);
    if (shadowsLookedUp) term *= shadowCoefficient(i, position, N);
    color += term;
  }
  for (int i = pointLightCount; i < pointLightCount + directionalLightCount; ++i) {
    GpuLight light = frameLight(i);
    // Unit length already (or zero), normalised once on the host.
    vec3 term = lightTerm(N, V, light.position.xyz, 1.0, light.intensity.rgb, material, blinn);
    if (shadowsLookedUp) term *= shadowCoefficient(i, position, N);
    color += term;
  }
  return color;
}

// The equation with each light's term apart, for flat and Gouraud with
// shadows: I = ambient + sum_i k_shadow,i terms[i], k_shadow found later,
// per fragment. Lights past the layout's count get zero.
void illuminateEach(vec3 position, vec3 normal, SurfaceMaterial material, bool blinn,
                    out vec3 ambient, out vec3 terms[MAX_LIGHTS]) {
  float lengthN2 = dot(normal, normal);
  vec3 N = lengthN2 > 1e-40 && lengthN2 < 1e30 ? normal * inversesqrt(lengthN2) : vec3(0.0);
  vec3 V = safeNormalize(-position);
  ambient = frameAmbient() * material.ka;
  for (int i = 0; i < MAX_LIGHTS; ++i) terms[i] = vec3(0.0);
  for (int i = 0; i < pointLightCount; ++i) {
    GpuLight light = frameLight(i);
    vec3 toLight = light.position.xyz - position;
    float d2 = dot(toLight, toLight);
    float inverseD = d2 > 1e-40 ? inversesqrt(d2) : 0.0;
    float attenuation = 1.0;
    if (pointLightsAttenuate) {
      float d = d2 * inverseD;
      float denom = light.attenuation.x + light.attenuation.y * d + light.attenuation.z * d2;
      attenuation = denom > 0.0 ? 1.0 / denom : 0.0;
    }
    terms[i] = lightTerm(N, V, toLight * inverseD, attenuation, light.intensity.rgb, material, blinn);
  }
  for (int i = pointLightCount; i < pointLightCount + directionalLightCount; ++i) {
    GpuLight light = frameLight(i);
    terms[i] = lightTerm(N, V, light.position.xyz, 1.0, light.intensity.rgb, material, blinn);
  }
}

// The fragment stage's half of illuminateEach: each light's k_shadow at the
// fragment's eye-space position, with `normal` (Gouraud's interpolated one,
// flat's face normal) for the bias; then sum_i k[i] terms[i].
void shadowCoefficients(vec3 position, vec3 normal, out float k[MAX_LIGHTS]) {
  for (int i = 0; i < MAX_LIGHTS; ++i) k[i] = 1.0;
  for (int i = 0; i < pointLightCount + directionalLightCount; ++i)
    k[i] = shadowCoefficient(i, position, normal);
}

vec3 shadowedSum(float k[MAX_LIGHTS], vec3 terms[MAX_LIGHTS]) {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < pointLightCount + directionalLightCount; ++i) sum += k[i] * terms[i];
  return sum;
}
#endif
