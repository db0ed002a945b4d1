#version 460
// The forward fragment stage of Phong, Blinn-Phong and unlit (forward_fragment.glsl).
#extension GL_GOOGLE_include_directive : require
#include "forward_fragment.glsl"
