#version 460
// The textured fragment stage of Gouraud shading (forward_textured_fragment.glsl).
#extension GL_GOOGLE_include_directive : require
#define VERTEX_LIGHTING
#include "forward_textured_fragment.glsl"
