#pragma once
// Skybox: the environment cube drawn behind everything. One triangle covers
// the viewport at the depth the depth buffer was cleared to, tested EQUAL,
// so only pixels (and, with MSAA, samples) that no object covered get it.
// Reads: set 0 binding BINDING_ENVIRONMENT (the frame's set, forward layout).
// Writes: the colour attachment of the rendering scope, after the forward pass.
#include <glm/glm.hpp>
#include <map>

#include "core/vulkan/context.h"
#include "core/vulkan/resources.h"
#include "passes/forward_pass.h"

namespace shadelab {

class SkyboxPass {
 public:
  SkyboxPass(const Context& context, VkFormat colorFormat, VkDescriptorSetLayout frameSetLayout);
  void prepare(TargetLayout target);
  // `view` and `projection` are the camera's (reversed-Z included); only the
  // view's rotation is used. The depth mode gives the far plane's depth.
  void record(VkCommandBuffer cmd, TargetLayout target, VkDescriptorSet frameSet,
              const glm::mat4& view, const glm::mat4& projection, const VkViewport& viewport) const;

 private:
  Pipeline createPipeline(TargetLayout target) const;

  const Context& context_;
  VkFormat colorFormat_;
  PipelineLayout layout_;
  ShaderModule vertex_;
  ShaderModule fragment_;
  std::map<TargetLayout, Pipeline> pipelines_;
};

}  // namespace shadelab
