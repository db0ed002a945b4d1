#version 460
// The forward vertex stage with Gouraud's environment directions (forward_vertex.glsl).
#extension GL_GOOGLE_include_directive : require
#define ENVIRONMENT_VARYINGS
#include "forward_vertex.glsl"
