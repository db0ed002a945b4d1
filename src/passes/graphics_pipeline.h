#pragma once
// What every graphics pipeline of the passes shares: a triangle list, one
// viewport and scissor set per draw (dynamic), one colour attachment and a
// depth attachment through dynamic rendering. A pass fills in the states that
// make it what it is.
#include <vulkan/vulkan.h>

#include <span>

#include "core/vulkan/resources.h"

namespace shadelab {

struct GraphicsPipelineDesc {
  std::span<const VkPipelineShaderStageCreateInfo> stages;
  const VkPipelineVertexInputStateCreateInfo* vertexInput = nullptr;
  const VkPipelineRasterizationStateCreateInfo* raster = nullptr;
  const VkPipelineMultisampleStateCreateInfo* multisample = nullptr;
  const VkPipelineDepthStencilStateCreateInfo* depth = nullptr;
  VkPipelineColorBlendAttachmentState blend{};  // of the one colour attachment
  VkFormat colorFormat = VK_FORMAT_UNDEFINED;
  VkFormat depthFormat = VK_FORMAT_UNDEFINED;
  VkPipelineLayout layout = VK_NULL_HANDLE;
};

Pipeline createGraphicsPipeline(VkDevice device, const GraphicsPipelineDesc& desc);

}  // namespace shadelab
