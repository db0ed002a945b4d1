#version 460
// Shadow pass: depth only, from the light. One matrix per draw takes the
// object's positions to the light's clip space (passes/shadow_pass.cpp).
#extension GL_GOOGLE_include_directive : require
#include "interface.h"

layout(push_constant) uniform ShadowDraw { mat4 objectToLightClip; };
layout(location = 0) in vec3 inPosition;

void main() {
  gl_Position = objectToLightClip * vec4(inPosition, 1.0);
}
