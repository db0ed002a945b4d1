#pragma once
// Skybox: the environment cube drawn behind everything. One triangle covers
// the viewport at the depth the depth buffer was cleared to, tested EQUAL,
// so only pixels (and, with MSAA, samples) that no object covered get it.
// Reads: set 0 binding BINDING_ENVIRONMENT (the frame's set, forward layout).
// Writes: the colour attachment of the rendering scope, after the forward pass.
#include <glm/glm.hpp>
#include <map>

#include "core/context.h"
#include "core/resources.h"
#include "passes/forward_pass.h"

namespace shadelab {

class SkyboxPass {
 public:
  SkyboxPass(const Context& context, const AttachmentFormats& formats,
             VkDescriptorSetLayout frameSetLayout);
  void prepare(uint32_t samples);
  // `view` and `projection` are the camera's; only the view's rotation is used.
  void record(VkCommandBuffer cmd, uint32_t samples, VkDescriptorSet frameSet,
              const glm::mat4& view, const glm::mat4& projection, float clearedDepth,
              const VkViewport& viewport) const;

 private:
  Pipeline createPipeline(uint32_t samples) const;

  const Context& context_;
  AttachmentFormats formats_;
  PipelineLayout layout_;
  ShaderModule vertex_;
  ShaderModule fragment_;
  std::map<uint32_t, Pipeline> pipelines_;  // by sample count
};

}  // namespace shadelab
