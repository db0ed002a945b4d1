// Descriptor bindings and per-draw data shared by the forward shaders.
#ifndef COMMON_GLSL
#define COMMON_GLSL
#include "interface.h"

layout(set = 0, binding = BINDING_FRAME, std140) uniform FrameBlock { FrameData frame; };
layout(set = 0, binding = BINDING_OBJECTS, std430) readonly buffer ObjectBlock { ObjectData objects[]; };
layout(push_constant) uniform DrawBlock { DrawConstants draw; };
layout(constant_id = SPEC_SHADING_MODEL) const int shadingModel = SHADING_PHONG;
layout(constant_id = SPEC_LIGHT_COUNT) const int lightCount = 1;
#endif
