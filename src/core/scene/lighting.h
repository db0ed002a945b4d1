#pragma once
// The Phong illumination equation on the CPU, the twin of
// shaders/lighting.glsl with the same edge cases, so tests can check GPU
// pixels against it and the CPU reference tracer can light with it:
//   I = Ia ka + sum_i f_att,i Ip,i [kd (N.L_i) + ks (R_i.V)^n],  f_att = 1/(a + b d + c d^2)
// Blinn-Phong replaces (R.V)^n with (N.H)^n, H = normalize(L + V).
#include <cstdint>
#include <glm/glm.hpp>

#include "core/scene/scene.h"
#include "interface.h"

namespace shadelab {

// `frame` is what the shader sees: lights in the same space as position and
// normal, with the eye at that space's origin (V = normalize(-position)). The
// first `lightCount` lights are used (at most MAX_LIGHTS). The normal need not
// be unit length; a zero, NaN or infinite one gives ambient only.
glm::vec3 illuminate(const gpu::FrameData& frame, uint32_t lightCount, glm::vec3 position,
                     glm::vec3 normal, const Material& material, bool blinn);

// Reflection of L about unit N: R = 2 (N.L) N - L.
glm::vec3 reflectAbout(glm::vec3 towardLight, glm::vec3 normal);

}  // namespace shadelab
