#version 460
// The forward fragment stage of the lit and unlit models without an environment (forward_fragment.glsl).
#extension GL_GOOGLE_include_directive : require
#include "forward_fragment.glsl"
