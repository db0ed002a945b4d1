#version 460
// Flat shading: one colour per triangle, from the illumination equation
// evaluated once at the centroid with the triangle's geometric normal (not
// a vertex's averaged normal). A geometry shader sees the whole triangle,
// which neither the vertex nor the fragment stage does.
// TEXTURED passes the texture coordinate through and keeps the lighting in
// two parts (the diffuse texel scales one). Bump maps do not apply: flat
// shading lights a triangle once, with its geometric normal.
#extension GL_GOOGLE_include_directive : require
#include "environment.glsl"
#ifdef TEXTURED
#include "texturing.glsl"
#endif

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

// From the vertex stage: what the face needs; out: what the fragment stage
// (FLAT_VARYINGS) reads: one colour and one environment lookup per triangle.
layout(location = 0) in vec3 inPosition[];
#ifdef TEXTURED
layout(location = 4) in vec2 inUv[];
#endif

layout(location = 3) flat out vec3 outFlatColor;
#ifdef TEXTURED
layout(location = 4) out vec2 outUv;
layout(location = 7) flat out vec3 outFlatSpecular;
#endif
layout(location = 10) flat out vec4 outFlatEnvReflected;
layout(location = 11) flat out vec4 outFlatEnvRefracted;
#ifdef SHADOW_VARYINGS
// With shadows, outFlatColor is the ambient part only; each light's term is
// weighed by k_shadow per fragment (lighting.glsl), looked up at the
// fragment's position with the face normal.
layout(location = 12) out vec3 outShadowPosition;
layout(location = 13) flat out vec3 outShadowNormal;
layout(location = 14) flat out vec3 outLightTerms[MAX_LIGHTS];
#ifdef TEXTURED
layout(location = 22) flat out vec3 outLightSpecular[MAX_LIGHTS];
#endif
#endif

void main() {
  vec3 p0 = inPosition[0], p1 = inPosition[1], p2 = inPosition[2];
  // Counter-clockwise winding seen from the front gives the outward normal.
  vec3 faceNormal = cross(p1 - p0, p2 - p0);
  vec3 center = (p0 + p1 + p2) / 3.0;
  // doubleSided: a triangle facing away from the eye (V = -center, as the
  // lighting takes it) is lit with the flipped normal.
  if (doubleSided && dot(faceNormal, -center) < 0.0) faceNormal = -faceNormal;
#ifdef SHADOW_VARYINGS
  vec3 terms[MAX_LIGHTS];
#ifdef TEXTURED
  vec3 diffusePart, specularTerms[MAX_LIGHTS];
  vec3 specularPart = vec3(0.0);
  illuminatePartsEach(center, faceNormal, diffusePart, terms, specularTerms);
#else
  vec3 color;
  illuminateEach(center, faceNormal, drawMaterial(), false, color, terms);
#endif
#elif defined(TEXTURED)
  vec3 diffusePart, specularPart;
  illuminateParts(center, faceNormal, diffusePart, specularPart);
#else
  vec3 color = illuminate(center, faceNormal, drawMaterial(), false);
#endif
  EnvironmentDirections environment = EnvironmentDirections(vec4(0.0), vec4(0.0));
  if (environmentEnabled) environment = environmentDirections(center, faceNormal, draw.optics.z);
  for (int i = 0; i < 3; ++i) {
    gl_Position = gl_in[i].gl_Position;
#ifdef TEXTURED
    outFlatColor = diffusePart;
    outUv = inUv[i];
    outFlatSpecular = specularPart;
#else
    outFlatColor = color;
#endif
    outFlatEnvReflected = environment.reflected;
    outFlatEnvRefracted = environment.refracted;
#ifdef SHADOW_VARYINGS
    outShadowPosition = inPosition[i];
    outShadowNormal = faceNormal;
    outLightTerms = terms;
#ifdef TEXTURED
    outLightSpecular = specularTerms;
#endif
#endif
    EmitVertex();
  }
  EndPrimitive();
}
