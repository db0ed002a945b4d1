#version 460
// Flat shading of the textured variants: forward_flat.geom with the texture
// coordinate passed through and the lighting kept in two parts
// (the diffuse texel scales one). Bump maps do not apply: flat shading
// lights a triangle once, with its geometric normal.
#extension GL_GOOGLE_include_directive : require
#include "environment.glsl"
#include "texturing.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

// From forward_textured.vert: what the face needs; out: what forward_textured_flat.frag reads.
layout(location = 0) in vec3 inPosition[];
layout(location = 4) in vec2 inUv[];

layout(location = 3) flat out vec3 outFlatColor;
layout(location = 4) out vec2 outUv;
layout(location = 7) flat out vec3 outFlatSpecular;
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
    outFlatColor = diffusePart;
    outUv = inUv[i];
    outFlatSpecular = specularPart;
    outFlatEnvReflected = environment.reflected;
    outFlatEnvRefracted = environment.refracted;
    EmitVertex();
  }
  EndPrimitive();
}
