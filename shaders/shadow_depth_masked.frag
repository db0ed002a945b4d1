#version 460
// alphaMode MASK and BLEND in the shadow maps: a fragment whose base colour
// texel's alpha is below the threshold (MASK: alphaCutoff / the factor's
// alpha, as the forward pass tests it; BLEND: one half, shadow_pass.cpp)
// casts no shadow.
#extension GL_GOOGLE_include_directive : require
#include "interface.h"
#include "uv_transform.glsl"

layout(push_constant) uniform ShadowDraw {
  mat4 objectToLightClip;
  vec4 texturing;  // xy = uv scale (repeats), z = alpha threshold, w = uv rotation
  vec4 diffuseUv;  // KHR_texture_transform: xy = offset, zw = scale
};
layout(set = 0, binding = BINDING_DIFFUSE_MAP) uniform sampler2D diffuseMap;
layout(location = 0) in vec2 inUv;

void main() {
  // texturing.glsl's textureCoordinate, then the texture transform.
  vec2 st = vec2(inUv.x * texturing.x, 1.0 - inUv.y * texturing.y);
  st = transformedCoordinate(st, diffuseUv, texturing.w);
  if (texture(diffuseMap, st).a < texturing.z) discard;
}
