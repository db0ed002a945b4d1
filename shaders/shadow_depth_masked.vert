#version 460
// Shadow pass for casters with alphaMode MASK and a base colour texture (and
// BLEND ones whose texture has alpha): the depth-only pass plus the texture
// coordinate, so that the fragment stage (shadow_depth_masked.frag) cuts the
// holes their texels' alpha leaves.
#extension GL_GOOGLE_include_directive : require
#include "interface.h"

layout(push_constant) uniform ShadowDraw {
  mat4 objectToLightClip;
  vec4 texturing;  // xy = uv scale (repeats), z = alpha threshold, w = uv rotation
  vec4 diffuseUv;  // KHR_texture_transform: xy = offset, zw = scale
};
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec2 inUv;
layout(location = 0) out vec2 outUv;

void main() {
  outUv = inUv;
  gl_Position = objectToLightClip * vec4(inPosition, 1.0);
}
