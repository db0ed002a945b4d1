// Bump mapping, per fragment: the interpolated normal perturbed in its
// tangent frame (T, B = w cross(N, T), N) by a tangent-space normal map
// (n = 2 rgb - 1, xy scaled by the bump scale) and/or a height map, whose
// central differences per texel give n = (-s dh/du, -s dh/dv, 1) with
// s = bump scale (Blinn 1978; core/scene/procedural_textures.h derives normal maps
// with the same formula). With both, their normals are combined as
// (n1.xy + n2.xy, n1.z n2.z) ("whiteout" blending).
#ifndef BUMP_GLSL
#define BUMP_GLSL
#include "texture_sampling.glsl"

vec3 heightMapNormal(vec2 st, float scale) {
  vec2 texel = 1.0 / vec2(textureSize(heightMap, 0));
  float dhdu = 0.5 * (texture(heightMap, st + vec2(texel.x, 0.0)).r -
                      texture(heightMap, st - vec2(texel.x, 0.0)).r);
  // v runs up the image, toward smaller t.
  float dhdv = 0.5 * (texture(heightMap, st - vec2(0.0, texel.y)).r -
                      texture(heightMap, st + vec2(0.0, texel.y)).r);
  return vec3(-scale * dhdu, -scale * dhdv, 1.0);
}

// `normal` and `tangent.xyz` in eye space, not normalised; tangent.w = +-1.
// Degenerate frames fall back to the unperturbed normal, never NaN.
vec3 bumpedNormal(vec3 normal, vec4 tangent, vec2 st) {
  bool normalMapped = hasMap(TEXTURE_NORMAL), heightMapped = hasMap(TEXTURE_HEIGHT);
  if (!normalMapped && !heightMapped) return normal;
  vec3 N = safeNormalize(normal);
  vec3 T = safeNormalize(tangent.xyz - N * dot(N, tangent.xyz));  // Gram-Schmidt
  vec3 B = (tangent.w < 0.0 ? -1.0 : 1.0) * cross(N, T);
  float scale = draw.texturing.z;
  vec3 n = vec3(0.0, 0.0, 1.0);
  if (normalMapped) {
    vec3 mapped = texture(normalMap, st).xyz * 2.0 - 1.0;
    n = vec3(mapped.xy * scale, mapped.z);
  }
  if (heightMapped) {
    vec3 h = heightMapNormal(st, scale);
    n = vec3(n.xy + h.xy, n.z * h.z);
  }
  vec3 bumped = T * n.x + B * n.y + N * n.z;
  return dot(T, T) > 0.0 ? bumped : normal;
}
#endif
