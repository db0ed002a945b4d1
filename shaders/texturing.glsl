// Texture mapping for the textured forward variants: set 1 (one per
// material), texture coordinates, lighting split for the diffuse texel.
// UVs follow the course convention (origin at the bottom left, v up, see
// core/scene/mesh.h); images are stored top row first, so t = 1 - v.
#ifndef TEXTURING_GLSL
#define TEXTURING_GLSL
#include "lighting.glsl"
#include "uv_transform.glsl"

layout(set = 1, binding = BINDING_DIFFUSE_MAP) uniform sampler2D diffuseMap;
layout(set = 1, binding = BINDING_NORMAL_MAP) uniform sampler2D normalMap;
layout(set = 1, binding = BINDING_HEIGHT_MAP) uniform sampler2D heightMap;

// The maps this pipeline applies (SPEC_TEXTURE_MAPS): compiled in, so a
// material without a map runs none of its code.
layout(constant_id = SPEC_TEXTURE_MAPS) const int textureMaps = 0;
bool hasMap(int flag) { return (textureMaps & flag) != 0; }

// Where to sample: the UV scaled by the material's repeats, v flipped.
vec2 textureCoordinate(vec2 uv) {
  return vec2(uv.x * draw.texturing.x, 1.0 - uv.y * draw.texturing.y);
}

// Flat and Gouraud light before the texel is known, so they keep the parts the
// texel scales (Ia ka + sum f_att Ip kd N.L) apart from the specular sum:
// I = texel * diffusePart + specularPart, the same equation regrouped.
void illuminateParts(vec3 position, vec3 normal, out vec3 diffusePart, out vec3 specularPart) {
  SurfaceMaterial material = drawMaterial();
  SurfaceMaterial diffuseOnly = SurfaceMaterial(material.ka, material.kd, vec3(0.0), 0.0);
  SurfaceMaterial specularOnly =
      SurfaceMaterial(vec3(0.0), vec3(0.0), material.ks, material.shininess);
  diffusePart = illuminate(position, normal, diffuseOnly, false);
  specularPart = illuminate(position, normal, specularOnly, false);
}

// illuminateParts with each light's term apart (flat and Gouraud with shadows).
void illuminatePartsEach(vec3 position, vec3 normal, out vec3 ambientPart,
                         out vec3 diffuseTerms[MAX_LIGHTS], out vec3 specularTerms[MAX_LIGHTS]) {
  SurfaceMaterial material = drawMaterial();
  SurfaceMaterial diffuseOnly = SurfaceMaterial(material.ka, material.kd, vec3(0.0), 0.0);
  SurfaceMaterial specularOnly =
      SurfaceMaterial(vec3(0.0), vec3(0.0), material.ks, material.shininess);
  vec3 noAmbient;
  illuminateEach(position, normal, diffuseOnly, false, ambientPart, diffuseTerms);
  illuminateEach(position, normal, specularOnly, false, noAmbient, specularTerms);
}
#endif
