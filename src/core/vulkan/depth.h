#pragma once
// Depth-buffer modes: the format of the z-buffer and, for reversed-Z, the
// projection that maps near to 1 and far to 0 with the compare op and clear
// value that go with it. Reversed-Z pairs with a float format because float
// spacing is finest near 0, which then falls on the distant geometry that
// 1/z depth squeezes together.
#include <vulkan/vulkan.h>

#include <optional>
#include <string>
#include <string_view>

#include "core/base/names.h"

namespace shadelab {

enum class DepthMode { D16, D24, D32F, ReversedZ };
inline constexpr NameTable<DepthMode, 4> kDepthModeNames = {{{DepthMode::D16, "d16"},
                                                             {DepthMode::D24, "d24"},
                                                             {DepthMode::D32F, "d32f"},
                                                             {DepthMode::ReversedZ, "reversed"}}};

VkFormat depthFormat(DepthMode mode);  // D16_UNORM, X8_D24_UNORM_PACK32, D32_SFLOAT, D32_SFLOAT
bool isReversedZ(DepthMode mode);
float depthClearValue(DepthMode mode);       // the far plane: 1, or 0 reversed
VkCompareOp depthCompareOp(DepthMode mode);  // LESS, or GREATER_OR_EQUAL reversed
inline std::string_view depthModeName(DepthMode mode) {
  return nameOf(kDepthModeNames, mode);
}
std::string_view depthFormatName(DepthMode mode);  // "D16_UNORM", ...

struct Camera;  // core/scene/scene.h

// The smallest difference of distance along the line of sight that `mode`
// tells apart `distance` in front of `camera`: one step of the format at the
// depth value there (a unit of the last place for float, 1 / (2^bits - 1)
// for UNORM) over the rate at which the projection's depth changes with
// distance. Infinite where the depth value rounds to the clear value, so
// that surfaces there fail the depth test and are not drawn at all.
double depthResolution(const Camera& camera, DepthMode mode, double distance);

// What a user should know before drawing with `mode`, if anything: at the
// camera's target or at `farthest` (the distance of the scene's farthest
// point along the line of sight), surfaces are not drawn, or depths 1% of
// the distance apart are not told apart. Names the mode, near and far, the
// distance and the fixes (a larger near plane or reversed-Z in perspective;
// a nearer far plane for orthographic or reversed-Z).
std::optional<std::string> depthPrecisionWarning(const Camera& camera, DepthMode mode,
                                                 double farthest);

}  // namespace shadelab
