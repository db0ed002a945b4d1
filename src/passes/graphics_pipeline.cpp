#include "passes/graphics_pipeline.h"

#include <algorithm>
#include <cassert>
#include <cstddef>

#include "core/vulkan/vk_check.h"

namespace shadelab {

Pipeline createGraphicsPipeline(VkDevice device, const GraphicsPipelineDesc& desc) {
  VkPipelineInputAssemblyStateCreateInfo assembly{
      VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineColorBlendStateCreateInfo blend{
      VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = 1;
  blend.pAttachments = &desc.blend;
  VkDynamicState dynamicStates[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamicStates;
  VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachmentFormats = &desc.colorFormat;
  rendering.depthAttachmentFormat = desc.depthFormat;

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO, &rendering};
  info.stageCount = uint32_t(desc.stages.size());
  info.pStages = desc.stages.data();
  info.pVertexInputState = desc.vertexInput;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = desc.raster;
  info.pMultisampleState = desc.multisample;
  info.pDepthStencilState = desc.depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = desc.layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VK_CHECK(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
  return Pipeline(device, pipeline);
}

uint32_t LightSets::intern(const LightValues& values) {
  auto found = std::find(sets_.begin(), sets_.end(), values);
  if (found == sets_.end()) found = sets_.insert(sets_.end(), values);
  return uint32_t(found - sets_.begin()) + 1;
}

const LightValues* LightSets::find(uint32_t id) const {
  assert(id <= sets_.size() && "a light set id of another table");
  return id == 0 ? nullptr : &sets_[id - 1];
}

LightSpecialization lightSpecialization(const LightLayout& layout, const LightValues* values) {
  return {
      int32_t(layout.point),    int32_t(layout.directional), layout.attenuated ? VK_TRUE : VK_FALSE,
      int32_t(layout.shadowed), values ? VK_TRUE : VK_FALSE, values ? *values : LightValues{}};
}

void appendLightEntries(std::vector<VkSpecializationMapEntry>& entries, uint32_t offset) {
  using L = LightSpecialization;
  entries.push_back({SPEC_POINT_LIGHTS, uint32_t(offset + offsetof(L, pointLights)), 4});
  entries.push_back(
      {SPEC_DIRECTIONAL_LIGHTS, uint32_t(offset + offsetof(L, directionalLights)), 4});
  entries.push_back({SPEC_ATTENUATED_POINT_LIGHTS, uint32_t(offset + offsetof(L, attenuated)), 4});
  entries.push_back({SPEC_SHADOWED_LIGHTS, uint32_t(offset + offsetof(L, shadowedLights)), 4});
  entries.push_back({SPEC_LIGHT_CONSTANTS, uint32_t(offset + offsetof(L, compiled)), 4});
  for (uint32_t i = 0; i < LIGHT_VALUE_WORDS; ++i)
    entries.push_back({SPEC_LIGHT_VALUES + i, uint32_t(offset + offsetof(L, values) + 4 * i), 4});
}

}  // namespace shadelab
