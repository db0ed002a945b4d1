#version 460
// Skybox: the environment along each pixel's view ray, in world space. The
// ray runs from the near to the far plane's point under the pixel, so a
// perspective camera sees the whole surround and an orthographic one a
// single direction, as its parallel rays would.
#extension GL_GOOGLE_include_directive : require
#include "interface.h"

layout(set = 0, binding = BINDING_ENVIRONMENT) uniform samplerCube environmentMap;
layout(push_constant) uniform SkyboxBlock { SkyboxConstants skybox; };
layout(location = 0) in vec2 inClip;
layout(location = 0) out vec4 outColor;

void main() {
  // Reversed-Z swaps the planes' depths; depth.xy says which is which.
  vec4 near = skybox.clipToWorld * vec4(inClip, skybox.depth.y, 1.0);
  vec4 far = skybox.clipToWorld * vec4(inClip, skybox.depth.x, 1.0);
  vec3 direction = far.xyz / far.w - near.xyz / near.w;
  outColor = vec4(texture(environmentMap, direction).rgb, 1.0);
}
