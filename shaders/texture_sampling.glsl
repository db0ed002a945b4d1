// Fragment-stage texture lookups (implicit derivatives, textureQueryLod):
// the diffuse texel and the mip-level tint of the --mip-tint debug view.
#ifndef TEXTURE_SAMPLING_GLSL
#define TEXTURE_SAMPLING_GLSL
#include "texturing.glsl"

// A colour per mip level (0 white, 1 red, 2 orange, 3 yellow, 4 green, 5 cyan,
// 6 blue, 7+ magenta), blended across the fractional level trilinear
// filtering samples between.
vec3 mipLevelColor(float level) {
  const vec3 palette[8] = vec3[8](vec3(1.0), vec3(1.0, 0.1, 0.1), vec3(1.0, 0.5, 0.0),
                                  vec3(1.0, 1.0, 0.1), vec3(0.1, 0.9, 0.1),
                                  vec3(0.1, 0.9, 0.9), vec3(0.15, 0.25, 1.0),
                                  vec3(0.9, 0.1, 0.9));
  float clamped = clamp(level, 0.0, 7.0);
  int low = int(floor(clamped));
  return mix(palette[low], palette[min(low + 1, 7)], clamped - float(low));
}

// The diffuse map's linear colour (white without one): it multiplies ka and kd.
vec3 diffuseTexel(vec2 st) {
  if (!hasMap(TEXTURE_DIFFUSE)) return vec3(1.0);
  vec3 texel = texture(diffuseMap, st).rgb;
  if (hasMap(TEXTURE_MIP_TINT))
    texel = mipLevelColor(textureQueryLod(diffuseMap, st).x) * (0.35 + 0.65 * texel);
  return texel;
}
#endif
