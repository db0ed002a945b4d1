#version 460
// The textured fragment stage of Phong, Blinn-Phong and unlit (forward_textured_fragment.glsl).
#extension GL_GOOGLE_include_directive : require
#include "forward_textured_fragment.glsl"
