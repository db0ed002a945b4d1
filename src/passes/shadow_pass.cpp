#include "passes/shadow_pass.h"

#include <glm/gtc/type_ptr.hpp>

#include "core/scene/frustum.h"
#include "core/vulkan/barriers.h"
#include "core/vulkan/shader.h"
#include "core/vulkan/vk_check.h"
#include "passes/graphics_pipeline.h"

namespace shadelab {

ShadowPass::ShadowPass(const Context& context) : context_(context) {
  VkDevice device = context.device();
  VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4)};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &push;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout));
  layout_ = PipelineLayout(device, layout);
  vertex_ = loadShader(device, "shadow_depth.vert");

  VkPipelineShaderStageCreateInfo stage{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  stage.stage = VK_SHADER_STAGE_VERTEX_BIT;
  stage.module = vertex_;
  stage.pName = "main";
  VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
  VkVertexInputAttributeDescription position{0, 0, VK_FORMAT_R32G32B32_SFLOAT,
                                             offsetof(Vertex, position)};
  VkPipelineVertexInputStateCreateInfo vertexInput{
      VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertexInput.vertexBindingDescriptionCount = 1;
  vertexInput.pVertexBindingDescriptions = &binding;
  vertexInput.vertexAttributeDescriptionCount = 1;
  vertexInput.pVertexAttributeDescriptions = &position;
  VkPipelineRasterizationStateCreateInfo raster{
      VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  // Both faces: an open surface (a plane) casts from either side.
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.lineWidth = 1.0f;
  // A caster between the light and its near plane is flattened onto the
  // plane instead of clipped away ("pancaking"), so it still casts.
  raster.depthClampEnable = context.features().depthClamp;
  VkPipelineMultisampleStateCreateInfo multisample{
      VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depth{
      VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = VK_TRUE;
  depth.depthCompareOp = VK_COMPARE_OP_LESS;
  // No colour attachment: the rendering scope's one slot stays empty.
  pipeline_ = createGraphicsPipeline(device, {{&stage, 1},
                                              &vertexInput,
                                              &raster,
                                              &multisample,
                                              &depth,
                                              {},
                                              VK_FORMAT_UNDEFINED,
                                              kDepthFormat,
                                              layout_});

  VkSamplerCreateInfo samplerInfo{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  // One tap per texture() call: the filters are taps in the shader (PCF).
  samplerInfo.magFilter = VK_FILTER_NEAREST;
  samplerInfo.minFilter = VK_FILTER_NEAREST;
  samplerInfo.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  samplerInfo.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  samplerInfo.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  samplerInfo.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  // Lit where the point's depth is no farther than the nearest caster's.
  samplerInfo.compareEnable = VK_TRUE;
  samplerInfo.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
  VkSampler sampler = VK_NULL_HANDLE;
  VK_CHECK(vkCreateSampler(device, &samplerInfo, nullptr, &sampler));
  sampler_ = Sampler(device, sampler);

  ImageDesc desc{kDepthFormat, 1, 1};
  desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  desc.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
  desc.arrayView = true;
  placeholder_ = Image(context, desc);
  context.submitAndWait([&](VkCommandBuffer cmd) {
    imageBarrier(cmd, placeholder_.get(), VK_IMAGE_ASPECT_DEPTH_BIT, ImageUse::Undefined,
                 ImageUse::ShaderRead);
  });
}

bool ShadowPass::prepare(uint32_t layers, uint32_t size) {
  layers = std::max(layers, 1u);
  if (map_ && map_.desc().layers == layers && map_.desc().width == size) return false;
  if (map_) context_.waitIdle();  // frames in flight read the old map
  layerViews_.clear();
  drawnFrom_.assign(layers, {});
  map_ = Image{};
  ImageDesc desc{kDepthFormat, size, size};
  desc.layers = layers;
  desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  desc.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
  desc.arrayView = true;
  map_ = Image(context_, desc);
  for (uint32_t layer = 0; layer < layers; ++layer) {
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = map_.get();
    info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    info.format = kDepthFormat;
    info.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, layer, 1};
    VkImageView view = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImageView(context_.device(), &info, nullptr, &view));
    layerViews_.emplace_back(context_.device(), view);
  }
  // Every layer in ShaderRead, as record() leaves them, even those never drawn.
  context_.submitAndWait([&](VkCommandBuffer cmd) {
    imageBarrier(cmd, map_.get(), VK_IMAGE_ASPECT_DEPTH_BIT, ImageUse::Undefined,
                 ImageUse::ShaderRead);
  });
  return true;
}

uint32_t ShadowPass::record(VkCommandBuffer cmd, const GpuScene& scene, uint32_t sceneUpload,
                            std::span<const glm::mat4> objectTransforms,
                            std::span<const glm::mat4> worldToLightClip, bool keep) {
  assert(map_ && worldToLightClip.size() <= layerViews_.size());
  if (sceneUpload != drawnUpload_) {
    drawnFrom_.assign(drawnFrom_.size(), {});
    drawnUpload_ = sceneUpload;
  }
  // Each layer's casters (culled against its frustum; the near plane stays:
  // depth clamp keeps what lies before it) and what the layer is drawn from.
  std::vector<std::vector<const DrawItem*>> casters(worldToLightClip.size());
  std::vector<size_t> toDraw;
  for (size_t layer = 0; layer < worldToLightClip.size(); ++layer) {
    Frustum frustum = frustumFromMatrix(worldToLightClip[layer]);
    std::vector<float> from(glm::value_ptr(worldToLightClip[layer]),
                            glm::value_ptr(worldToLightClip[layer]) + 16);
    for (const DrawItem& draw : scene.draws) {
      if (!draw.castsShadows || !boxIntersectsFrustum(draw.worldBounds, frustum)) continue;
      casters[layer].push_back(&draw);
      const glm::mat4& model = objectTransforms[size_t(draw.constants.object.x)];
      from.push_back(float(&draw - scene.draws.data()));
      from.insert(from.end(), glm::value_ptr(model), glm::value_ptr(model) + 16);
    }
    if (keep && from == drawnFrom_[layer]) continue;
    drawnFrom_[layer] = std::move(from);
    toDraw.push_back(layer);
  }
  if (toDraw.empty()) return 0;

  uint32_t size = map_.desc().width;
  // The layers not drawn keep their depth: ShaderRead, not Undefined, before.
  imageBarrier(cmd, map_.get(), VK_IMAGE_ASPECT_DEPTH_BIT, ImageUse::ShaderRead,
               ImageUse::DepthAttachment);
  uint32_t drawn = 0;
  for (size_t layer : toDraw) {
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};  // unused slot
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth.imageView = layerViews_[layer];
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    depth.clearValue.depthStencil = {1.0f, 0};  // the far plane: nothing casts
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {size, size}};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;
    rendering.pDepthAttachment = &depth;
    vkCmdBeginRendering(cmd, &rendering);
    VkViewport viewport{0.0f, 0.0f, float(size), float(size), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, {size, size}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
    VkDeviceSize offset = 0;
    VkBuffer vertexBuffer = scene.vertices.get();
    vkCmdBindVertexBuffers(cmd, 0, 1, &vertexBuffer, &offset);
    vkCmdBindIndexBuffer(cmd, scene.indices.get(), 0, VK_INDEX_TYPE_UINT32);
    for (const DrawItem* draw : casters[layer]) {
      glm::mat4 objectToClip =
          worldToLightClip[layer] * objectTransforms[size_t(draw->constants.object.x)];
      vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(objectToClip),
                         &objectToClip);
      vkCmdDrawIndexed(cmd, draw->indexCount, 1, draw->firstIndex, draw->vertexOffset, 0);
      ++drawn;
    }
    vkCmdEndRendering(cmd);
  }
  imageBarrier(cmd, map_.get(), VK_IMAGE_ASPECT_DEPTH_BIT, ImageUse::DepthAttachment,
               ImageUse::ShaderRead);
  return drawn;
}

}  // namespace shadelab
