#version 460
// Billboard pass, fragment stage: the quad lit as a flat surface with the
// Phong illumination equation (lighting.glsl; Blinn-Phong when the frame's
// model is, unlit as the diffuse colour; flat and Gouraud light a flat quad
// per fragment too, since its normal is the same everywhere), optionally
// bumped by a normal map, and shadowed like any receiver. The diffuse
// texture's alpha cuts the quad out (SPEC_ALPHA_MASK: below draw.ka.w, the
// cut-off, the fragment is discarded) or, for the blended variant, is the
// opacity it is blended with (times kd.w, 1 - transparency).
#extension GL_GOOGLE_include_directive : require
#define SHADOW_LOOKUP
#include "bump.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 4) in vec2 inUv;
layout(location = 5) in vec4 inTangent;

layout(location = 0) out vec4 outColor;

void main() {
  vec2 st = textureCoordinate(inUv);
  vec4 texel = texture(diffuseMap, st);
  if (alphaMask && texel.a < draw.ka.w) discard;
  vec3 color;
  if (shadingModel == SHADING_UNLIT) {
    color = diffuseTexel(st) * draw.kd.rgb;
  } else {
    SurfaceMaterial material = drawMaterial();
    vec3 diffuse = diffuseTexel(st);
    material.ka *= diffuse;
    material.kd *= diffuse;
    vec3 normal = bumpedNormal(inNormal, inTangent, st);
    // Seen from behind (a cylindrical quad from above its axis), the back
    // is lit as the front.
    if (!gl_FrontFacing) normal = -normal;
    color = illuminate(inPosition, normal, material, shadingModel == SHADING_BLINN_PHONG);
  }
  outColor = vec4(color, alphaMask ? 1.0 : texel.a * draw.kd.w);
}
