// The Phong illumination equation, the one implementation every pass uses:
//   I = Ia ka + sum_i f_att,i Ip,i [ kd (N.L_i) + ks (R_i.V)^n ]
// with f_att = 1 / (a + b d + c d^2) for point lights and 1 for directional
// ones. Blinn-Phong replaces (R.V)^n with (N.H)^n, H = normalize(L + V).
// There is no specular term where N.L <= 0 (the light is behind the surface).
// Everything is in eye space, so V = normalize(-position).
#ifndef LIGHTING_GLSL
#define LIGHTING_GLSL
#include "common.glsl"

struct SurfaceMaterial {
  vec3 ka;
  vec3 kd;
  vec3 ks;
  float shininess;
};

SurfaceMaterial drawMaterial() {
  return SurfaceMaterial(draw.ka.rgb, draw.kd.rgb, draw.ks.rgb, draw.ks.w);
}

// pow(0, 0) is undefined in GLSL; shininess 0 means "specular everywhere it is lit".
float specularPower(float cosine, float shininess) {
  return shininess <= 0.0 ? 1.0 : pow(max(cosine, 0.0), shininess);
}

// normalize() of a zero vector is NaN; here it is the zero vector, which
// contributes nothing (an eye exactly at the point, L = -V for Blinn, a
// directional light with no direction).
vec3 safeNormalize(vec3 v) {
  float len = length(v);
  return len > 1e-20 ? v / len : vec3(0.0);
}

vec3 illuminate(vec3 position, vec3 normal, SurfaceMaterial material, bool blinn) {
  vec3 N = normal;
  float lengthN = length(N);
  // Zero-length or NaN normals (bad input) light as ambient only, never NaN.
  bool validNormal = lengthN > 1e-20 && !isnan(lengthN) && !isinf(lengthN);
  N = validNormal ? N / lengthN : vec3(0.0);
  vec3 V = safeNormalize(-position);
  vec3 color = frame.ambient.rgb * material.ka;
  for (int i = 0; i < lightCount; ++i) {
    GpuLight light = frame.lights[i];
    vec3 L;
    float attenuation = 1.0;
    if (light.type.x == LIGHT_POINT) {
      vec3 toLight = light.position.xyz - position;
      float d = length(toLight);
      // A light exactly at the surface point has no direction: it lights nothing.
      L = safeNormalize(toLight);
      float denom = light.attenuation.x + light.attenuation.y * d + light.attenuation.z * d * d;
      attenuation = denom > 0.0 ? 1.0 / denom : 0.0;
    } else {
      L = safeNormalize(light.position.xyz);
    }
    float NdotL = dot(N, L);
    if (NdotL <= 0.0) continue;
    float specular;
    if (blinn) {
      specular = specularPower(dot(N, safeNormalize(L + V)), material.shininess);
    } else {
      vec3 R = 2.0 * NdotL * N - L;  // reflection of L about N
      specular = specularPower(dot(R, V), material.shininess);
    }
    color += attenuation * light.intensity.rgb * (material.kd * NdotL + material.ks * specular);
  }
  return color;
}
#endif
