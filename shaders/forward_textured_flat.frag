#version 460
// The textured fragment stage of flat shading, after forward_textured_flat.geom (forward_fragment.glsl).
#extension GL_GOOGLE_include_directive : require
#define FLAT_VARYINGS
#define TEXTURED
#include "forward_fragment.glsl"
