#version 460
// The textured fragment stage of Gouraud shading with an environment (forward_fragment.glsl).
#extension GL_GOOGLE_include_directive : require
#define VERTEX_LIGHTING
#define ENVIRONMENT_VARYINGS
#define TEXTURED
#include "forward_fragment.glsl"
