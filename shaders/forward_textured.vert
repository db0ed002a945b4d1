#version 460
// The textured vertex stage of the per-fragment models and flat (forward_vertex.glsl).
#extension GL_GOOGLE_include_directive : require
#define TEXTURED
#include "forward_vertex.glsl"
