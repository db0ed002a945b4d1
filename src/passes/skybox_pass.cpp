#include "passes/skybox_pass.h"

#include <cassert>

#include "core/vulkan/depth.h"
#include "core/vulkan/shader.h"
#include "core/vulkan/vk_check.h"
#include "interface.h"
#include "passes/graphics_pipeline.h"

namespace shadelab {

SkyboxPass::SkyboxPass(const Context& context, VkFormat colorFormat,
                       VkDescriptorSetLayout frameSetLayout)
    : context_(context), colorFormat_(colorFormat) {
  VkDevice device = context.device();
  VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                           sizeof(gpu::SkyboxConstants)};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &frameSetLayout;
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &push;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout));
  layout_ = PipelineLayout(device, layout);
  vertex_ = loadShader(device, "skybox.vert");
  fragment_ = loadShader(device, "skybox.frag");
}

void SkyboxPass::prepare(TargetLayout target) {
  if (!pipelines_.count(target)) pipelines_[target] = createPipeline(target);
}

Pipeline SkyboxPass::createPipeline(TargetLayout target) const {
  VkPipelineShaderStageCreateInfo stages[2] = {
      {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
      {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vertex_;
  stages[0].pName = "main";
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = fragment_;
  stages[1].pName = "main";
  VkPipelineVertexInputStateCreateInfo vertexInput{
      VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  VkPipelineRasterizationStateCreateInfo raster{
      VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{
      VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VkSampleCountFlagBits(target.samples);
  // Exactly the cleared value: the triangle's depth is that constant.
  VkPipelineDepthStencilStateCreateInfo depth{
      VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = VK_FALSE;
  depth.depthCompareOp = VK_COMPARE_OP_EQUAL;
  VkPipelineColorBlendAttachmentState blendAttachment{};
  blendAttachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                   VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  return createGraphicsPipeline(
      context_.device(), {stages, &vertexInput, &raster, &multisample, &depth, blendAttachment,
                          colorFormat_, depthFormat(target.depth), layout_});
}

void SkyboxPass::record(VkCommandBuffer cmd, TargetLayout target, VkDescriptorSet frameSet,
                        const glm::mat4& view, const glm::mat4& projection,
                        const VkViewport& viewport) const {
  auto pipeline = pipelines_.find(target);
  assert(pipeline != pipelines_.end() && "SkyboxPass::prepare() not called for this target");
  VkRect2D scissor{{int32_t(viewport.x), int32_t(viewport.y)},
                   {uint32_t(viewport.width), uint32_t(viewport.height)}};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline->second);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &frameSet, 0,
                          nullptr);
  gpu::SkyboxConstants constants{};
  // Without the translation the camera sits at the origin: the environment is at infinity.
  constants.clipToWorld = glm::inverse(projection * glm::mat4(glm::mat3(view)));
  float nearDepth = isReversedZ(target.depth) ? 1.0f : 0.0f;
  constants.depth = glm::vec4(depthClearValue(target.depth), nearDepth, 0.0f, 0.0f);
  vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                     sizeof(constants), &constants);
  vkCmdDraw(cmd, 3, 1, 0, 0);
}

}  // namespace shadelab
