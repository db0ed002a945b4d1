#pragma once
// Total internal reflection measured: a ray inside glass (index `ior`)
// meets a flat surface at an angle; the light the tracer refracts out
// reaches a red emitter above, the light it reflects a green emitter below.
// So the traced colour is (transmitted, reflected) and their sum is the
// energy kept. The CPU tracer alone, no device.
#include <cstdint>

#include "core/base/image.h"
#include "core/scene/scene.h"

namespace shadelab {

// The glass surface y = 0 (seen from below: leaving glass into air), a red
// emitter at y = 1 and a green one at y = -2, black elsewhere.
Scene tirScene(float ior);

struct TirSample {
  float ior = 1.5f;
  double angleDegrees = 0.0;  // from the normal, inside the glass
  double transmitted = 0.0;   // the red emitter's share
  double reflected = 0.0;     // the green emitter's share
  bool totalInternalReflection = false;
};

TirSample measureInterface(float ior, double angleDegrees);
// The smallest angle at which the tracer reflects totally, by bisection to
// 1e-6 degrees; the formula's is asin(1 / ior).
double tracedCriticalAngle(float ior);

// Fresnel reflectance leaving a medium of index n into air at angle theta
// inside: Schlick's (what the tracer uses, cos on the air side) and the
// exact unpolarised one; both 1 past the critical angle.
double schlickReflectance(double ior, double angleDegrees);
double exactReflectance(double ior, double angleDegrees);

// Looking up from inside the glass with a wide lens: Snell's window, the
// red disc of light refracted in within the critical angle, green beyond.
ImageRgba snellsWindow(float ior, uint32_t width, uint32_t height);

}  // namespace shadelab
