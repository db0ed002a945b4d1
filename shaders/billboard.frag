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
#include "impostor_atlas.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) flat in vec3 inNormal;
layout(location = 4) in vec2 inUv;
layout(location = 5) flat in vec4 inTangent;
#ifdef IMPOSTOR_BLEND
layout(location = 6) flat in vec4 inCellRight[3];  // billboard.vert
layout(location = 9) flat in vec4 inCellUp[3];
layout(location = 12) flat in vec3 inImpostorCentre;
#endif

layout(location = 0) out vec4 outColor;

layout(constant_id = SPEC_BILLBOARD_KIND) const int kind = BILLBOARD_CYLINDRICAL;

#ifdef IMPOSTOR_BLEND
// An impostor's texel: its three atlas cells, each looked up where the view
// ray through this fragment meets the plane its image was captured in (the
// camera's ray: from the eye, or along -z for an orthographic camera), and
// blended by weight times coverage. rgb: the covered cells' mean albedo,
// a: the blended coverage. With normals (bumpMapped): `normal` their mean
// surface normal in eye space and `position` their mean surface point (each
// cell's height, its normal map's alpha, off its plane).
vec4 impostorTexel(bool bumpMapped, out vec3 normal, out vec3 position) {
  bool orthographic = frame.projection[3][3] != 0.0;
  vec3 origin = orthographic ? inPosition : vec3(0.0);
  vec3 ray = orthographic ? vec3(0.0, 0.0, -1.0) : inPosition;
  int cells = int(draw.optics.z);
  float halfSide = inTangent.w;
  vec4 sum = vec4(0.0);
  normal = vec3(0.0);
  position = vec3(0.0);
  for (int k = 0; k < 3; ++k) {
    vec3 right = inCellRight[k].xyz, up = inCellUp[k].xyz, facing = cross(right, up);
    float across = dot(ray, facing);
    float t = abs(across) > 1e-20 ? dot(inImpostorCentre - origin, facing) / across : 0.0;
    vec3 local = origin + t * ray - inImpostorCentre;
    vec2 corner = vec2(dot(local, right), dot(local, up)) / (2.0 * halfSide) + 0.5;
    vec2 st = textureCoordinate(impostorAtlasCoordinate(int(inCellUp[k].w), cells, corner));
    vec4 texel = texture(diffuseMap, st);
    // Off the cell's square lies another cell's image.
    bool inside = abs(across) > 1e-20 && all(greaterThanEqual(corner, vec2(0.0))) &&
                  all(lessThanEqual(corner, vec2(1.0)));
    float coverage = inside ? inCellRight[k].w * texel.a : 0.0;
    sum += vec4(texel.rgb * coverage, coverage);
    if (bumpMapped) {
      vec4 mapped = texture(normalMap, st);
      vec3 n = mapped.xyz * 2.0 - 1.0;
      normal += coverage * (right * (n.x * draw.texturing.z) + up * (n.y * draw.texturing.z) +
                            facing * n.z);
      position += coverage * (inImpostorCentre + local + facing * (impostorHeight(mapped.a) * halfSide));
    }
  }
  float a = sum.a;
  position = a > 0.0 ? position / a : inPosition;
  return vec4(a > 0.0 ? sum.rgb / a : vec3(0.0), a);
}
#endif

void main() {
  bool bumpMapped = hasMap(TEXTURE_NORMAL | TEXTURE_HEIGHT);
  // A trimmed copy's triangle reaches past the quad: what lies outside it
  // is not the billboard's.
  if (draw.optics.w > 0.5 && (any(lessThan(inUv, vec2(0.0))) || any(greaterThan(inUv, vec2(1.0)))))
    discard;
  vec2 st = textureCoordinate(inUv);
#ifdef IMPOSTOR_BLEND
  vec3 impostorNormal, impostorPosition;
  vec4 texel = impostorTexel(bumpMapped, impostorNormal, impostorPosition);
#else
  vec4 texel = texture(diffuseMap, st);
#endif
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
#ifdef IMPOSTOR_BLEND
    if (bumpMapped) {
      normal = impostorNormal;
      position = impostorPosition;
    }
#else
    if (bumpMapped && kind == BILLBOARD_IMPOSTOR) {
      position += normalize(inNormal) * impostorHeight(texture(normalMap, st).a) * inTangent.w;
    }
#endif
    // Seen from behind (a cylindrical quad from above its axis), the back
    // is lit as the front.
    if (!gl_FrontFacing) normal = -normal;
    color = illuminate(position, normal, material, shadingModel == SHADING_BLINN_PHONG) +
            drawEmissive();
  }
  outColor = vec4(color, alphaMask ? 1.0 : texel.a * draw.kd.w);
}
