// Forward pass, fragment stage of the textured variants (forward_textured.frag,
// forward_textured_gouraud.frag, forward_textured_gouraud_environment.frag,
// forward_textured_flat.frag). The diffuse texel multiplies ka and kd in every
// model. Bump mapping needs the equation per fragment, so only Phong and
// Blinn-Phong apply normal and height maps; flat and Gouraud light with the
// geometric / vertex normals and ignore them. The environment term is added
// as in forward_fragment.glsl; Phong and Blinn-Phong reflect and refract
// about the bumped normal. Inputs per variant as in forward_fragment.glsl.
#extension GL_GOOGLE_include_directive : require
#include "bump.glsl"
#include "environment.glsl"

layout(location = 4) in vec2 inUv;
#if defined(FLAT_VARYINGS)
layout(location = 3) flat in vec3 inFlatColor;
layout(location = 7) flat in vec3 inFlatSpecular;
layout(location = 10) flat in vec4 inFlatEnvReflected;
layout(location = 11) flat in vec4 inFlatEnvRefracted;
#elif defined(VERTEX_LIGHTING)
layout(location = 2) in vec3 inColor;
layout(location = 6) in vec3 inSpecular;
#ifdef ENVIRONMENT_VARYINGS
layout(location = 8) in vec4 inEnvReflected;
layout(location = 9) in vec4 inEnvRefracted;
#endif
#else
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 5) in vec4 inTangent;
#endif

layout(location = 0) out vec4 outColor;

void main() {
  vec2 st = textureCoordinate(inUv);
  vec3 texel = diffuseTexel(st);
#if defined(FLAT_VARYINGS)
  vec3 color = texel * inFlatColor + inFlatSpecular;
  EnvironmentDirections environment =
      EnvironmentDirections(inFlatEnvReflected, inFlatEnvRefracted);
#elif defined(VERTEX_LIGHTING)
  vec3 color = texel * inColor + inSpecular;
#ifdef ENVIRONMENT_VARYINGS
  EnvironmentDirections environment = EnvironmentDirections(inEnvReflected, inEnvRefracted);
#else
  EnvironmentDirections environment = EnvironmentDirections(vec4(0.0), vec4(0.0));
#endif
#else
  vec3 color;
  vec3 normal = inNormal;
  if (shadingModel == SHADING_UNLIT) {
    color = texel * draw.kd.rgb;
  } else {
    SurfaceMaterial material = drawMaterial();
    material.ka *= texel;
    material.kd *= texel;
    normal = bumpedNormal(inNormal, inTangent, st);
    color = illuminate(inPosition, normal, material, shadingModel == SHADING_BLINN_PHONG);
  }
  EnvironmentDirections environment = environmentDirections(inPosition, normal, draw.optics.z);
#endif
  if (environmentEnabled && shadingModel != SHADING_UNLIT)
    color += environmentColor(environment, draw.optics.x, draw.optics.y);
  // kd.w: opacity, 1 - transparency; opaque with the environment term (forward_fragment.glsl).
  outColor = vec4(color, environmentEnabled ? 1.0 : draw.kd.w);
}
