// Descriptor bindings and per-draw data shared by the forward shaders.
#ifndef COMMON_GLSL
#define COMMON_GLSL
#include "interface.h"

layout(set = 0, binding = BINDING_FRAME, std140) uniform FrameBlock { FrameData frame; };
layout(set = 0, binding = BINDING_OBJECTS, std430) readonly buffer ObjectBlock { ObjectData objects[]; };
layout(push_constant) uniform DrawBlock { DrawConstants draw; };
layout(constant_id = SPEC_SHADING_MODEL) const int shadingModel = SHADING_PHONG;
layout(constant_id = SPEC_POINT_LIGHTS) const int pointLightCount = 1;
layout(constant_id = SPEC_DIRECTIONAL_LIGHTS) const int directionalLightCount = 0;
// False when every point light has attenuation (1, 0, 0), so f_att = 1 needs no division.
layout(constant_id = SPEC_ATTENUATED_POINT_LIGHTS) const bool pointLightsAttenuate = true;
layout(constant_id = SPEC_ALPHA_MASK) const bool alphaMask = false;
layout(constant_id = SPEC_DOUBLE_SIDED) const bool doubleSided = false;
layout(constant_id = SPEC_MATERIAL_CONSTANTS) const bool materialConstants = false;
layout(constant_id = SPEC_MATERIAL_KA) const float materialKaR = 0.0;
layout(constant_id = SPEC_MATERIAL_KA + 1) const float materialKaG = 0.0;
layout(constant_id = SPEC_MATERIAL_KA + 2) const float materialKaB = 0.0;
layout(constant_id = SPEC_MATERIAL_KD) const float materialKdR = 0.0;
layout(constant_id = SPEC_MATERIAL_KD + 1) const float materialKdG = 0.0;
layout(constant_id = SPEC_MATERIAL_KD + 2) const float materialKdB = 0.0;
layout(constant_id = SPEC_MATERIAL_KS) const float materialKsR = 0.0;
layout(constant_id = SPEC_MATERIAL_KS + 1) const float materialKsG = 0.0;
layout(constant_id = SPEC_MATERIAL_KS + 2) const float materialKsB = 0.0;
layout(constant_id = SPEC_MATERIAL_SHININESS) const float materialShininess = 0.0;
layout(constant_id = SPEC_MATERIAL_EMISSIVE) const uint materialEmissive = 0u;

layout(constant_id = SPEC_LIGHT_CONSTANTS) const bool lightConstants = false;
layout(constant_id = SPEC_LIGHT_VALUES) const float ambientR = 0.0;
layout(constant_id = SPEC_LIGHT_VALUES + 1) const float ambientG = 0.0;
layout(constant_id = SPEC_LIGHT_VALUES + 2) const float ambientB = 0.0;
// Light i's nine constants (interface.h: SPEC_LIGHT_VALUES).
#define LIGHT_CONSTANTS(i)                                                              \
  layout(constant_id = SPEC_LIGHT_VALUES + 3 + 9 * i) const float light##i##X = 0.0;     \
  layout(constant_id = SPEC_LIGHT_VALUES + 4 + 9 * i) const float light##i##Y = 0.0;     \
  layout(constant_id = SPEC_LIGHT_VALUES + 5 + 9 * i) const float light##i##Z = 0.0;     \
  layout(constant_id = SPEC_LIGHT_VALUES + 6 + 9 * i) const float light##i##R = 0.0;     \
  layout(constant_id = SPEC_LIGHT_VALUES + 7 + 9 * i) const float light##i##G = 0.0;     \
  layout(constant_id = SPEC_LIGHT_VALUES + 8 + 9 * i) const float light##i##B = 0.0;     \
  layout(constant_id = SPEC_LIGHT_VALUES + 9 + 9 * i) const float light##i##A = 0.0;     \
  layout(constant_id = SPEC_LIGHT_VALUES + 10 + 9 * i) const float light##i##Linear = 0.0; \
  layout(constant_id = SPEC_LIGHT_VALUES + 11 + 9 * i) const float light##i##Quadratic = 0.0;
LIGHT_CONSTANTS(0) LIGHT_CONSTANTS(1) LIGHT_CONSTANTS(2) LIGHT_CONSTANTS(3)
LIGHT_CONSTANTS(4) LIGHT_CONSTANTS(5) LIGHT_CONSTANTS(6) LIGHT_CONSTANTS(7)
#undef LIGHT_CONSTANTS

vec3 frameAmbient() {
  return lightConstants ? vec3(ambientR, ambientG, ambientB) : frame.ambient.rgb;
}

// FrameData::lights[i], or its compiled-in copy. The callers' loops run to
// the constant light counts and unroll, so i is a constant and the chain
// folds to one light's values.
GpuLight frameLight(int i) {
  if (!lightConstants) return frame.lights[i];
#define COMPILED_LIGHT(n)                                                                      \
  if (i == n)                                                                                 \
    return GpuLight(vec4(light##n##X, light##n##Y, light##n##Z, 0.0),                         \
                    vec4(light##n##R, light##n##G, light##n##B, 0.0),                         \
                    vec4(light##n##A, light##n##Linear, light##n##Quadratic, 0.0));
  COMPILED_LIGHT(0) COMPILED_LIGHT(1) COMPILED_LIGHT(2) COMPILED_LIGHT(3)
  COMPILED_LIGHT(4) COMPILED_LIGHT(5) COMPILED_LIGHT(6)
#undef COMPILED_LIGHT
  return GpuLight(vec4(light7X, light7Y, light7Z, 0.0), vec4(light7R, light7G, light7B, 0.0),
                  vec4(light7A, light7Linear, light7Quadratic, 0.0));
}
#endif
