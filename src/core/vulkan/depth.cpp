#include "core/vulkan/depth.h"

namespace shadelab {
namespace {

struct DepthModeInfo {
  std::string_view name;
  std::string_view formatName;
  VkFormat format;
};
constexpr DepthModeInfo kInfo[] = {
    {"d16", "D16_UNORM", VK_FORMAT_D16_UNORM},
    {"d24", "X8_D24_UNORM_PACK32", VK_FORMAT_X8_D24_UNORM_PACK32},
    {"d32f", "D32_SFLOAT", VK_FORMAT_D32_SFLOAT},
    {"reversed", "D32_SFLOAT", VK_FORMAT_D32_SFLOAT},
};

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
std::string_view depthModeName(DepthMode mode) {
  return kInfo[int(mode)].name;
}
std::string_view depthFormatName(DepthMode mode) {
  return kInfo[int(mode)].formatName;
}

std::optional<DepthMode> parseDepthMode(std::string_view name) {
  for (DepthMode mode : kDepthModes)
    if (depthModeName(mode) == name) return mode;
  return std::nullopt;
}

std::vector<std::string> depthModeNames() {
  std::vector<std::string> names;
  for (DepthMode mode : kDepthModes) names.emplace_back(depthModeName(mode));
  return names;
}

}  // namespace shadelab
