#version 460
// The textured vertex stage of the per-fragment models and flat (forward_textured_vertex.glsl).
#extension GL_GOOGLE_include_directive : require
#include "forward_textured_vertex.glsl"
