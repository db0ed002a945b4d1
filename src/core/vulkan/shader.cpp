#include "core/vulkan/shader.h"

#include <string>

#include "core/base/errors.h"
#include "core/vulkan/vk_check.h"

namespace shadelab {

ShaderModule createShaderModule(VkDevice device, std::span<const uint32_t> spirv) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = spirv.size_bytes();
  info.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  VK_CHECK(vkCreateShaderModule(device, &info, nullptr, &module));
  return ShaderModule(device, module);
}

std::span<const uint32_t> embeddedSpirv(std::string_view name) {
  for (const ShaderVariant& variant : shaderTable())
    if (variant.name == name) return variant.spirv;
  return {};
}

ShaderModule loadShader(VkDevice device, std::string_view name) {
  std::span<const uint32_t> spirv = embeddedSpirv(name);
  if (spirv.empty())
    throw VulkanError("shader '" + std::string(name) + "' was not compiled into this binary");
  return createShaderModule(device, spirv);
}

}  // namespace shadelab
