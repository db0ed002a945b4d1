#version 460
// Forward pass, fragment stage: Phong and Blinn-Phong evaluate the equation
// per fragment with the interpolated, renormalised normal; flat and Gouraud
// output the colour computed earlier; unlit writes the diffuse colour as is.
// With an environment, every lit model adds its term (environment.glsl), from
// directions found per fragment, per vertex (Gouraud) or per triangle (flat).
// TEXTURED: the diffuse texel multiplies ka and kd in every model. Bump
// mapping needs the equation per fragment, so only Phong and Blinn-Phong
// apply normal and height maps, and reflect and refract about the bumped
// normal; flat and Gouraud light with the geometric / vertex normals.
// The variants differ only in their inputs (forward_vertex.glsl says why):
// FLAT_VARYINGS: the flat geometry stage's per-triangle colour and directions;
// VERTEX_LIGHTING: Gouraud's vertex colour, with ENVIRONMENT_VARYINGS its
// per-vertex directions; neither: the eye-space position and normal.
#extension GL_GOOGLE_include_directive : require
// Shadow maps are looked up here only (shaders/shadows.glsl).
#define SHADOW_LOOKUP
#ifdef TEXTURED
#include "bump.glsl"
#endif
#include "environment.glsl"

#ifdef TEXTURED
layout(location = 4) in vec2 inUv;
#endif
#if defined(FLAT_VARYINGS)
layout(location = 3) flat in vec3 inFlatColor;
#ifdef TEXTURED
layout(location = 7) flat in vec3 inFlatSpecular;
#endif
layout(location = 10) flat in vec4 inFlatEnvReflected;
layout(location = 11) flat in vec4 inFlatEnvRefracted;
#elif defined(VERTEX_LIGHTING)
layout(location = 2) in vec3 inColor;
#ifdef TEXTURED
layout(location = 6) in vec3 inSpecular;
#endif
#ifdef ENVIRONMENT_VARYINGS
layout(location = 8) in vec4 inEnvReflected;
layout(location = 9) in vec4 inEnvRefracted;
#endif
#else
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
#ifdef TEXTURED
layout(location = 5) in vec4 inTangent;
#endif
#endif

#ifdef SHADOW_VARYINGS
layout(location = 12) in vec3 inShadowPosition;
#ifdef FLAT_VARYINGS
layout(location = 13) flat in vec3 inShadowNormal;
layout(location = 14) flat in vec3 inLightTerms[MAX_LIGHTS];
#ifdef TEXTURED
layout(location = 22) flat in vec3 inLightSpecular[MAX_LIGHTS];
#endif
#else
layout(location = 13) in vec3 inShadowNormal;
layout(location = 14) in vec3 inLightTerms[MAX_LIGHTS];
#ifdef TEXTURED
layout(location = 22) in vec3 inLightSpecular[MAX_LIGHTS];
#endif
#endif
#endif

layout(location = 0) out vec4 outColor;

// Flat and Gouraud light before the texel is known; TEXTURED passes the light
// in two parts (texturing.glsl): I = texel * diffusePart + specularPart.
#ifdef TEXTURED
#define LIT_EARLIER(diffusePart, specularPart) (texel * diffusePart + specularPart)
#else
#define LIT_EARLIER(color, noSpecularPart) (color)
#endif

void main() {
#ifdef TEXTURED
  vec2 st = textureCoordinate(inUv);
  // The normal and height maps' coordinates (their own texture transform).
  vec2 bumpSt = st;
  if (hasMap(TEXTURE_UV_TRANSFORM)) {
    bumpSt = transformedCoordinate(st, draw.normalUv, draw.optics.w);
    st = transformedCoordinate(st, draw.diffuseUv, draw.texturing.w);
  }
  // alphaMode MASK: the texel's alpha against alphaCutoff / the factor's alpha.
  if (alphaMask && (hasMap(TEXTURE_DIFFUSE) ? texture(diffuseMap, st).a : 1.0) < draw.ka.w)
    discard;
  vec3 texel = diffuseTexel(st);
  // glTF BLEND: the texel's alpha times the factor's.
  float opacity = draw.kd.w * (hasMap(TEXTURE_ALPHA) ? texture(diffuseMap, st).a : 1.0);
#else
  float opacity = draw.kd.w;
  if (alphaMask && 1.0 < draw.ka.w) discard;
#endif
#if defined(FLAT_VARYINGS)
  vec3 color = LIT_EARLIER(inFlatColor, inFlatSpecular);
  EnvironmentDirections environment =
      EnvironmentDirections(inFlatEnvReflected, inFlatEnvRefracted);
#elif defined(VERTEX_LIGHTING)
  vec3 color = LIT_EARLIER(inColor, inSpecular);
#ifdef ENVIRONMENT_VARYINGS
  EnvironmentDirections environment = EnvironmentDirections(inEnvReflected, inEnvRefracted);
#else
  EnvironmentDirections environment = EnvironmentDirections(vec4(0.0), vec4(0.0));
#endif
#elif defined(TEXTURED)
  vec3 color;
  vec3 normal = inNormal;
  if (shadingModel == SHADING_UNLIT) {
    color = texel * drawMaterial().kd;
  } else {
    SurfaceMaterial material = drawMaterial();
    material.ka *= texel;
    material.kd *= texel;
    normal = bumpedNormal(inNormal, inTangent, bumpSt);
    // doubleSided: a back face is lit as the front seen from behind.
    if (doubleSided && !gl_FrontFacing) normal = -normal;
    color = illuminate(inPosition, normal, material, shadingModel == SHADING_BLINN_PHONG);
  }
  EnvironmentDirections environment = environmentDirections(inPosition, normal, draw.optics.z);
#else
  vec3 normal = inNormal;
  // doubleSided: a back face is lit as the front seen from behind.
  if (doubleSided && !gl_FrontFacing) normal = -normal;
  vec3 color = shadingModel == SHADING_UNLIT
                   ? drawMaterial().kd
                   : illuminate(inPosition, normal, drawMaterial(),
                                shadingModel == SHADING_BLINN_PHONG);
  EnvironmentDirections environment = environmentDirections(inPosition, normal, draw.optics.z);
#endif
#ifdef SHADOW_VARYINGS
  // color holds the ambient part; each light's term enters weighed by its
  // k_shadow at this fragment.
  float k[MAX_LIGHTS];
  shadowCoefficients(inShadowPosition, inShadowNormal, k);
#ifdef TEXTURED
  // The specular part passed on is zero here: it travels per light.
  color += texel * shadowedSum(k, inLightTerms) + shadowedSum(k, inLightSpecular);
#else
  color += shadowedSum(k, inLightTerms);
#endif
#endif
  if (shadingModel != SHADING_UNLIT) color += drawEmissive();
  if (environmentEnabled && shadingModel != SHADING_UNLIT)
    color += environmentColor(environment, draw.optics.x, draw.optics.y);
  // kd.w: opacity, 1 - transparency (times a glTF BLEND texel's alpha), for the blended draws.
  // Where the environment term refracts (kt > 0, not glTF BLEND) the transmitted light is
  // env(T), so the surface is opaque.
  outColor = vec4(color, environmentEnabled && environmentRefracts ? 1.0 : opacity);
}
