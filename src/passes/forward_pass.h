#pragma once
// Forward shading pass: draws every object of a GpuScene with the Phong
// illumination equation under one of the shading models.
// Reads: set 0 = FrameData (uniform) + ObjectData[] (storage) + the environment
// cube (environment term: kr, kt and ior per draw), vertex/index buffers.
// Writes: the colour and depth attachments of the rendering scope it is recorded in.
#include <map>
#include <tuple>

#include "core/context.h"
#include "core/gpu_scene.h"
#include "core/resources.h"
#include "core/shading.h"

namespace shadelab {

struct AttachmentFormats {
  VkFormat color = VK_FORMAT_R16G16B16A16_SFLOAT;
  VkFormat depth = VK_FORMAT_D32_SFLOAT;
};

class ForwardPass {
 public:
  ForwardPass(const Context& context, const AttachmentFormats& formats);

  VkDescriptorSetLayout descriptorSetLayout() const { return setLayout_.get(); }
  // Builds the pipelines of every shading model for a scene's light layout
  // (specialization constants), a sample count and whether the environment
  // term is on, before any frame records with them.
  void prepare(LightLayout lights, uint32_t samples, bool environment = false);
  // Records inside an active dynamic-rendering scope; sets its own viewport.
  void record(VkCommandBuffer cmd, ShadingModel model, uint32_t samples, VkDescriptorSet frameSet,
              const GpuScene& scene, const VkViewport& viewport, bool environment = false) const;

 private:
  // model, lights, samples, environment term
  using VariantKey = std::tuple<ShadingModel, LightLayout, uint32_t, bool>;
  Pipeline createPipeline(const VariantKey& key) const;

  const Context& context_;
  AttachmentFormats formats_;
  DescriptorSetLayout setLayout_;
  PipelineLayout layout_;
  ShaderModule vertex_;
  ShaderModule flatGeometry_;
  ShaderModule fragment_;
  std::map<VariantKey, Pipeline> pipelines_;
};

}  // namespace shadelab
