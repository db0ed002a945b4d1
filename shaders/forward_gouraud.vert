#version 460
// The forward vertex stage of Gouraud shading (forward_vertex.glsl).
#extension GL_GOOGLE_include_directive : require
#define VERTEX_LIGHTING
#include "forward_vertex.glsl"
