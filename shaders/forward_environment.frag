#version 460
// The forward fragment stage with an environment (forward_fragment.glsl).
#extension GL_GOOGLE_include_directive : require
#define ENVIRONMENT_VARYINGS
#include "forward_fragment.glsl"
