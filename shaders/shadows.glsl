// Shadow maps: the shadow coefficient k_shadow of a light at a point, in
// 0..1 (1: lit), from the depth the shadow pass stored for the light
// (passes/shadow_pass.cpp). The layers of one array: a directional light's
// orthographic map, or a point light's six cube faces (+x, -x, +y, -y, +z,
// -z). Filtering is a specialization constant (SHADOW_*):
//   hard: one tap of the compare sampler (lit or not),
//   pcf3 / pcf5: the mean of 3x3 / 5x5 compare taps one texel apart
//   (percentage-closer filtering: the compare happens before the average).
// Bias (ShadowData::bias, in texels of the map where the point is): the
// point moves towards the light by constant + slope * tan(theta) texels and
// along its normal by normalOffset * sin(theta) texels before the lookup.
// Only the fragment stage looks maps up (SHADOW_LOOKUP defined by its body);
// elsewhere shadowsLookedUp is false and every light is unshadowed.
#ifndef SHADOWS_GLSL
#define SHADOWS_GLSL
#include "common.glsl"

layout(constant_id = SPEC_SHADOW_FILTER) const int shadowFilter = SHADOW_OFF;
layout(constant_id = SPEC_SHADOWED_LIGHTS) const int shadowedLights = 0xff;

#ifdef SHADOW_LOOKUP
layout(set = 0, binding = BINDING_SHADOWS, std140) uniform ShadowBlock { ShadowData shadows; };
layout(set = 0, binding = BINDING_SHADOW_MAP) uniform sampler2DArrayShadow shadowMap;
const bool shadowsLookedUp = shadowFilter != SHADOW_OFF;

// Light i (FrameData::lights' order) at eye-space `position` with unit
// normal N and unit direction L towards the light. Written for lavapipe's
// SIMD lanes: every value that depends on i is loaded at a constant index
// (the light loops are unrolled), and the fragment's own choices (cube face,
// inside the map or not) are selects, not branches or indexed loads.
float shadowCoefficient(int i, vec3 position, vec3 N, vec3 L) {
  if ((shadowedLights & (1 << i)) == 0) return 1.0;  // folded away per unrolled light
  vec4 light = shadows.lights[i];
  if (light.x < 0.0 || draw.object.z == 0) return 1.0;  // the same for the whole draw
  bool point = i < pointLightCount;
  vec3 lightPosition = frame.lights[i].position.xyz;
  float texel = point ? light.y * length(lightPosition - position) : light.y;
  float cosine = clamp(dot(N, L), 0.0, 1.0);
  float sine = sqrt(max(1.0 - cosine * cosine, 0.0));
  float tangent = min(sine / max(cosine, 1e-4), 10.0);  // kMaxSlopeTangent
  vec3 biased = position + L * (texel * (shadows.bias.x + shadows.bias.y * tangent)) +
                N * (texel * shadows.bias.z * sine);
  vec3 ndc;
  float layer = light.x;
  if (point) {
    // The cube face is the major axis of the world-space direction from the
    // light; its clip xy and depth follow from the face's (right, up) as
    // lookAt built them. The C++ twin is cubeFaceCoordinates() in
    // core/scene/shadows.cpp.
    vec3 v = mat3(frame.viewToWorld) * (biased - lightPosition);
    vec3 a = abs(v);
    bool xMajor = a.x >= a.y && a.x >= a.z;
    bool yMajor = !xMajor && a.y >= a.z;
    float major = xMajor ? a.x : (yMajor ? a.y : a.z);
    bool positive = xMajor ? v.x >= 0.0 : (yMajor ? v.y >= 0.0 : v.z >= 0.0);
    float right = xMajor ? (positive ? v.z : -v.z) : (yMajor ? (positive ? v.x : -v.x)
                                                             : (positive ? -v.x : v.x));
    float up = yMajor ? v.z : v.y;
    vec4 cube = shadows.cube[i];
    ndc = vec3(cube.z * right / major, -cube.z * up / major, cube.x - cube.y / major);
    layer += float((xMajor ? 0 : (yMajor ? 2 : 4)) + (positive ? 0 : 1));
  } else {
    ndc = (shadows.eyeToLight[i] * vec4(biased, 1.0)).xyz;  // orthographic: w = 1
  }
  vec2 uv = ndc.xy * 0.5 + 0.5;
  // Outside the map nothing was drawn: lit (NaN, a point at the light, too).
  bool inside = all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)));
  int radius = shadowFilter == SHADOW_PCF5 ? 2 : (shadowFilter == SHADOW_PCF3 ? 1 : 0);
  float lit = 0.0;
  for (int y = -radius; y <= radius; ++y)
    for (int x = -radius; x <= radius; ++x)
      lit += texture(shadowMap, vec4(uv + vec2(x, y) * light.z, layer, ndc.z));
  float taps = float((2 * radius + 1) * (2 * radius + 1));
  return inside ? lit / taps : 1.0;
}
#else
const bool shadowsLookedUp = false;
float shadowCoefficient(int i, vec3 position, vec3 N, vec3 L) { return 1.0; }
#endif
#endif
