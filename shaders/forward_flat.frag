#version 460
// The forward fragment stage of flat shading, after forward_flat.geom (forward_fragment.glsl).
#extension GL_GOOGLE_include_directive : require
#define FLAT_VARYINGS
#include "forward_fragment.glsl"
