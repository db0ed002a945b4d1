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
layout(location = 1) flat in vec3 inNormal;
layout(location = 4) in vec2 inUv;
layout(location = 5) flat in vec4 inTangent;

layout(location = 0) out vec4 outColor;

layout(constant_id = SPEC_BILLBOARD_KIND) const int kind = BILLBOARD_CYLINDRICAL;

void main() {
  bool bumpMapped = hasMap(TEXTURE_NORMAL | TEXTURE_HEIGHT);
  // A trimmed copy's triangle reaches past the quad: what lies outside it
  // is not the billboard's.
  if (draw.optics.w > 0.5 && (any(lessThan(inUv, vec2(0.0))) || any(greaterThan(inUv, vec2(1.0)))))
    discard;
  vec2 st = textureCoordinate(inUv);
  vec4 texel = texture(diffuseMap, st);
  if (alphaMask && texel.a < draw.ka.w) discard;
  vec3 color;
  // One lookup serves the cut-out and the colour (diffuseTexel's formula,
  // which would sample again).
  vec3 diffuse = texel.rgb;
  if (hasMap(TEXTURE_MIP_TINT))
    diffuse = mipLevelColor(textureQueryLod(diffuseMap, st).x) * (0.35 + 0.65 * diffuse);
  if (shadingModel == SHADING_UNLIT) {
    color = diffuse * draw.kd.rgb;
  } else {
    SurfaceMaterial material = drawMaterial();
    material.ka *= diffuse;
    material.kd *= diffuse;
    vec3 normal = bumpMapped ? bumpedNormal(inNormal, inTangent, st) : inNormal;
    // An impostor's texel lies off the quad by the height its atlas keeps
    // (impostor_capture.frag): lit and shadowed there, where the surface is.
    vec3 position = inPosition;
    if (bumpMapped && kind == BILLBOARD_IMPOSTOR) {
      float height = ((texture(normalMap, st).a * 255.0 - 1.0) / 254.0) * 2.0 - 1.0;
      position += normalize(inNormal) * height * inTangent.w;
    }
    // Seen from behind (a cylindrical quad from above its axis), the back
    // is lit as the front.
    if (!gl_FrontFacing) normal = -normal;
    color = illuminate(position, normal, material, shadingModel == SHADING_BLINN_PHONG);
  }
  outColor = vec4(color, alphaMask ? 1.0 : texel.a * draw.kd.w);
}
