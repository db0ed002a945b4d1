#version 460
// Skybox: one triangle covering the viewport, at the far plane's depth.
#extension GL_GOOGLE_include_directive : require
#include "interface.h"

layout(push_constant) uniform SkyboxBlock { SkyboxConstants skybox; };
layout(location = 0) out vec2 outClip;

void main() {
  // Vertices (-1, -1), (3, -1), (-1, 3): the clip square and more.
  vec2 clip = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2) * 2.0 - 1.0;
  outClip = clip;
  gl_Position = vec4(clip, skybox.depth.x, 1.0);
}
