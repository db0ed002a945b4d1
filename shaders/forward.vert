#version 460
// The forward vertex stage without environment outputs (forward_vertex.glsl).
#extension GL_GOOGLE_include_directive : require
#include "forward_vertex.glsl"
