// The procedural sky (mirrored by skyRadiance in src/core/scene/environment.cpp):
// a gradient, sqrt-shaped in the elevation y, from the horizon to the zenith
// above and to the ground below, plus the sun's disc, whose outer half of
// radius fades out (smoothstep in the cosine).
#ifndef SKY_GLSL
#define SKY_GLSL
#include "interface.h"

vec3 skyRadiance(SkyParameters sky, vec3 d) {
  float y = clamp(d.y, -1.0, 1.0);
  vec3 base = y >= 0.0 ? mix(sky.horizon.rgb, sky.zenith.rgb, sqrt(y))
                       : mix(sky.horizon.rgb, sky.ground.rgb, sqrt(-y));
  float cosine = dot(d, sky.sunDirection.xyz);
  float outer = sky.sunDirection.w, inner = sky.sunRadiance.w;
  float disc = inner > outer ? smoothstep(outer, inner, cosine) : 0.0;
  return base + disc * sky.sunRadiance.rgb;
}
#endif
