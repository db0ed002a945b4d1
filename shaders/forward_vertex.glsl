#version 460
// Forward pass, vertex stage. Gouraud (VERTEX_LIGHTING) evaluates the
// illumination equation here, at each vertex with its averaged normal, and
// with ENVIRONMENT_VARYINGS its environment directions too; the other models
// pass the eye-space position and normal on. TEXTURED adds the texture
// coordinate and the eye-space tangent frame, and Gouraud then keeps the part
// the diffuse texel scales apart from the specular part.
// Each variant declares only the outputs its fragment stage reads: lavapipe
// sets up and interpolates every output, and the unused ones made the 800x600
// Gouraud frame 1.36x glmark2's (scripts/peer_bench.sh, docs/PERFORMANCE.md).
// The variants and their defines: the shader table in shaders/CMakeLists.txt.
#extension GL_GOOGLE_include_directive : require
#include "environment.glsl"
#ifdef TEXTURED
#include "texturing.glsl"
#endif

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
#ifdef TEXTURED
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec4 inTangent;

layout(location = 4) out vec2 outUv;
#endif

#ifdef VERTEX_LIGHTING
layout(location = 2) out vec3 outColor;  // lit colour; TEXTURED: Ia ka + sum f_att Ip kd N.L
#ifdef TEXTURED
layout(location = 6) out vec3 outSpecular;  // sum f_att Ip ks (R.V)^n
#endif
#ifdef ENVIRONMENT_VARYINGS
layout(location = 8) out vec4 outEnvReflected;  // environment.glsl's directions
layout(location = 9) out vec4 outEnvRefracted;
#endif
#ifdef SHADOW_VARYINGS
// With shadows, outColor is the ambient part only and each light's term
// travels apart; the fragment stage weighs them by k_shadow (lighting.glsl).
layout(location = 12) out vec3 outShadowPosition;  // eye space, for the lookup
layout(location = 13) out vec3 outShadowNormal;
layout(location = 14) out vec3 outLightTerms[MAX_LIGHTS];  // TEXTURED: the parts the texel scales
#ifdef TEXTURED
layout(location = 22) out vec3 outLightSpecular[MAX_LIGHTS];
#endif
#endif
#else
layout(location = 0) out vec3 outPosition;  // eye space
layout(location = 1) out vec3 outNormal;    // eye space, not normalised
#ifdef TEXTURED
layout(location = 5) out vec4 outTangent;  // eye space xyz, w = handedness
#endif
#ifdef SHADOW_COORDINATES
// Phong with shadows: each shadowed light's shadowMapCoordinates()
// (shadows.glsl; the biases included), found here per vertex and
// interpolated instead of per fragment.
SHADOW_COORDINATE_VARYINGS(out, outShadowCoordinates)
#endif
#endif

void main() {
  // An instanced draw's copies have consecutive ObjectData (batchInstances,
  // core/vulkan/gpu_scene.h); any other draw is one instance, index 0.
  ObjectData object = objects[draw.object.x + gl_InstanceIndex];
  vec4 eye = object.modelView * vec4(inPosition, 1.0);
  // Normals transform by the inverse transpose of the model-view matrix.
  vec3 normal = mat3(object.normalMatrix) * inNormal;
#ifdef VERTEX_LIGHTING
  // doubleSided: Gouraud lights only here, where the facing of the triangle is
  // unknown; a normal facing away from the eye is flipped (per vertex, so a
  // triangle across a silhouette may mix the two sides).
  if (doubleSided && dot(normal, -eye.xyz) < 0.0) normal = -normal;
#endif
#ifdef TEXTURED
  outUv = inUv;
#endif
#ifdef VERTEX_LIGHTING
#if defined(SHADOW_VARYINGS)
  outShadowPosition = eye.xyz;
  outShadowNormal = normal;
#ifdef TEXTURED
  illuminatePartsEach(eye.xyz, normal, outColor, outLightTerms, outLightSpecular);
  outSpecular = vec3(0.0);
#else
  illuminateEach(eye.xyz, normal, drawMaterial(), false, outColor, outLightTerms);
#endif
#elif defined(TEXTURED)
  illuminateParts(eye.xyz, normal, outColor, outSpecular);
#else
  outColor = illuminate(eye.xyz, normal, drawMaterial(), false);
#endif
#ifdef ENVIRONMENT_VARYINGS
  EnvironmentDirections environment = environmentDirections(eye.xyz, normal, draw.optics.z);
  outEnvReflected = environment.reflected;
  outEnvRefracted = environment.refracted;
#endif
#else
  outPosition = eye.xyz;
  outNormal = normal;
#ifdef SHADOW_COORDINATES
  // Only the lights with maps: the others are neither written nor read.
#define SHADOW_COORDINATES_OF(i) \
  if (castsShadows(i)) outShadowCoordinates##i = shadowMapCoordinates(i, eye.xyz, normal);
  SHADOW_COORDINATES_OF(0) SHADOW_COORDINATES_OF(1) SHADOW_COORDINATES_OF(2)
  SHADOW_COORDINATES_OF(3) SHADOW_COORDINATES_OF(4) SHADOW_COORDINATES_OF(5)
  SHADOW_COORDINATES_OF(6) SHADOW_COORDINATES_OF(7)
#undef SHADOW_COORDINATES_OF
#endif
#ifdef TEXTURED
  // Tangents lie in the surface, so they transform like positions; a
  // mirroring transform flips the frame's handedness.
  mat3 linear = mat3(object.modelView);
  outTangent = vec4(linear * inTangent.xyz,
                    inTangent.w * (determinant(linear) < 0.0 ? -1.0 : 1.0));
#endif
#endif
  gl_Position = frame.projection * eye;
}
