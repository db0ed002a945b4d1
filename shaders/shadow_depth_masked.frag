#version 460
// alphaMode MASK in the shadow maps: a fragment whose base colour texel's
// alpha is below the threshold (alphaCutoff / the factor's alpha, as the
// forward pass tests it) casts no shadow. With TRANSMITTANCE, glTF BLEND
// over a texture with alpha: the share of the light the texel passes,
// 1 - its coverage (the opacity kd.w, in the threshold's slot, times the
// texel's alpha), multiplied into the layer's transmittance
// (passes/shadow_pass.cpp, as the tracer's coverage()).
#extension GL_GOOGLE_include_directive : require
#include "interface.h"
#include "uv_transform.glsl"

layout(push_constant) uniform ShadowDraw {
  mat4 objectToLightClip;
  vec4 texturing;  // xy = uv scale (repeats), z = alpha threshold (opacity), w = uv rotation
  vec4 diffuseUv;  // KHR_texture_transform: xy = offset, zw = scale
};
layout(set = 0, binding = BINDING_DIFFUSE_MAP) uniform sampler2D diffuseMap;
layout(location = 0) in vec2 inUv;
#ifdef TRANSMITTANCE
layout(location = 0) out vec4 outTransmittance;
#endif

void main() {
  // texturing.glsl's textureCoordinate, then the texture transform.
  vec2 st = vec2(inUv.x * texturing.x, 1.0 - inUv.y * texturing.y);
  st = transformedCoordinate(st, diffuseUv, texturing.w);
#ifdef TRANSMITTANCE
  outTransmittance = vec4(1.0 - texturing.z * clamp(texture(diffuseMap, st).a, 0.0, 1.0));
#else
  if (texture(diffuseMap, st).a < texturing.z) discard;
#endif
}
