#version 460
// Forward pass, fragment stage: Phong and Blinn-Phong evaluate the equation
// per fragment with the interpolated, renormalised normal; flat and Gouraud
// output the colour computed earlier; unlit writes the diffuse colour as is.
#extension GL_GOOGLE_include_directive : require
#include "lighting.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inColor;
layout(location = 3) flat in vec3 inFlatColor;

layout(location = 0) out vec4 outColor;

void main() {
  vec3 color;
  if (shadingModel == SHADING_FLAT) {
    color = inFlatColor;
  } else if (shadingModel == SHADING_GOURAUD) {
    color = inColor;
  } else if (shadingModel == SHADING_UNLIT) {
    color = draw.kd.rgb;
  } else {
    color = illuminate(inPosition, inNormal, drawMaterial(),
                       shadingModel == SHADING_BLINN_PHONG);
  }
  outColor = vec4(color, draw.kd.w);  // kd.w: opacity, 1 - transparency
}
