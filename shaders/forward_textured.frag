#version 460
// Forward pass, fragment stage of the textured variants. The diffuse texel
// multiplies ka and kd in every model. Bump mapping needs the equation per
// fragment, so only Phong and Blinn-Phong apply normal and height maps; flat
// and Gouraud light with the geometric / vertex normals and ignore them.
// The environment term is added as in forward.frag; Phong and Blinn-Phong
// reflect and refract about the bumped normal.
#extension GL_GOOGLE_include_directive : require
#include "bump.glsl"
#include "environment.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inColor;
layout(location = 3) flat in vec3 inFlatColor;
layout(location = 4) in vec2 inUv;
layout(location = 5) in vec4 inTangent;
layout(location = 6) in vec3 inSpecular;
layout(location = 7) flat in vec3 inFlatSpecular;
layout(location = 8) in vec4 inEnvReflected;
layout(location = 9) in vec4 inEnvRefracted;
layout(location = 10) flat in vec4 inFlatEnvReflected;
layout(location = 11) flat in vec4 inFlatEnvRefracted;

layout(location = 0) out vec4 outColor;

void main() {
  vec2 st = textureCoordinate(inUv);
  vec3 texel = diffuseTexel(st);
  vec3 color;
  vec3 normal = inNormal;
  if (shadingModel == SHADING_FLAT) {
    color = texel * inFlatColor + inFlatSpecular;
  } else if (shadingModel == SHADING_GOURAUD) {
    color = texel * inColor + inSpecular;
  } else if (shadingModel == SHADING_UNLIT) {
    color = texel * draw.kd.rgb;
  } else {
    SurfaceMaterial material = drawMaterial();
    material.ka *= texel;
    material.kd *= texel;
    normal = bumpedNormal(inNormal, inTangent, st);
    color = illuminate(inPosition, normal, material, shadingModel == SHADING_BLINN_PHONG);
  }
  if (environmentEnabled && shadingModel != SHADING_UNLIT) {
    EnvironmentDirections environment;
    if (shadingModel == SHADING_FLAT)
      environment = EnvironmentDirections(inFlatEnvReflected, inFlatEnvRefracted);
    else if (shadingModel == SHADING_GOURAUD)
      environment = EnvironmentDirections(inEnvReflected, inEnvRefracted);
    else
      environment = environmentDirections(inPosition, normal, draw.optics.z);
    color += environmentColor(environment, draw.optics.x, draw.optics.y);
  }
  // kd.w: opacity, 1 - transparency; opaque with the environment term (forward.frag).
  outColor = vec4(color, environmentEnabled ? 1.0 : draw.kd.w);
}
