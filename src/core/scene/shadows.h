#pragma once
// Shadow maps, the parts without Vulkan: the filtering methods (a name
// table), the bias, and the light's view-projection matrices, fitted to what
// the camera sees. The shadow pass (passes/shadow_pass) draws depth with these
// matrices; shaders/shadows.glsl looks the maps up with the same numbers.
#include <array>
#include <glm/glm.hpp>
#include <vector>

#include "core/base/names.h"
#include "core/scene/mesh.h"
#include "core/scene/scene.h"
#include "interface.h"

namespace shadelab {

// How the shadow map is filtered: the SPEC_SHADOW_FILTER constant. Off draws
// no map and lights every point by every light (the images of before shadows).
enum class ShadowMethod : int {
  Off = SHADOW_OFF,
  Hard = SHADOW_HARD,  // one tap of the compare sampler: lit or not
  Pcf3 = SHADOW_PCF3,  // percentage-closer filtering, 3x3 taps one texel apart
  Pcf5 = SHADOW_PCF5,  // 5x5 taps
};
inline constexpr NameTable<ShadowMethod, 4> kShadowMethodNames = {{{ShadowMethod::Off, "off"},
                                                                   {ShadowMethod::Hard, "hard"},
                                                                   {ShadowMethod::Pcf3, "pcf3"},
                                                                   {ShadowMethod::Pcf5, "pcf5"}}};

// SPEC_SHADOW_FILTER's value: the filter, with SHADOW_TRANSLUCENT when the
// maps have translucent layers to read (passes/shadow_pass.h).
inline int32_t shadowSpecialization(ShadowMethod method, bool translucent) {
  return int32_t(method) | (translucent && method != ShadowMethod::Off ? SHADOW_TRANSLUCENT : 0);
}

// Bias against self-shadowing ("acne"), all in shadow-map texels (the world
// size of one texel where the point is), so one setting suits every map size
// and scene scale. The receiver is moved before the lookup by
//   constant * texel + slope * tan(theta) * texel  towards the light, and
//   normalOffset * sin(theta) * texel              along its normal,
// theta the angle between N and L (tan clamped at kMaxSlopeTangent).
struct ShadowBias {
  float constant = 0.5f;
  float slope = 1.0f;
  float normalOffset = 1.0f;
  bool operator==(const ShadowBias&) const = default;
};
inline constexpr float kMaxShadowBias = 64.0f;  // texels: options and scene files accept 0..this
inline constexpr float kMaxSlopeTangent = 10.0f;

// 768, chosen by measurement: the lookup's memory traffic grows with the
// map on llvmpipe, and on `default` at 1280x720 hard 768 costs 1.39-1.44x
// the frame without shadows (median of 5 runs 1.43x) where 1024 cost
// 1.37-1.53x (median 1.49x; issue 15's budget is 1.5x), while the mean
// FLIP against the traced reference at 640x360 is within 0.0001 of 1024's
// and 0.0004 of 2048's (docs/PERFORMANCE.md, "Shadow lookups"; README.md,
// "Shadow maps").
inline constexpr uint32_t kDefaultShadowMapSize = 768;
// The largest map size a request may ask for (the device may allow less:
// 16384 on lavapipe).
inline constexpr uint32_t kMaxShadowMapSize = 65536;
// What the command line and the viewer draw unless told otherwise (the
// library's FrameSettings default stays Off). Chosen by measurement
// (README.md, "Shadows"): against the traced reference, whose shadows are
// hard, one tap is both the cheapest and the closest of the filters.
inline constexpr ShadowMethod kDefaultShadowMethod = ShadowMethod::Hard;

// The light's view-projection matrices, world space to Vulkan clip space:
// one for a directional light, six (+x, -x, +y, -y, +z, -z) for a point light.
struct ShadowView {
  std::vector<glm::mat4> viewProjection;
  // World size of one texel: at the map (directional) or per unit of
  // distance from the light (point: multiply by the distance).
  float texelSize = 0.0f;
  // Point light: its faces' projection as gpu::ShadowData::cube holds it
  // (depth = x - y / major axis, face xy = z * (right, up) / major axis),
  // what cubeFaceCoordinates() computes; zero for a directional light.
  glm::vec4 cube{0.0f};
};

// Directional light: an orthographic box along the light whose sides are
// the scene's bounds intersected with the camera's view frustum (as the light
// sees them), so the map's texels cover only what the camera can see; its
// depth range spans the whole scene, so every caster between the light and a
// seen receiver is inside. `cameraViewProjection` is world to clip space.
ShadowView directionalShadowView(const Light& light, const Bounds& sceneBounds,
                                 const glm::mat4& cameraViewProjection, uint32_t mapSize);

// A point light's cube faces start this far from the light (or at a tenth
// of the far distance, if nearer): casters closer are flattened onto it.
inline constexpr float kPointShadowNear = 0.05f;
// Point light: six 90-degree perspective faces, widened by `marginTexels` on
// each side so filter taps near a face's edge stay inside the face; far plane
// at the farthest corner of the scene's bounds.
ShadowView pointShadowView(const Light& light, const Bounds& sceneBounds, uint32_t mapSize,
                           float marginTexels);

// Which cube face a point light's map uses for the direction from the light
// to a point: the major axis (+x, -x, +y, -y, +z, -z = 0..5). The GLSL twin is
// cubeFace() in shaders/shadows.glsl.
int cubeFace(glm::vec3 fromLight);

// Where a point light's map holds the direction `fromLight` (world space):
// its face, that face's clip xy (-1..1) and depth (0..1), the same numbers
// as viewProjection[face] gives, found without the matrix. `cube` is
// ShadowView::cube. The GLSL twin is in shaders/shadows.glsl.
struct CubeMapPoint {
  int face = 0;
  glm::vec3 ndc{0.0f};
};
CubeMapPoint cubeFaceCoordinates(glm::vec3 fromLight, glm::vec4 cube);

}  // namespace shadelab
