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
// lookup comes in two halves: shadowMapCoordinates(), the map coordinates
// with both biases applied, which Phong's vertex stage computes
// (SHADOW_COORDINATES) and the rasteriser interpolates, and shadowLookup(),
// per fragment. Flat, Gouraud and billboards run both halves per fragment
// (shadowCoefficient).
#ifndef SHADOWS_GLSL
#define SHADOWS_GLSL
#include "common.glsl"

// SPEC_SHADOW_FILTER: the filter, or-ed with SHADOW_TRANSLUCENT when the
// maps have translucent layers (passes/shadow_pass.h).
layout(constant_id = SPEC_SHADOW_FILTER) const int shadowSpecialization = SHADOW_OFF;
const int shadowFilter = shadowSpecialization & (SHADOW_TRANSLUCENT - 1);
const bool translucentShadows = (shadowSpecialization & SHADOW_TRANSLUCENT) != 0;

// Phong's shadow coordinates travel from its vertex stage to its fragment
// stage (SHADOW_COORDINATES) as one vec4 per light slot, locations 12..19,
// one variable each so that only the lights with maps are interpolated.
// Both sides declare them from here: (out, outShadowCoordinates) and (in,
// inShadowCoordinates).
#define SHADOW_COORDINATE_VARYING(direction, name, i) \
  layout(location = 12 + i) direction vec4 name##i;
#define SHADOW_COORDINATE_VARYINGS(direction, name)                                            \
  SHADOW_COORDINATE_VARYING(direction, name, 0) SHADOW_COORDINATE_VARYING(direction, name, 1) \
  SHADOW_COORDINATE_VARYING(direction, name, 2) SHADOW_COORDINATE_VARYING(direction, name, 3) \
  SHADOW_COORDINATE_VARYING(direction, name, 4) SHADOW_COORDINATE_VARYING(direction, name, 5) \
  SHADOW_COORDINATE_VARYING(direction, name, 6) SHADOW_COORDINATE_VARYING(direction, name, 7)
layout(constant_id = SPEC_SHADOWED_LIGHTS) const int shadowedLights = 0xff;

#if defined(SHADOW_LOOKUP) || defined(SHADOW_COORDINATES)
layout(set = 0, binding = BINDING_SHADOWS, std140) uniform ShadowBlock { ShadowData shadows; };

// Light i (FrameData::lights' order) has a map that this pipeline reads.
bool castsShadows(int i) {
  return shadowFilter != SHADOW_OFF && (shadowedLights & (1 << i)) != 0 &&
         i < pointLightCount + directionalLightCount;
}

// The half of the lookup that runs per vertex where it can (Phong's vertex
// stage, SHADOW_COORDINATES; the rasteriser interpolates it): where light
// i's map holds the eye-space `position` with both biases applied, and
// which layer. The point moves along its normal by normalOffset * sin(theta)
// texels and towards the light by constant + slope * tan(theta) texels.
// Directional light: the map's (u, v, depth), the depth moved by
// ShadowData::lookup (x + y tan). Point light: the world-space vector from
// the light scaled by lookup.x - lookup.y tan, which moves the depth only
// (the face and its xy stay); the face choice and the divide stay per
// fragment (shadowLookup). w: the light's first layer, or -1 when the
// point gets no shadow (no map, or a draw that does not receive shadows).
// The projection and the vector from the light are affine in the position;
// the biases are not (theta and, for a point light, the texel size vary):
// per vertex they are interpolated, a fraction of a texel off on curved or
// large triangles, exact on planes under a directional light
// (docs/PERFORMANCE.md, "Shadow lookups").
vec4 shadowMapCoordinates(int i, vec3 position, vec3 normal) {
  float lengthN2 = dot(normal, normal);
  vec3 N = lengthN2 > 1e-40 && lengthN2 < 1e30 ? normal * inversesqrt(lengthN2) : vec3(0.0);
  vec3 lightPosition = frameLight(i).position.xyz;
  bool point = i < pointLightCount;
  vec3 toLight = lightPosition - position;
  vec3 L = point ? toLight * inversesqrt(max(dot(toLight, toLight), 1e-40)) : lightPosition;
  // A double-sided surface is biased towards the side the light is on.
  if (doubleSided && dot(N, L) < 0.0) N = -N;
  float cosine = clamp(dot(N, L), 0.0, 1.0);
  float sine = sqrt(max(1.0 - cosine * cosine, 0.0));
  float tangent = min(sine / max(cosine, 1e-4), 10.0);  // kMaxSlopeTangent
  vec4 light = shadows.lights[i];
  vec4 lookup = shadows.lookup[i];
  float texel = point ? light.y * length(toLight) : light.y;
  vec3 offset = position + N * (texel * shadows.bias.z * sine);
  float layer = draw.object.z == 0 ? -1.0 : light.x;
  float slope = lookup.y * tangent;
  if (point) {
    vec3 v = mat3(frame.viewToWorld) * (offset - lightPosition);
    return vec4(v * max(lookup.x - slope, 1e-4), layer);
  }
  vec3 ndc = (shadows.eyeToLight[i] * vec4(offset, 1.0)).xyz;  // orthographic: w = 1
  return vec4(ndc.xy * 0.5 + 0.5, ndc.z + lookup.x + slope, layer);
}
#endif

#ifdef SHADOW_LOOKUP
layout(set = 0, binding = BINDING_SHADOW_MAP) uniform sampler2DArrayShadow shadowMap;
layout(set = 0, binding = BINDING_OPAQUE_SHADOW_MAP) uniform sampler2DArrayShadow opaqueShadowMap;
layout(set = 0, binding = BINDING_TRANSMITTANCE) uniform sampler2DArray transmittanceMap;
const bool shadowsLookedUp = shadowFilter != SHADOW_OFF;

// One tap: the light that reaches the point `uvDepth` of a layer. 1 before
// the nearest caster, 0 behind it; with translucent casters
// (SHADOW_TRANSLUCENT) the map holds them too, and a point behind no opaque
// caster but behind a translucent one gets the product of the
// transmittances of every translucent caster the texel's ray crosses (also
// those behind the point: one layer cannot tell them apart).
float shadowTap(vec3 uvDepth, float layer) {
  vec4 coordinate = vec4(uvDepth.xy, layer, uvDepth.z);
  float lit = texture(shadowMap, coordinate);
  // Where it says shadow: behind an opaque caster, or only translucent
  // ones? llvmpipe 22.3 runs this for lit fragments too (it does not skip a
  // branch no lane takes), so such a scene pays two more lookups per tap.
  // One level each: zero gradients, as implicit ones are undefined inside
  // a branch that varies per fragment.
  if (translucentShadows && lit < 1.0) {
    lit = textureGrad(opaqueShadowMap, coordinate, vec2(0.0), vec2(0.0)) *
          textureGrad(transmittanceMap, vec3(uvDepth.xy, layer), vec2(0.0), vec2(0.0)).r;
  }
  return lit;
}

// The per-fragment half: light i's k_shadow from shadowMapCoordinates()'
// `coordinates`. Written for lavapipe's SIMD lanes: every value that
// depends on i is loaded at a constant index (the light loops are
// unrolled), the fragment's own choices (cube face, inside the map or not)
// are selects, not branches or indexed loads, and a directional light's
// hard lookup reads nothing but the map (on llvmpipe 22.3 a uniform-buffer
// read in the fragment stage costs about 0.1 ms per float per 1280x720
// frame, measured: docs/PERFORMANCE.md).
float shadowLookup(int i, vec4 coordinates) {
  vec3 uvDepth;
  float uvDepthMajor = 1.0;  // point lights: the distance along the face's axis
  float layer = coordinates.w;  // interpolated: a layer number to within rounding
  bool inside = layer > -0.5;
  if (i < pointLightCount) {
    // The cube face is the major axis of the world-space direction from the
    // light; its clip xy and depth follow from the face's (right, up) as
    // lookAt built them. The C++ twin is cubeFaceCoordinates() in
    // core/scene/shadows.cpp. The faces cover every direction; a point at
    // the light itself (no direction, NaN here) gets no light anyway.
    vec3 v = coordinates.xyz;
    vec3 a = abs(v);
    bool xMajor = a.x >= a.y && a.x >= a.z;
    bool yMajor = !xMajor && a.y >= a.z;
    float major = xMajor ? a.x : (yMajor ? a.y : a.z);
    bool positive = xMajor ? v.x >= 0.0 : (yMajor ? v.y >= 0.0 : v.z >= 0.0);
    float right = xMajor ? (positive ? v.z : -v.z) : (yMajor ? (positive ? v.x : -v.x)
                                                             : (positive ? -v.x : v.x));
    float up = yMajor ? v.z : v.y;
    vec4 cube = shadows.cube[i];
    float inverseMajor = 1.0 / major;
    uvDepthMajor = major;
    float face = 0.5 * cube.z * inverseMajor;  // cot(half angle) / 2 / major
    uvDepth = vec3(0.5 + face * right, 0.5 - face * up, cube.x - cube.y * inverseMajor);
    layer += float((xMajor ? 0 : (yMajor ? 2 : 4)) + (positive ? 0 : 1));
  } else {
    uvDepth = coordinates.xyz;
    // Outside the map nothing was drawn: lit.
    inside = inside && all(greaterThanEqual(uvDepth.xy, vec2(0.0))) &&
             all(lessThanEqual(uvDepth.xy, vec2(1.0)));
  }
  int radius = shadowFilter == SHADOW_PCF5 ? 2 : (shadowFilter == SHADOW_PCF3 ? 1 : 0);
  float lit;
  if (radius == 0) {
    lit = shadowTap(uvDepth, layer);
  } else {
    float step = shadows.lights[i].z;  // one texel
    // Receiver-plane depth: a tap `offset` away compares the depth the
    // surface has there (its plane through this point), not this point's
    // own, or on a surface sloped towards the light the outer taps find it
    // in front of itself and lit floor is dimmed in rings. The plane's depth
    // gradient in the map follows from the screen derivatives of the map
    // coordinates (one triangle's, exact on planes). Where they say nothing
    // (the quad straddles two cube faces, or a map texel is seen edge-on)
    // the taps keep this point's depth; at grazing angles the gradient is
    // held to 100 texels of depth per texel (kMaxSlopeTangent, 10, left
    // visible rings towards the horizon).
    vec3 alongX = dFdx(uvDepth), alongY = dFdy(uvDepth);
    float determinant = alongX.x * alongY.y - alongX.y * alongY.x;
    vec2 gradient = vec2(alongY.y * alongX.z - alongX.y * alongY.z,
                         alongX.x * alongY.z - alongY.x * alongX.z) /
                    determinant;
    float depthPerTexel = i < pointLightCount
                              ? shadows.cube[i].y * shadows.lights[i].y / max(abs(uvDepthMajor), 1e-30)
                              : shadows.lookup[i].z;
    float limit = 100.0 * abs(depthPerTexel) / step;  // 100 texels of depth per texel, per unit of uv
    float size = length(gradient);
    bool known = abs(determinant) > 0.0 && size < 1e30 && abs(dFdx(layer)) + abs(dFdy(layer)) < 0.5;
    gradient = known ? gradient * min(1.0, limit / max(size, 1e-30)) : vec2(0.0);
    lit = 0.0;
    for (int y = -radius; y <= radius; ++y)
      for (int x = -radius; x <= radius; ++x) {
        vec2 offset = vec2(x, y) * step;
        lit += shadowTap(vec3(uvDepth.xy + offset, uvDepth.z + dot(gradient, offset)), layer);
      }
    lit /= float((2 * radius + 1) * (2 * radius + 1));
  }
  return inside ? lit : 1.0;
}

#ifdef SHADOW_COORDINATES
// Phong and Blinn-Phong: shadowMapCoordinates() of each shadowed light,
// from the vertex stage (forward_vertex.glsl).
SHADOW_COORDINATE_VARYINGS(in, inShadowCoordinates)
vec4 shadowCoordinatesAt(int i, vec3 position, vec3 normal) {
  // i is a constant once the light loops unroll: this folds to one input.
  return i == 0 ? inShadowCoordinates0 : i == 1 ? inShadowCoordinates1 :
         i == 2 ? inShadowCoordinates2 : i == 3 ? inShadowCoordinates3 :
         i == 4 ? inShadowCoordinates4 : i == 5 ? inShadowCoordinates5 :
         i == 6 ? inShadowCoordinates6 : inShadowCoordinates7;
}
#else
vec4 shadowCoordinatesAt(int i, vec3 position, vec3 normal) {
  return shadowMapCoordinates(i, position, normal);
}
#endif

// Light i's k_shadow at eye-space `position` with normal `normal`.
float shadowCoefficient(int i, vec3 position, vec3 normal) {
  if (!castsShadows(i)) return 1.0;  // folded away per unrolled light
  return shadowLookup(i, shadowCoordinatesAt(i, position, normal));
}
#else
const bool shadowsLookedUp = false;
float shadowCoefficient(int i, vec3 position, vec3 normal) { return 1.0; }
#endif
#endif
