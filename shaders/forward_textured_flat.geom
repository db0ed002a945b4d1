#version 460
// Flat shading of the textured variants: forward_flat.geom with the texture
// coordinate and tangent passed through and the lighting kept in two parts
// (the diffuse texel scales one). Bump maps do not apply: flat shading
// lights a triangle once, with its geometric normal.
#extension GL_GOOGLE_include_directive : require
#include "environment.glsl"
#include "texturing.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

layout(location = 0) in vec3 inPosition[];
layout(location = 1) in vec3 inNormal[];
layout(location = 2) in vec3 inColor[];
layout(location = 3) flat in vec3 inFlatColor[];
layout(location = 4) in vec2 inUv[];
layout(location = 5) in vec4 inTangent[];
layout(location = 6) in vec3 inSpecular[];
layout(location = 7) flat in vec3 inFlatSpecular[];
// The vertex stage's environment outputs (Gouraud's): unused here, declared to match.
layout(location = 8) in vec4 inEnvReflected[];
layout(location = 9) in vec4 inEnvRefracted[];
layout(location = 10) flat in vec4 inFlatEnvReflected[];
layout(location = 11) flat in vec4 inFlatEnvRefracted[];

layout(location = 0) out vec3 outPosition;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec3 outColor;
layout(location = 3) flat out vec3 outFlatColor;
layout(location = 4) out vec2 outUv;
layout(location = 5) out vec4 outTangent;
layout(location = 6) out vec3 outSpecular;
layout(location = 7) flat out vec3 outFlatSpecular;
layout(location = 8) out vec4 outEnvReflected;
layout(location = 9) out vec4 outEnvRefracted;
layout(location = 10) flat out vec4 outFlatEnvReflected;  // one lookup per triangle, like its colour
layout(location = 11) flat out vec4 outFlatEnvRefracted;

void main() {
  vec3 p0 = inPosition[0], p1 = inPosition[1], p2 = inPosition[2];
  vec3 faceNormal = cross(p1 - p0, p2 - p0);
  vec3 center = (p0 + p1 + p2) / 3.0;
  vec3 diffusePart, specularPart;
  illuminateParts(center, faceNormal, diffusePart, specularPart);
  EnvironmentDirections environment = EnvironmentDirections(vec4(0.0), vec4(0.0));
  if (environmentEnabled) environment = environmentDirections(center, faceNormal, draw.optics.z);
  for (int i = 0; i < 3; ++i) {
    gl_Position = gl_in[i].gl_Position;
    outPosition = inPosition[i];
    outNormal = faceNormal;
    outColor = diffusePart;
    outFlatColor = diffusePart;
    outUv = inUv[i];
    outTangent = inTangent[i];
    outSpecular = specularPart;
    outFlatSpecular = specularPart;
    outEnvReflected = environment.reflected;
    outEnvRefracted = environment.refracted;
    outFlatEnvReflected = environment.reflected;
    outFlatEnvRefracted = environment.refracted;
    EmitVertex();
  }
  EndPrimitive();
}
