#version 460
// Flat shading: one colour per triangle, from the illumination equation
// evaluated once at the centroid with the triangle's geometric normal (not
// a vertex's averaged normal). A geometry shader sees the whole triangle,
// which neither the vertex nor the fragment stage does.
#extension GL_GOOGLE_include_directive : require
#include "environment.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

layout(location = 0) in vec3 inPosition[];

// What forward_flat.frag reads: one colour and one environment lookup per triangle.
layout(location = 3) flat out vec3 outFlatColor;
layout(location = 10) flat out vec4 outFlatEnvReflected;
layout(location = 11) flat out vec4 outFlatEnvRefracted;

void main() {
  vec3 p0 = inPosition[0], p1 = inPosition[1], p2 = inPosition[2];
  // Counter-clockwise winding seen from the front gives the outward normal.
  vec3 faceNormal = cross(p1 - p0, p2 - p0);
  vec3 center = (p0 + p1 + p2) / 3.0;
  vec3 color = illuminate(center, faceNormal, drawMaterial(), false);
  EnvironmentDirections environment = EnvironmentDirections(vec4(0.0), vec4(0.0));
  if (environmentEnabled) environment = environmentDirections(center, faceNormal, draw.optics.z);
  for (int i = 0; i < 3; ++i) {
    gl_Position = gl_in[i].gl_Position;
    outFlatColor = color;
    outFlatEnvReflected = environment.reflected;
    outFlatEnvRefracted = environment.refracted;
    EmitVertex();
  }
  EndPrimitive();
}
