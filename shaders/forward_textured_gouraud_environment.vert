#version 460
// The textured vertex stage of Gouraud shading with an environment (forward_vertex.glsl).
#extension GL_GOOGLE_include_directive : require
#define VERTEX_LIGHTING
#define ENVIRONMENT_VARYINGS
#define TEXTURED
#include "forward_vertex.glsl"
