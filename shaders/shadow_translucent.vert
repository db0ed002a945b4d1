#version 460
// Shadow pass, translucent casters (kt > 0): the share of the light each
// crossing of such a surface passes, multiplied into the layer's
// transmittance (passes/shadow_pass.cpp). The fragment stage needs the
// angle between the light's ray and the surface, so this stage also moves
// the position and normal into the light's frame: the light at the origin
// (point light) or shining along -z (directional light).
#extension GL_GOOGLE_include_directive : require
#include "interface.h"

layout(push_constant) uniform TranslucentShadowDraw {
  mat4 objectToLightClip;
  // Object space to the light's frame, an affine map; its last row, which
  // an affine map does not need, carries (kt, ior, 1: Fresnel, 1: point light).
  mat4 objectToLight;
};
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 0) out vec3 outPosition;  // in the light's frame
layout(location = 1) out vec3 outNormal;
layout(location = 2) flat out vec4 outOptics;

void main() {
  mat4 affine = objectToLight;
  outOptics = vec4(affine[0][3], affine[1][3], affine[2][3], affine[3][3]);
  affine[0][3] = 0.0;
  affine[1][3] = 0.0;
  affine[2][3] = 0.0;
  affine[3][3] = 1.0;
  outPosition = (affine * vec4(inPosition, 1.0)).xyz;
  outNormal = transpose(inverse(mat3(affine))) * inNormal;
  gl_Position = objectToLightClip * vec4(inPosition, 1.0);
}
