#version 460
// Impostor capture, vertex stage: the object's full mesh seen from one atlas
// cell's direction, orthographic (passes/impostor_capture.cpp).
#extension GL_GOOGLE_include_directive : require
#include "interface.h"

layout(push_constant) uniform Capture {
  mat4 objectToClip;
  vec4 right;  // the cell's frame in object space (core/scene/impostor.h)
  vec4 up;
  vec4 towardsViewer;
} capture;

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 0) out vec3 outNormal;  // object space

void main() {
  outNormal = inNormal;
  gl_Position = capture.objectToClip * vec4(inPosition, 1.0);
}
