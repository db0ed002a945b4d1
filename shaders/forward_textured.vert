#version 460
// Forward pass, vertex stage of the textured variants: forward.vert plus the
// texture coordinate and the eye-space tangent frame. Gouraud lights here,
// keeping the part the diffuse texel scales apart from the specular part.
#extension GL_GOOGLE_include_directive : require
#include "environment.glsl"
#include "texturing.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec4 inTangent;

layout(location = 0) out vec3 outPosition;  // eye space
layout(location = 1) out vec3 outNormal;    // eye space, not normalised
layout(location = 2) out vec3 outColor;     // Gouraud: Ia ka + sum f_att Ip kd N.L
layout(location = 3) flat out vec3 outFlatColor;
layout(location = 4) out vec2 outUv;
layout(location = 5) out vec4 outTangent;   // eye space xyz, w = handedness
layout(location = 6) out vec3 outSpecular;  // Gouraud: sum f_att Ip ks (R.V)^n
layout(location = 7) flat out vec3 outFlatSpecular;
// Environment directions (environment.glsl): per vertex for Gouraud, per triangle for flat.
layout(location = 8) out vec4 outEnvReflected;
layout(location = 9) out vec4 outEnvRefracted;
layout(location = 10) flat out vec4 outFlatEnvReflected;
layout(location = 11) flat out vec4 outFlatEnvRefracted;

void main() {
  ObjectData object = objects[draw.object.x];
  vec4 eye = object.modelView * vec4(inPosition, 1.0);
  outPosition = eye.xyz;
  outNormal = mat3(object.normalMatrix) * inNormal;
  // Tangents lie in the surface, so they transform like positions; a
  // mirroring transform flips the frame's handedness.
  mat3 linear = mat3(object.modelView);
  outTangent = vec4(linear * inTangent.xyz,
                    inTangent.w * (determinant(linear) < 0.0 ? -1.0 : 1.0));
  outUv = inUv;
  outColor = vec3(0.0);
  outSpecular = vec3(0.0);
  if (shadingModel == SHADING_GOURAUD) illuminateParts(eye.xyz, outNormal, outColor, outSpecular);
  outFlatColor = vec3(0.0);
  outFlatSpecular = vec3(0.0);
  EnvironmentDirections environment = EnvironmentDirections(vec4(0.0), vec4(0.0));
  if (environmentEnabled && shadingModel == SHADING_GOURAUD)
    environment = environmentDirections(eye.xyz, outNormal, draw.optics.z);
  outEnvReflected = environment.reflected;
  outEnvRefracted = environment.refracted;
  outFlatEnvReflected = vec4(0.0);
  outFlatEnvRefracted = vec4(0.0);
  gl_Position = frame.projection * eye;
}
