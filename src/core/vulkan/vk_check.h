#pragma once
#include <vulkan/vulkan.h>

namespace shadelab {

const char* vkResultName(VkResult result);
// Throws VulkanError naming the call, the VkResult, the file and the line.
void vkCheckFailed(VkResult result, const char* call, const char* file, int line);

}  // namespace shadelab

#define VK_CHECK(call)                                                        \
  do {                                                                        \
    VkResult vk_check_result_ = (call);                                       \
    if (vk_check_result_ != VK_SUCCESS)                                       \
      ::shadelab::vkCheckFailed(vk_check_result_, #call, __FILE__, __LINE__); \
  } while (0)
