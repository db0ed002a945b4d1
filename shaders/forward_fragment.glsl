// Forward pass, fragment stage (forward.frag, forward_environment.frag,
// forward_flat.frag): Phong and Blinn-Phong evaluate the equation per
// fragment with the interpolated, renormalised normal; flat and Gouraud
// output the colour computed earlier; unlit writes the diffuse colour as is.
// With an environment, every lit model adds its term (environment.glsl),
// from directions found per fragment, per vertex (Gouraud) or per triangle (flat).
// The variants differ only in their inputs (see forward_vertex.glsl for why):
// FLAT_VARYINGS: the flat geometry stage's per-triangle colour and directions;
// ENVIRONMENT_VARYINGS: Gouraud's per-vertex directions as well.
#extension GL_GOOGLE_include_directive : require
#include "environment.glsl"

#ifdef FLAT_VARYINGS
layout(location = 3) flat in vec3 inFlatColor;
layout(location = 10) flat in vec4 inFlatEnvReflected;
layout(location = 11) flat in vec4 inFlatEnvRefracted;
#else
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inColor;
#ifdef ENVIRONMENT_VARYINGS
layout(location = 8) in vec4 inEnvReflected;
layout(location = 9) in vec4 inEnvRefracted;
#endif
#endif

layout(location = 0) out vec4 outColor;

void main() {
#ifdef FLAT_VARYINGS
  vec3 color = inFlatColor;
  EnvironmentDirections environment =
      EnvironmentDirections(inFlatEnvReflected, inFlatEnvRefracted);
#else
  vec3 color;
  if (shadingModel == SHADING_GOURAUD) {
    color = inColor;
  } else if (shadingModel == SHADING_UNLIT) {
    color = draw.kd.rgb;
  } else {
    color = illuminate(inPosition, inNormal, drawMaterial(),
                       shadingModel == SHADING_BLINN_PHONG);
  }
  EnvironmentDirections environment;
#ifdef ENVIRONMENT_VARYINGS
  if (shadingModel == SHADING_GOURAUD)
    environment = EnvironmentDirections(inEnvReflected, inEnvRefracted);
  else
#endif
    environment = environmentDirections(inPosition, inNormal, draw.optics.z);
#endif
  if (environmentEnabled && shadingModel != SHADING_UNLIT)
    color += environmentColor(environment, draw.optics.x, draw.optics.y);
  // kd.w: opacity, 1 - transparency, for the blended draws. With the
  // environment term the transmitted light is env(T), so the surface is opaque.
  outColor = vec4(color, environmentEnabled ? 1.0 : draw.kd.w);
}
