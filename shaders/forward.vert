#version 460
// Forward pass, vertex stage. Gouraud evaluates the illumination equation
// here, at each vertex with its averaged normal; the other models pass the
// eye-space position and normal on.
#extension GL_GOOGLE_include_directive : require
#include "environment.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

layout(location = 0) out vec3 outPosition;  // eye space
layout(location = 1) out vec3 outNormal;    // eye space, not normalised
layout(location = 2) out vec3 outColor;     // Gouraud: lit vertex colour
layout(location = 3) flat out vec3 outFlatColor;
// Environment directions (environment.glsl): per vertex for Gouraud, per triangle for flat.
layout(location = 8) out vec4 outEnvReflected;
layout(location = 9) out vec4 outEnvRefracted;
layout(location = 10) flat out vec4 outFlatEnvReflected;
layout(location = 11) flat out vec4 outFlatEnvRefracted;

void main() {
  ObjectData object = objects[draw.object.x];
  vec4 eye = object.modelView * vec4(inPosition, 1.0);
  outPosition = eye.xyz;
  // Normals transform by the inverse transpose of the model-view matrix.
  outNormal = mat3(object.normalMatrix) * inNormal;
  outColor = shadingModel == SHADING_GOURAUD
                 ? illuminate(eye.xyz, outNormal, drawMaterial(), false)
                 : vec3(0.0);
  outFlatColor = vec3(0.0);
  EnvironmentDirections environment = EnvironmentDirections(vec4(0.0), vec4(0.0));
  if (environmentEnabled && shadingModel == SHADING_GOURAUD)
    environment = environmentDirections(eye.xyz, outNormal, draw.optics.z);
  outEnvReflected = environment.reflected;
  outEnvRefracted = environment.refracted;
  outFlatEnvReflected = vec4(0.0);
  outFlatEnvRefracted = vec4(0.0);
  gl_Position = frame.projection * eye;
}
