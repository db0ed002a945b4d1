#version 460
// Impostor capture, fragment stage: the surface normal in the cell's frame
// (x right, y up, z towards the viewer), encoded as a normal map is (rgb =
// (n + 1) / 2), and in alpha the surface's height h above the quad's plane
// (through the atlas centre, across the cell's direction) as (1 + 254 (0.5 +
// 0.5 h / halfSize)) / 255, so a covered texel's alpha is never 0, the
// clear's. The orthographic depth is linear: h = 1.5 radius - 3 radius z
// (passes/impostor_capture.cpp, cellToClip).
#extension GL_GOOGLE_include_directive : require
#include "interface.h"

layout(push_constant) uniform Capture {
  mat4 objectToClip;
  vec4 right;
  vec4 up;
  vec4 towardsViewer;  // w = radius / halfSize
} capture;

layout(location = 0) in vec3 inNormal;
layout(location = 0) out vec4 outColor;

void main() {
  float length2 = dot(inNormal, inNormal);
  vec3 n = length2 > 0.0 ? inNormal * inversesqrt(length2) : capture.towardsViewer.xyz;
  vec3 local = vec3(dot(n, capture.right.xyz), dot(n, capture.up.xyz),
                    dot(n, capture.towardsViewer.xyz));
  float height = (1.5 - 3.0 * gl_FragCoord.z) * capture.towardsViewer.w;  // h / halfSize
  float encoded = (1.0 + 254.0 * clamp(0.5 + 0.5 * height, 0.0, 1.0)) / 255.0;
  outColor = vec4(local * 0.5 + 0.5, encoded);
}
