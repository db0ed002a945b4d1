#version 460
// Shadow pass, translucent casters: what one crossing of the surface passes,
// kt (1 - F) with F Schlick's reflectance for light arriving from air at the
// ray's angle to the surface, or kt alone for a coverage material (glTF
// BLEND). The tracer's shadow rays weigh each crossing the same way
// (RayTracer::transmittance). The attachment multiplies it in (blend: dst *
// src), so the texel ends as the product over every crossing.
#extension GL_GOOGLE_include_directive : require
#include "interface.h"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) flat in vec4 inOptics;  // kt, ior, 1: Fresnel, 1: point light
layout(location = 0) out vec4 outTransmittance;

void main() {
  float kt = inOptics.x, ior = inOptics.y;
  float passed = kt;
  if (inOptics.z > 0.5) {
    // The ray from a point light runs along the position; a directional
    // light's along z.
    vec3 ray = inOptics.w > 0.5 ? inPosition : vec3(0.0, 0.0, 1.0);
    float lengths = length(ray) * length(inNormal);
    float cosine = lengths > 0.0 ? clamp(abs(dot(ray, inNormal)) / lengths, 0.0, 1.0) : 1.0;
    // Into a thinner medium (ior < 1) Schlick takes the transmitted angle's
    // cosine, and past the critical angle everything is reflected
    // (schlickFresnel in core/trace/optics.cpp, from air: n1 = 1, n2 = ior).
    bool thinner = ior < 1.0;
    float eta = 1.0 / ior;
    float radicand = 1.0 - eta * eta * (1.0 - cosine * cosine);
    if (thinner) cosine = sqrt(max(radicand, 0.0));
    float f0 = (1.0 - ior) / (1.0 + ior);
    f0 *= f0;
    float reflected =
        thinner && radicand < 0.0 ? 1.0 : f0 + (1.0 - f0) * pow(1.0 - cosine, 5.0);
    passed *= 1.0 - reflected;
  }
  outTransmittance = vec4(passed);
}
