// Forward pass, vertex stage (forward.vert, forward_environment.vert).
// Gouraud evaluates the illumination equation here, at each vertex with its
// averaged normal; the other models pass the eye-space position and normal on.
// ENVIRONMENT_VARYINGS adds Gouraud's per-vertex environment directions.
// Each variant declares only the outputs its fragment stage reads: lavapipe
// sets up and interpolates every output, and the unused flat and environment
// ones made the 800x600 Gouraud frame 1.39x glmark2's instead of 1.00x
// (scripts/peer_bench.sh, docs/PERFORMANCE.md).
#extension GL_GOOGLE_include_directive : require
#include "environment.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

layout(location = 0) out vec3 outPosition;  // eye space
layout(location = 1) out vec3 outNormal;    // eye space, not normalised
layout(location = 2) out vec3 outColor;     // Gouraud: lit vertex colour
#ifdef ENVIRONMENT_VARYINGS
layout(location = 8) out vec4 outEnvReflected;  // environment.glsl's directions
layout(location = 9) out vec4 outEnvRefracted;
#endif

void main() {
  ObjectData object = objects[draw.object.x];
  vec4 eye = object.modelView * vec4(inPosition, 1.0);
  outPosition = eye.xyz;
  // Normals transform by the inverse transpose of the model-view matrix.
  outNormal = mat3(object.normalMatrix) * inNormal;
  outColor = shadingModel == SHADING_GOURAUD
                 ? illuminate(eye.xyz, outNormal, drawMaterial(), false)
                 : vec3(0.0);
#ifdef ENVIRONMENT_VARYINGS
  EnvironmentDirections environment = EnvironmentDirections(vec4(0.0), vec4(0.0));
  if (environmentEnabled && shadingModel == SHADING_GOURAUD)
    environment = environmentDirections(eye.xyz, outNormal, draw.optics.z);
  outEnvReflected = environment.reflected;
  outEnvRefracted = environment.refracted;
#endif
  gl_Position = frame.projection * eye;
}
