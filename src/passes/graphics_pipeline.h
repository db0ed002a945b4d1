#pragma once
// What every graphics pipeline of the passes shares: a triangle list, one
// viewport and scissor set per draw (dynamic), one colour attachment and a
// depth attachment through dynamic rendering. A pass fills in the states that
// make it what it is.
#include <vulkan/vulkan.h>

#include <optional>
#include <span>
#include <vector>

#include "core/vulkan/gpu_scene.h"
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

// The sets of light values compiled into pipelines (SPEC_LIGHT_CONSTANTS),
// each under a small id, so that a pipeline key holds and compares 4 bytes
// instead of a set's 300 (ForwardPass and BillboardPass look a key up per
// draw). The same values get the same id; 0 stands for none (read from
// FrameData). Ids stay valid for the table's lifetime (the Renderer's).
class LightSets {
 public:
  uint32_t intern(const LightValues& values);
  const LightValues* find(uint32_t id) const;  // nullptr for 0

 private:
  std::vector<LightValues> sets_;  // id - 1
};

// The lighting specialization constants the forward and billboard pipelines
// share (shaders/common.glsl): the light counts, whether point lights
// attenuate, which lights cast shadows and, when `values` holds them, the
// frame's ambient term and lights compiled in (SPEC_LIGHT_CONSTANTS).
struct LightSpecialization {
  int32_t pointLights;
  int32_t directionalLights;
  VkBool32 attenuated;
  int32_t shadowedLights;
  VkBool32 compiled;
  LightValues values;
};
LightSpecialization lightSpecialization(const LightLayout& layout, const LightValues* values);
// Appends the map entries of a LightSpecialization that lies `offset` bytes
// into a pipeline's specialization data.
void appendLightEntries(std::vector<VkSpecializationMapEntry>& entries, uint32_t offset);

}  // namespace shadelab
