#pragma once
// The Phong illumination equation on the CPU, the twin of
// shaders/lighting.glsl with the same edge cases, so tests can check GPU
// pixels against it and the CPU reference tracer can light with it:
//   I = Ia ka + sum_i k_shadow,i f_att,i Ip,i [kd (N.L_i) + ks (R_i.V)^n],  f_att = 1/(a + b d + c
//   d^2)
// Blinn-Phong replaces (R.V)^n with (N.H)^n, H = normalize(L + V).
#include <glm/glm.hpp>
#include <span>

#include "core/scene/scene.h"

namespace shadelab {

// `lights` are in the same space as position and normal, with the viewer at
// that space's origin (V = normalize(-position)), as lightInView gives them;
// each lights by its type, in any order, all of them (the GPU's MAX_LIGHTS
// limit is the caller's business). A directional light's direction need not
// be unit length. The normal need not be unit length either; a zero, NaN or
// infinite one gives ambient only. `shadowCoefficients`: k_shadow per light
// (0..1, parallel to `lights`), scaling its whole term,
//   I = Ia ka + sum_i k_shadow,i f_att,i Ip,i [...];
// empty means every light reaches the point (k_shadow = 1).
glm::vec3 illuminate(glm::vec3 ambient, std::span<const Light> lights, glm::vec3 position,
                     glm::vec3 normal, const Material& material, bool blinn,
                     std::span<const float> shadowCoefficients = {});

// A world-space light as seen from `view` (a rigid transform): a point
// light's position moved, a directional light's direction turned and made
// unit length (a zero direction stays zero: it lights nothing). The space
// the shaders light in, and what illuminate() takes with eye-space points.
Light lightInView(const Light& light, const glm::mat4& view);

// Reflection of L about unit N: R = 2 (N.L) N - L.
glm::vec3 reflectAbout(glm::vec3 towardLight, glm::vec3 normal);

}  // namespace shadelab
