// Forward pass, vertex stage of the textured variants (forward_textured.vert,
// forward_textured_gouraud.vert, forward_textured_gouraud_environment.vert):
// forward_vertex.glsl plus the texture coordinate and the eye-space tangent
// frame. Gouraud (VERTEX_LIGHTING) lights here, keeping the part the diffuse
// texel scales apart from the specular part. As in forward_vertex.glsl each
// variant declares only the outputs its fragment stage reads.
#extension GL_GOOGLE_include_directive : require
#include "environment.glsl"
#include "texturing.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec4 inTangent;

layout(location = 4) out vec2 outUv;
#ifdef VERTEX_LIGHTING
layout(location = 2) out vec3 outColor;     // Ia ka + sum f_att Ip kd N.L
layout(location = 6) out vec3 outSpecular;  // sum f_att Ip ks (R.V)^n
#ifdef ENVIRONMENT_VARYINGS
layout(location = 8) out vec4 outEnvReflected;  // environment.glsl's directions
layout(location = 9) out vec4 outEnvRefracted;
#endif
#else
layout(location = 0) out vec3 outPosition;  // eye space
layout(location = 1) out vec3 outNormal;    // eye space, not normalised
layout(location = 5) out vec4 outTangent;   // eye space xyz, w = handedness
#endif

void main() {
  ObjectData object = objects[draw.object.x];
  vec4 eye = object.modelView * vec4(inPosition, 1.0);
  vec3 normal = mat3(object.normalMatrix) * inNormal;
  outUv = inUv;
#ifdef VERTEX_LIGHTING
  illuminateParts(eye.xyz, normal, outColor, outSpecular);
#ifdef ENVIRONMENT_VARYINGS
  EnvironmentDirections environment = environmentDirections(eye.xyz, normal, draw.optics.z);
  outEnvReflected = environment.reflected;
  outEnvRefracted = environment.refracted;
#endif
#else
  outPosition = eye.xyz;
  outNormal = normal;
  // Tangents lie in the surface, so they transform like positions; a
  // mirroring transform flips the frame's handedness.
  mat3 linear = mat3(object.modelView);
  outTangent = vec4(linear * inTangent.xyz,
                    inTangent.w * (determinant(linear) < 0.0 ? -1.0 : 1.0));
#endif
  gl_Position = frame.projection * eye;
}
