#version 460
// The forward fragment stage of Gouraud shading (forward_fragment.glsl).
#extension GL_GOOGLE_include_directive : require
#define VERTEX_LIGHTING
#include "forward_fragment.glsl"
