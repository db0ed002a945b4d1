#version 460
// The textured fragment stage of Phong, Blinn-Phong and unlit (forward_fragment.glsl).
#extension GL_GOOGLE_include_directive : require
#define TEXTURED
#include "forward_fragment.glsl"
