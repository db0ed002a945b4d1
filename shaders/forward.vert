#version 460
// The forward vertex stage of the per-fragment models and flat (forward_vertex.glsl).
#extension GL_GOOGLE_include_directive : require
#include "forward_vertex.glsl"
