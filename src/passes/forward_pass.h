#pragma once
// Forward shading pass: draws the visible objects of a GpuScene with the
// Phong illumination equation under one of the shading models.
// Reads: set 0 = FrameData (uniform) + ObjectData[] (storage) + the environment
// cube (environment term: kr, kt and ior per draw), vertex/index buffers;
// textured draws also set 1 (their material's textures).
// Textured draws use their own variants (the TEXTURED rows of the shader
// table): they read the uv and tangent attributes, which the others do not
// declare. Transparent draws use blended variants that do not write depth.
// Writes: the colour and depth attachments of the rendering scope it is recorded in.
#include <map>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "core/vulkan/context.h"
#include "core/vulkan/depth.h"
#include "core/vulkan/gpu_scene.h"
#include "core/vulkan/resources.h"
#include "core/vulkan/shader_table.h"
#include "core/scene/shading.h"

namespace shadelab {

// What a pipeline must match in the render target: sample count and depth
// mode (format, compare op).
struct TargetLayout {
  uint32_t samples = 1;
  DepthMode depth = DepthMode::D32F;
  auto operator<=>(const TargetLayout&) const = default;
};

class ForwardPass {
 public:
  ForwardPass(const Context& context, VkFormat colorFormat);

  VkDescriptorSetLayout descriptorSetLayout() const { return setLayout_.get(); }
  VkDescriptorSetLayout materialSetLayout() const { return materialSetLayout_.get(); }
  // Builds the pipelines of every shading model for a scene's light layout
  // (specialization constants) and a target layout, before any frame records
  // with them; `textured` adds the textured variants, `blended` the ones
  // transparent draws use; `environment` selects the variants with the
  // environment term.
  void prepare(LightLayout lights, TargetLayout target, bool textured, bool blended,
               bool environment = false);
  // Records `draws` (visibleDraws: opaque first, then transparent ones, which
  // blend over what is drawn) inside an active dynamic-rendering scope; sets
  // its own viewport.
  void record(VkCommandBuffer cmd, ShadingModel model, TargetLayout target,
              VkDescriptorSet frameSet, const GpuScene& scene, std::span<const DrawItem> draws,
              const VkViewport& viewport, bool environment = false) const;
  // Triangle edges of `draws` over what record() drew (polygonMode LINE,
  // depth-biased towards the eye); a no-op without fillModeNonSolid.
  void recordWireframe(VkCommandBuffer cmd, TargetLayout target, VkDescriptorSet frameSet,
                       const GpuScene& scene, std::span<const DrawItem> draws,
                       const VkViewport& viewport) const;

  // The shader table rows (shaders/CMakeLists.txt) compiled from the forward bodies.
  static std::vector<ShaderVariant> shaderVariants();
  // New SPIR-V by row name; drops every pipeline (prepare() rebuilds them).
  void reloadShaders(const std::map<std::string, std::vector<uint32_t>>& spirv);

 private:
  // model, lights, target (samples, depth), textured, blended, wireframe, environment term
  using VariantKey = std::tuple<ShadingModel, LightLayout, TargetLayout, bool, bool, bool, bool>;
  Pipeline createPipeline(const VariantKey& key) const;

  const Context& context_;
  VkFormat colorFormat_;
  DescriptorSetLayout setLayout_;
  DescriptorSetLayout materialSetLayout_;
  PipelineLayout layout_;
  std::map<std::string, ShaderModule> modules_;  // by row name: every one of shaderVariants()
  std::map<VariantKey, Pipeline> pipelines_;
};

}  // namespace shadelab
