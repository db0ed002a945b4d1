#pragma once
// Forward shading pass: draws every object of a GpuScene with the Phong
// illumination equation under one of the shading models.
// Reads: set 0 = FrameData (uniform) + ObjectData[] (storage) + the environment
// cube (environment term: kr, kt and ior per draw), vertex/index buffers;
// textured draws also set 1 (their material's textures).
// Textured draws use their own variants (forward_textured.*): they read the
// uv and tangent attributes, which the others do not declare.
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
  VkDescriptorSetLayout materialSetLayout() const { return materialSetLayout_.get(); }
  // Builds the pipelines of every shading model for a scene's light layout
  // (specialization constants) and a sample count, before any frame records
  // with them; `textured` adds the textured variants, `environment` selects
  // the variants with the environment term.
  void prepare(LightLayout lights, uint32_t samples, bool textured, bool environment = false);
  // Records inside an active dynamic-rendering scope; sets its own viewport.
  void record(VkCommandBuffer cmd, ShadingModel model, uint32_t samples, VkDescriptorSet frameSet,
              const GpuScene& scene, const VkViewport& viewport, bool environment = false) const;

 private:
  // model, lights, samples, textured, environment term
  using VariantKey = std::tuple<ShadingModel, LightLayout, uint32_t, bool, bool>;
  Pipeline createPipeline(const VariantKey& key) const;

  const Context& context_;
  AttachmentFormats formats_;
  DescriptorSetLayout setLayout_;
  DescriptorSetLayout materialSetLayout_;
  PipelineLayout layout_;
  ShaderModule vertex_;
  ShaderModule flatGeometry_;
  ShaderModule fragment_;
  ShaderModule texturedVertex_;
  ShaderModule texturedFlatGeometry_;
  ShaderModule texturedFragment_;
  std::map<VariantKey, Pipeline> pipelines_;
};

}  // namespace shadelab
