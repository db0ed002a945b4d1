#version 460
// The textured vertex stage of Gouraud shading (forward_textured_vertex.glsl).
#extension GL_GOOGLE_include_directive : require
#define VERTEX_LIGHTING
#include "forward_textured_vertex.glsl"
