#include "passes/compute_kernel.h"

#include <map>

#include "core/vulkan/shader.h"
#include "core/vulkan/vk_check.h"

namespace shadelab {

ComputeKernel::ComputeKernel(const Context& context, std::string_view shader,
                             const std::vector<VkDescriptorSetLayoutBinding>& bindings,
                             uint32_t pushSize)
    : context_(context), pushSize_(pushSize) {
  VkDevice device = context.device();
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.bindingCount = uint32_t(bindings.size());
  setInfo.pBindings = bindings.data();
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &setLayout));
  setLayout_ = DescriptorSetLayout(device, setLayout);

  VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushSize};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &setLayout;
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &push;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout));
  layout_ = PipelineLayout(device, layout);

  shader_ = loadShader(device, shader);
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = shader_;
  info.stage.pName = "main";
  info.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VK_CHECK(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
  pipeline_ = Pipeline(device, pipeline);

  std::map<VkDescriptorType, uint32_t> counts;
  for (const VkDescriptorSetLayoutBinding& binding : bindings)
    counts[binding.descriptorType] += binding.descriptorCount;
  std::vector<VkDescriptorPoolSize> sizes;
  for (auto [type, count] : counts) sizes.push_back({type, count});
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = 1;
  poolInfo.poolSizeCount = uint32_t(sizes.size());
  poolInfo.pPoolSizes = sizes.data();
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorPool(device, &poolInfo, nullptr, &pool));
  pool_ = DescriptorPool(device, pool);
  VkDescriptorSetAllocateInfo allocInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  allocInfo.descriptorPool = pool;
  allocInfo.descriptorSetCount = 1;
  allocInfo.pSetLayouts = &setLayout;
  VK_CHECK(vkAllocateDescriptorSets(device, &allocInfo, &set_));
}

void ComputeKernel::update(const std::vector<VkWriteDescriptorSet>& writes) const {
  std::vector<VkWriteDescriptorSet> targeted = writes;
  for (VkWriteDescriptorSet& write : targeted) write.dstSet = set_;
  vkUpdateDescriptorSets(context_.device(), uint32_t(targeted.size()), targeted.data(), 0, nullptr);
}

void ComputeKernel::dispatch(VkCommandBuffer cmd, const void* constants, uint32_t groupsX,
                             uint32_t groupsY, uint32_t groupsZ) const {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set_, 0, nullptr);
  vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, pushSize_, constants);
  vkCmdDispatch(cmd, groupsX, groupsY, groupsZ);
}

}  // namespace shadelab
