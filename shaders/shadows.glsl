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
// elsewhere shadowsLookedUp is false and every light is unshadowed. The
// lookup comes in two halves: shadowMapCoordinates(), affine in the
// position, which Phong's vertex stage computes (SHADOW_COORDINATES) and
// the rasteriser interpolates, and shadowLookup(), per fragment. Flat,
// Gouraud and billboards run both halves per fragment (shadowCoefficient).
#ifndef SHADOWS_GLSL
#define SHADOWS_GLSL
#include "common.glsl"

layout(constant_id = SPEC_SHADOW_FILTER) const int shadowFilter = SHADOW_OFF;
layout(constant_id = SPEC_SHADOWED_LIGHTS) const int shadowedLights = 0xff;

#if defined(SHADOW_LOOKUP) || defined(SHADOW_COORDINATES)
layout(set = 0, binding = BINDING_SHADOWS, std140) uniform ShadowBlock { ShadowData shadows; };

// Light i (FrameData::lights' order) has a map that this pipeline reads.
bool castsShadows(int i) {
  return shadowFilter != SHADOW_OFF && (shadowedLights & (1 << i)) != 0 &&
         i < pointLightCount + directionalLightCount;
}

// The half of the lookup that is affine in the position (so a vertex stage
// may compute it and the rasteriser interpolate it): where light i's map
// holds the eye-space `position` moved along its normal by normalOffset *
// sin(theta) texels (the normal-offset bias). Directional light: the map's
// (u, v, depth), its orthographic projection being affine. Point light: the
// world-space vector from the light, which is affine in the position too;
// the face choice and the divide stay per fragment (shadowLookup).
// Only the normal offset is not affine (sin(theta) and, for a point light,
// the texel size vary): per vertex it is interpolated, a fraction of a texel
// off on curved or large triangles (docs/PERFORMANCE.md, "Shadow lookups").
vec3 shadowMapCoordinates(int i, vec3 position, vec3 normal) {
  float lengthN2 = dot(normal, normal);
  vec3 N = lengthN2 > 1e-40 && lengthN2 < 1e30 ? normal * inversesqrt(lengthN2) : vec3(0.0);
  vec3 lightPosition = frame.lights[i].position.xyz;
  bool point = i < pointLightCount;
  vec3 toLight = lightPosition - position;
  vec3 L = point ? toLight * inversesqrt(max(dot(toLight, toLight), 1e-40)) : lightPosition;
  // A double-sided surface is offset towards the side the light is on.
  if (doubleSided && dot(N, L) < 0.0) N = -N;
  float cosine = clamp(dot(N, L), 0.0, 1.0);
  float sine = sqrt(max(1.0 - cosine * cosine, 0.0));
  float texel = point ? shadows.lights[i].y * length(toLight) : shadows.lights[i].y;
  vec3 offset = position + N * (texel * shadows.bias.z * sine);
  if (point) return mat3(frame.viewToWorld) * (offset - lightPosition);
  vec3 ndc = (shadows.eyeToLight[i] * vec4(offset, 1.0)).xyz;  // orthographic: w = 1
  return vec3(ndc.xy * 0.5 + 0.5, ndc.z);
}
#endif

#ifdef SHADOW_LOOKUP
layout(set = 0, binding = BINDING_SHADOW_MAP) uniform sampler2DArrayShadow shadowMap;
const bool shadowsLookedUp = shadowFilter != SHADOW_OFF;

// The per-fragment half: light i's k_shadow from shadowMapCoordinates()'
// `coordinates`, with unit normal N and unit direction L towards the light.
// The point then moves towards the light by constant + slope * tan(theta)
// texels: for a directional light that changes the map depth only (by
// ShadowData::lights[i].w per texel), for a point light it scales the vector
// from the light by 1 - texel per unit distance * texels, which keeps the
// face and its xy. Written for lavapipe's SIMD lanes: every value that
// depends on i is loaded at a constant index (the light loops are unrolled),
// and the fragment's own choices (cube face, inside the map or not) are
// selects, not branches or indexed loads.
float shadowLookup(int i, vec3 coordinates, vec3 N, vec3 L) {
  vec4 light = shadows.lights[i];
  if (light.x < 0.0 || draw.object.z == 0) return 1.0;  // the same for the whole draw
  vec4 lookup = shadows.lookup[i];
  float cosine = clamp(dot(N, L), 0.0, 1.0);
  float sine = sqrt(max(1.0 - cosine * cosine, 0.0));
  float tangent = min(sine / max(cosine, 1e-4), 10.0);  // kMaxSlopeTangent
  vec3 uvDepth;
  float layer = light.x;
  bool inside = true;
  if (i < pointLightCount) {
    // The cube face is the major axis of the world-space direction from the
    // light; its clip xy and depth follow from the face's (right, up) as
    // lookAt built them. The C++ twin is cubeFaceCoordinates() in
    // core/scene/shadows.cpp. The faces cover every direction; a point at
    // the light itself (no direction, NaN here) gets no light anyway.
    vec3 v = coordinates;
    vec3 a = abs(v);
    bool xMajor = a.x >= a.y && a.x >= a.z;
    bool yMajor = !xMajor && a.y >= a.z;
    float major = xMajor ? a.x : (yMajor ? a.y : a.z);
    bool positive = xMajor ? v.x >= 0.0 : (yMajor ? v.y >= 0.0 : v.z >= 0.0);
    float right = xMajor ? (positive ? v.z : -v.z) : (yMajor ? (positive ? v.x : -v.x)
                                                             : (positive ? -v.x : v.x));
    float up = yMajor ? v.z : v.y;
    // Moved towards the light: v scaled by lookup.x - lookup.y tan, which
    // changes the depth only (one divide for both).
    float scale = max(lookup.x - lookup.y * tangent, 1e-4);
    float inverseScaledMajor = 1.0 / (major * scale);
    float face = lookup.z * scale * inverseScaledMajor;  // cot(half angle) / 2 / major
    vec4 cube = shadows.cube[i];
    uvDepth = vec3(0.5 + face * right, 0.5 - face * up, cube.x - cube.y * inverseScaledMajor);
    layer += float((xMajor ? 0 : (yMajor ? 2 : 4)) + (positive ? 0 : 1));
  } else {
    // Moved towards the light: the orthographic depth changes, nothing else.
    uvDepth = vec3(coordinates.xy, coordinates.z + lookup.x + lookup.y * tangent);
    // Outside the map nothing was drawn: lit.
    inside = all(greaterThanEqual(uvDepth.xy, vec2(0.0))) &&
             all(lessThanEqual(uvDepth.xy, vec2(1.0)));
  }
  int radius = shadowFilter == SHADOW_PCF5 ? 2 : (shadowFilter == SHADOW_PCF3 ? 1 : 0);
  float lit = 0.0;
  for (int y = -radius; y <= radius; ++y)
    for (int x = -radius; x <= radius; ++x)
      lit += texture(shadowMap, vec4(uvDepth.xy + vec2(x, y) * light.z, layer, uvDepth.z));
  float taps = float((2 * radius + 1) * (2 * radius + 1));
  return inside ? lit / taps : 1.0;
}

#ifdef SHADOW_COORDINATES
// Phong and Blinn-Phong: shadowMapCoordinates() of each shadowed light,
// from the vertex stage (forward_vertex.glsl), one input per light so that
// only the lights with maps are interpolated.
layout(location = 12) in vec3 inShadowCoordinates0;
layout(location = 13) in vec3 inShadowCoordinates1;
layout(location = 14) in vec3 inShadowCoordinates2;
layout(location = 15) in vec3 inShadowCoordinates3;
layout(location = 16) in vec3 inShadowCoordinates4;
layout(location = 17) in vec3 inShadowCoordinates5;
layout(location = 18) in vec3 inShadowCoordinates6;
layout(location = 19) in vec3 inShadowCoordinates7;
vec3 shadowCoordinatesAt(int i, vec3 position, vec3 N) {
  // i is a constant once the light loops unroll: this folds to one input.
  return i == 0 ? inShadowCoordinates0 : i == 1 ? inShadowCoordinates1 :
         i == 2 ? inShadowCoordinates2 : i == 3 ? inShadowCoordinates3 :
         i == 4 ? inShadowCoordinates4 : i == 5 ? inShadowCoordinates5 :
         i == 6 ? inShadowCoordinates6 : inShadowCoordinates7;
}
#else
vec3 shadowCoordinatesAt(int i, vec3 position, vec3 N) {
  return shadowMapCoordinates(i, position, N);
}
#endif

// Light i at eye-space `position` with unit normal N and unit direction L
// towards the light.
float shadowCoefficient(int i, vec3 position, vec3 N, vec3 L) {
  if (!castsShadows(i)) return 1.0;  // folded away per unrolled light
  return shadowLookup(i, shadowCoordinatesAt(i, position, N), N, L);
}
#else
const bool shadowsLookedUp = false;
float shadowCoefficient(int i, vec3 position, vec3 N, vec3 L) { return 1.0; }
#endif
#endif
