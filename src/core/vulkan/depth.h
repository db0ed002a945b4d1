#pragma once
// Depth-buffer modes: the format of the z-buffer and, for reversed-Z, the
// projection that maps near to 1 and far to 0 with the compare op and clear
// value that go with it. Reversed-Z pairs with a float format because float
// spacing is finest near 0, which then falls on the distant geometry that
// 1/z depth squeezes together.
#include <vulkan/vulkan.h>

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

}  // namespace shadelab
