#version 460
// The textured vertex stage of Gouraud shading with an environment (forward_textured_vertex.glsl).
#extension GL_GOOGLE_include_directive : require
#define VERTEX_LIGHTING
#define ENVIRONMENT_VARYINGS
#include "forward_textured_vertex.glsl"
