#include "core/vulkan/depth.h"

namespace shadelab {
namespace {

// Indexed by DepthMode, in kDepthModeNames' order.
struct DepthModeInfo {
  std::string_view formatName;
  VkFormat format;
};
constexpr DepthModeInfo kInfo[] = {
    {"D16_UNORM", VK_FORMAT_D16_UNORM},
    {"X8_D24_UNORM_PACK32", VK_FORMAT_X8_D24_UNORM_PACK32},
    {"D32_SFLOAT", VK_FORMAT_D32_SFLOAT},
    {"D32_SFLOAT", VK_FORMAT_D32_SFLOAT},
};
static_assert(std::size(kInfo) == kDepthModeNames.size());

}  // namespace

VkFormat depthFormat(DepthMode mode) {
  return kInfo[int(mode)].format;
}
bool isReversedZ(DepthMode mode) {
  return mode == DepthMode::ReversedZ;
}
float depthClearValue(DepthMode mode) {
  return isReversedZ(mode) ? 0.0f : 1.0f;
}
VkCompareOp depthCompareOp(DepthMode mode) {
  return isReversedZ(mode) ? VK_COMPARE_OP_GREATER_OR_EQUAL : VK_COMPARE_OP_LESS;
}
std::string_view depthFormatName(DepthMode mode) {
  return kInfo[int(mode)].formatName;
}

}  // namespace shadelab
