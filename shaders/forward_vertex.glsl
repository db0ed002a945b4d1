// Forward pass, vertex stage (forward.vert, forward_gouraud.vert,
// forward_gouraud_environment.vert). Gouraud (VERTEX_LIGHTING) evaluates the
// illumination equation here, at each vertex with its averaged normal, and
// with ENVIRONMENT_VARYINGS its environment directions too; the other models
// pass the eye-space position and normal on.
// Each variant declares only the outputs its fragment stage reads: lavapipe
// sets up and interpolates every output, and the unused ones made the 800x600
// Gouraud frame 1.36x glmark2's (scripts/peer_bench.sh, docs/PERFORMANCE.md).
#extension GL_GOOGLE_include_directive : require
#include "environment.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

#ifdef VERTEX_LIGHTING
layout(location = 2) out vec3 outColor;  // the lit vertex colour
#ifdef ENVIRONMENT_VARYINGS
layout(location = 8) out vec4 outEnvReflected;  // environment.glsl's directions
layout(location = 9) out vec4 outEnvRefracted;
#endif
#else
layout(location = 0) out vec3 outPosition;  // eye space
layout(location = 1) out vec3 outNormal;    // eye space, not normalised
#endif

void main() {
  ObjectData object = objects[draw.object.x];
  vec4 eye = object.modelView * vec4(inPosition, 1.0);
  // Normals transform by the inverse transpose of the model-view matrix.
  vec3 normal = mat3(object.normalMatrix) * inNormal;
#ifdef VERTEX_LIGHTING
  outColor = illuminate(eye.xyz, normal, drawMaterial(), false);
#ifdef ENVIRONMENT_VARYINGS
  EnvironmentDirections environment = environmentDirections(eye.xyz, normal, draw.optics.z);
  outEnvReflected = environment.reflected;
  outEnvRefracted = environment.refracted;
#endif
#else
  outPosition = eye.xyz;
  outNormal = normal;
#endif
  gl_Position = frame.projection * eye;
}
