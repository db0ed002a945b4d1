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
#endif
