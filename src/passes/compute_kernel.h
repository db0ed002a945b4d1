#pragma once
// One compute pipeline with its own descriptor set (one set, rewritten
// between uses) and push constants: what the load-time passes that build
// the environment cube share. Not for the frame loop: update() must not run
// while a submitted dispatch still reads the set.
#include <string_view>
#include <vector>

#include "core/vulkan/context.h"
#include "core/vulkan/resources.h"

namespace shadelab {

class ComputeKernel {
 public:
  ComputeKernel(const Context& context, std::string_view shader,
                const std::vector<VkDescriptorSetLayoutBinding>& bindings, uint32_t pushSize);

  // Points every binding of the set at its resource (all of them: lavapipe
  // crashes on unwritten descriptors).
  void update(const std::vector<VkWriteDescriptorSet>& writes) const;
  VkDescriptorSet set() const { return set_; }
  // Binds pipeline and set, pushes `constants`, dispatches groups.
  void dispatch(VkCommandBuffer cmd, const void* constants, uint32_t groupsX, uint32_t groupsY,
                uint32_t groupsZ) const;

 private:
  const Context& context_;
  uint32_t pushSize_;
  DescriptorSetLayout setLayout_;
  PipelineLayout layout_;
  ShaderModule shader_;
  Pipeline pipeline_;
  DescriptorPool pool_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace shadelab
