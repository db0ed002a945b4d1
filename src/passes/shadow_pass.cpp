#include "passes/shadow_pass.h"

#include <bit>
#include <cassert>
#include <cmath>
#include <cstring>
#include <glm/gtc/type_ptr.hpp>
#include <optional>

#include "core/scene/frustum.h"
#include "core/vulkan/barriers.h"
#include "core/vulkan/shader.h"
#include "core/vulkan/vk_check.h"
#include "passes/graphics_pipeline.h"

namespace shadelab {

namespace {
// shadow_depth_masked.*'s push constants.
struct MaskedShadowDraw {
  glm::mat4 objectToLightClip;
  // xy = uv scale, z = alpha threshold (a blended caster's transmittance:
  // its opacity kd.w), w = uv rotation
  glm::vec4 texturing;
  glm::vec4 diffuseUv;  // KHR_texture_transform: xy = offset, zw = scale
};

// A caster whose base colour texture's alpha matters to its shadow: alphaMode
// MASK (cut below its cut-off, in the depth array) and BLEND over a texture
// with alpha (TEXTURE_ALPHA: a translucent caster whose every texel passes
// 1 - its coverage, kd.w times the texel's alpha, as the tracer's shadow
// rays do). They read their uv and their material's set.
bool isMaskedCaster(const DrawItem& draw) {
  int32_t maps = draw.constants.object.y;
  return draw.textured && (maps & TEXTURE_DIFFUSE) && (draw.masked || (maps & TEXTURE_ALPHA));
}

// glTF BLEND over a texture with alpha: translucent, texel by texel.
bool isBlendedTextureCaster(const DrawItem& draw) {
  return isMaskedCaster(draw) && !draw.masked;
}

// shadow_translucent.*'s push constants.
struct TranslucentShadowDraw {
  glm::mat4 objectToLightClip;
  // Object space to the light's frame (affine); its last row carries
  // (kt, ior, 1: Fresnel, 1: point light).
  glm::mat4 objectToLight;
};
static_assert(sizeof(TranslucentShadowDraw) <= 128,
              "Vulkan guarantees 128 bytes of push constants");

// World space to a light's frame: the point light at the origin, or the
// directional light shining along -z (`towardsLight` becomes +z).
glm::mat4 worldToLightFrame(const glm::vec4& light) {
  if (light.w != 0.0f)
    return glm::mat4(glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, 1, 0),
                     glm::vec4(-glm::vec3(light), 1));
  glm::vec3 z = glm::normalize(glm::vec3(light));
  glm::vec3 helper = std::abs(z.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  glm::vec3 x = glm::normalize(glm::cross(helper, z));
  glm::vec3 y = glm::cross(z, x);
  // Rows x, y, z: a rotation taking z to (0, 0, 1).
  return glm::mat4(glm::vec4(x.x, y.x, z.x, 0), glm::vec4(x.y, y.y, z.y, 0),
                   glm::vec4(x.z, y.z, z.z, 0), glm::vec4(0, 0, 0, 1));
}
}  // namespace

bool ShadowPass::isTranslucentCaster(const DrawItem& draw) {
  // kd.w = 1 - kt. A MASK texture keeps the caster in the depth array
  // (isMaskedCaster), whatever its kt.
  return draw.castsShadows && !draw.hidden &&
         (isBlendedTextureCaster(draw) || (draw.constants.kd.w < 1.0f && !isMaskedCaster(draw)));
}

bool ShadowPass::anyTranslucentCaster(std::span<const DrawItem> draws) {
  for (const DrawItem& draw : draws)
    if (isTranslucentCaster(draw)) return true;
  return false;
}

ShadowPass::ShadowPass(const Context& context, VkDescriptorSetLayout materialLayout)
    : context_(context) {
  VkDevice device = context.device();
  VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4)};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &push;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout));
  layout_ = PipelineLayout(device, layout);
  vertex_ = loadShader(device, "shadow_depth.vert");

  // Masked casters (isMaskedCaster): the same state with the uv and a fragment stage.
  VkPushConstantRange maskedPush{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                 sizeof(MaskedShadowDraw)};
  VkPipelineLayoutCreateInfo maskedLayoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  maskedLayoutInfo.setLayoutCount = 1;
  maskedLayoutInfo.pSetLayouts = &materialLayout;
  maskedLayoutInfo.pushConstantRangeCount = 1;
  maskedLayoutInfo.pPushConstantRanges = &maskedPush;
  VK_CHECK(vkCreatePipelineLayout(device, &maskedLayoutInfo, nullptr, &layout));
  maskedLayout_ = PipelineLayout(device, layout);
  maskedVertex_ = loadShader(device, "shadow_depth_masked.vert");
  maskedFragment_ = loadShader(device, "shadow_depth_masked.frag");
  // The usual pipelines now; the ones without depth clamp (a study's) when asked.
  pipelines_[0][1] = createDepthPipeline(false, true);
  pipelines_[1][1] = createDepthPipeline(true, true);

  // Translucent casters (isTranslucentCaster): position and normal, the light's frame.
  VkPushConstantRange translucentPush{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(TranslucentShadowDraw)};
  VkPipelineLayoutCreateInfo translucentLayoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  translucentLayoutInfo.pushConstantRangeCount = 1;
  translucentLayoutInfo.pPushConstantRanges = &translucentPush;
  VK_CHECK(vkCreatePipelineLayout(device, &translucentLayoutInfo, nullptr, &layout));
  translucentLayout_ = PipelineLayout(device, layout);
  translucentVertex_ = loadShader(device, "shadow_translucent.vert");
  translucentFragment_ = loadShader(device, "shadow_translucent.frag");
  texturedTranslucentFragment_ = loadShader(device, "shadow_translucent_textured.frag");

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

  // The transmittance: one texel per tap, as the depth's.
  samplerInfo.compareEnable = VK_FALSE;
  samplerInfo.compareOp = VK_COMPARE_OP_ALWAYS;
  VK_CHECK(vkCreateSampler(device, &samplerInfo, nullptr, &sampler));
  transmittanceSampler_ = Sampler(device, sampler);

  ImageDesc desc{kDepthFormat, 1, 1};
  desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  desc.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
  desc.arrayView = true;
  placeholder_ = Image(context, desc);
  ImageDesc transmittanceDesc{kTransmittanceFormat, 1, 1};
  transmittanceDesc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  transmittanceDesc.arrayView = true;
  transmittancePlaceholder_ = Image(context, transmittanceDesc);
  context.submitAndWait([&](VkCommandBuffer cmd) {
    imageBarrier(cmd, placeholder_.get(), VK_IMAGE_ASPECT_DEPTH_BIT, ImageUse::Undefined,
                 ImageUse::ShaderRead);
    // Defined contents, though only variants that read real layers sample it.
    imageBarrier(cmd, transmittancePlaceholder_.get(), VK_IMAGE_ASPECT_COLOR_BIT,
                 ImageUse::Undefined, ImageUse::TransferDest);
    VkClearColorValue one{{1.0f, 1.0f, 1.0f, 1.0f}};
    VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, transmittancePlaceholder_.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         &one, 1, &range);
    imageBarrier(cmd, transmittancePlaceholder_.get(), VK_IMAGE_ASPECT_COLOR_BIT,
                 ImageUse::TransferDest, ImageUse::ShaderRead);
  });
}

Pipeline ShadowPass::createCasterPipeline(VkShaderModule vertex, VkShaderModule fragment,
                                          const VkVertexInputAttributeDescription* second,
                                          bool depthClamp, GraphicsPipelineDesc desc) const {
  VkPipelineShaderStageCreateInfo stages[2] = {
      {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
      {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vertex;
  stages[0].pName = "main";
  stages[1] = stages[0];
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = fragment;
  VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
  VkVertexInputAttributeDescription attributes[] = {
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
      second ? *second : VkVertexInputAttributeDescription{}};
  VkPipelineVertexInputStateCreateInfo vertexInput{
      VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertexInput.vertexBindingDescriptionCount = 1;
  vertexInput.pVertexBindingDescriptions = &binding;
  vertexInput.vertexAttributeDescriptionCount = second ? 2 : 1;
  vertexInput.pVertexAttributeDescriptions = attributes;
  VkPipelineRasterizationStateCreateInfo raster{
      VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  // Both faces: an open surface (a plane) casts from either side, and a
  // closed translucent one passes light twice (in and out), as the tracer's
  // shadow rays count its crossings.
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.lineWidth = 1.0f;
  // A caster between the light and its near plane is flattened onto the
  // plane instead of clipped away ("pancaking"), so it still casts
  // (study shadow-near measures what clipping would lose).
  raster.depthClampEnable = depthClamp && context_.features().depthClamp;
  VkPipelineMultisampleStateCreateInfo multisample{
      VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  desc.stages = {stages, fragment ? 2u : 1u};
  desc.vertexInput = &vertexInput;
  desc.raster = &raster;
  desc.multisample = &multisample;
  return createGraphicsPipeline(context_.device(), desc);
}

Pipeline ShadowPass::createDepthPipeline(bool masked, bool depthClamp) const {
  VkPipelineDepthStencilStateCreateInfo depth{
      VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = VK_TRUE;
  depth.depthCompareOp = VK_COMPARE_OP_LESS;
  // No colour attachment: the rendering scope's one slot stays empty.
  GraphicsPipelineDesc desc;
  desc.depth = &depth;
  desc.depthFormat = kDepthFormat;
  desc.layout = masked ? maskedLayout_.get() : layout_.get();
  // Masked casters also read the uv.
  const VkVertexInputAttributeDescription uv{1, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(Vertex, uv)};
  return createCasterPipeline(masked ? maskedVertex_.get() : vertex_.get(),
                              masked ? maskedFragment_.get() : VK_NULL_HANDLE,
                              masked ? &uv : nullptr, depthClamp, desc);
}

VkPipeline ShadowPass::pipeline(bool masked, bool depthClamp) {
  Pipeline& slot = pipelines_[masked ? 1 : 0][depthClamp ? 1 : 0];
  if (!slot) slot = createDepthPipeline(masked, depthClamp);
  return slot;
}

Pipeline ShadowPass::createTranslucentPipeline(bool depthClamp, bool textured) const {
  VkPipelineDepthStencilStateCreateInfo depth{
      VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  // Every crossing counts, in any order: no depth test.
  GraphicsPipelineDesc desc;
  desc.depth = &depth;
  // dst = dst * src: the product of every crossing's transmittance.
  desc.blend.blendEnable = VK_TRUE;
  desc.blend.srcColorBlendFactor = VK_BLEND_FACTOR_ZERO;
  desc.blend.dstColorBlendFactor = VK_BLEND_FACTOR_SRC_COLOR;
  desc.blend.colorBlendOp = VK_BLEND_OP_ADD;
  desc.blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
  desc.blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
  desc.blend.alphaBlendOp = VK_BLEND_OP_ADD;
  desc.blend.colorWriteMask = VK_COLOR_COMPONENT_R_BIT;
  desc.colorFormat = kTransmittanceFormat;
  desc.layout = textured ? maskedLayout_.get() : translucentLayout_.get();
  // A blended texture's caster (shadow_depth_masked.*) reads its uv, glass its normal.
  const VkVertexInputAttributeDescription second =
      textured
          ? VkVertexInputAttributeDescription{1, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(Vertex, uv)}
          : VkVertexInputAttributeDescription{1, 0, VK_FORMAT_R32G32B32_SFLOAT,
                                              offsetof(Vertex, normal)};
  return createCasterPipeline(
      textured ? maskedVertex_.get() : translucentVertex_.get(),
      textured ? texturedTranslucentFragment_.get() : translucentFragment_.get(), &second,
      depthClamp, desc);
}

VkPipeline ShadowPass::translucentPipeline(bool depthClamp, bool textured) {
  Pipeline& slot = translucentPipelines_[depthClamp ? 1 : 0][textured ? 1 : 0];
  if (!slot) slot = createTranslucentPipeline(depthClamp, textured);
  return slot;
}

ShadowPass::~ShadowPass() {
  waitForWarmUp();
}

void ShadowPass::waitForWarmUp() {
  if (!warmPending_) return;
  VkFence fence = warmFence_;
  VK_CHECK(vkWaitForFences(context_.device(), 1, &fence, VK_TRUE, UINT64_MAX));
  warmPending_ = false;
}

void ShadowPass::warmUp(bool depthClamp) {
  if (warmed_ || !map_) return;
  warmed_ = true;
  waitForWarmUp();
  VkDevice device = context_.device();
  if (!warmCommands_.pool) {
    warmCommands_ = createCommandBuffer(context_, VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT);
    warmFence_ = createFence(device);
    // Three vertices at the origin: a triangle with no area, no fragment.
    warmVertices_ = Buffer(context_, 3 * sizeof(Vertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                           MemoryUse::HostVisible);
    std::memset(warmVertices_.mapped(), 0, 3 * sizeof(Vertex));
  }
  VkCommandBuffer cmd = warmCommands_.cmd;
  VK_CHECK(vkResetCommandBuffer(cmd, 0));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
  imageBarrier(cmd, map_.get(), VK_IMAGE_ASPECT_DEPTH_BIT, ImageUse::ShaderRead,
               ImageUse::DepthAttachment);
  VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};  // unused slot
  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  depth.imageView = layerViews_[0];
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  depth.clearValue.depthStencil = {1.0f, 0};
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, {1, 1}};
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachments = &color;
  rendering.pDepthAttachment = &depth;
  vkCmdBeginRendering(cmd, &rendering);
  VkViewport viewport{0.0f, 0.0f, 1.0f, 1.0f, 0.0f, 1.0f};
  VkRect2D scissor{{0, 0}, {1, 1}};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline(false, depthClamp));
  VkDeviceSize offset = 0;
  VkBuffer vertexBuffer = warmVertices_.get();
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertexBuffer, &offset);
  glm::mat4 identity(1.0f);
  vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(identity), &identity);
  vkCmdDraw(cmd, 3, 1, 0, 0);
  vkCmdEndRendering(cmd);
  imageBarrier(cmd, map_.get(), VK_IMAGE_ASPECT_DEPTH_BIT, ImageUse::DepthAttachment,
               ImageUse::ShaderRead);
  VK_CHECK(vkEndCommandBuffer(cmd));
  VkFence fence = warmFence_;
  VK_CHECK(vkResetFences(device, 1, &fence));
  VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cmdInfo.commandBuffer = cmd;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cmdInfo;
  VK_CHECK(vkQueueSubmit2(context_.queue(), 1, &submit, fence));
  warmPending_ = true;
}

std::vector<ImageView> ShadowPass::makeLayerViews(const Image& image, VkFormat format,
                                                  VkImageAspectFlags aspect) const {
  std::vector<ImageView> views;
  for (uint32_t layer = 0; layer < image.desc().layers; ++layer) {
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = image.get();
    info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    info.format = format;
    info.subresourceRange = {aspect, 0, 1, layer, 1};
    VkImageView view = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImageView(context_.device(), &info, nullptr, &view));
    views.emplace_back(context_.device(), view);
  }
  return views;
}

bool ShadowPass::prepare(uint32_t layers, uint32_t size, bool translucent) {
  layers = std::max(layers, 1u);
  if (map_ && map_.desc().layers == layers && map_.desc().width == size &&
      this->translucent() == translucent)
    return false;
  if (map_) context_.waitIdle();  // frames in flight read the old map
  waitForWarmUp();
  warmed_ = false;
  drawnFrom_.assign(layers, {});
  layerViews_.clear();
  opaqueDepthViews_.clear();
  transmittanceViews_.clear();
  map_ = Image{};
  opaqueDepth_ = Image{};
  transmittance_ = Image{};
  ImageDesc desc{kDepthFormat, size, size};
  desc.layers = layers;
  desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  desc.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
  desc.arrayView = true;
  // With translucent casters each layer starts as a copy of the opaque ones' depth.
  ImageDesc opaqueDesc = desc;
  if (translucent) {
    desc.usage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    opaqueDesc.usage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  }
  map_ = Image(context_, desc);
  layerViews_ = makeLayerViews(map_, kDepthFormat, VK_IMAGE_ASPECT_DEPTH_BIT);
  if (translucent) {
    opaqueDepth_ = Image(context_, opaqueDesc);
    opaqueDepthViews_ = makeLayerViews(opaqueDepth_, kDepthFormat, VK_IMAGE_ASPECT_DEPTH_BIT);
    ImageDesc colour{kTransmittanceFormat, size, size};
    colour.layers = layers;
    colour.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    colour.arrayView = true;
    transmittance_ = Image(context_, colour);
    transmittanceViews_ =
        makeLayerViews(transmittance_, kTransmittanceFormat, VK_IMAGE_ASPECT_COLOR_BIT);
  }
  // Every layer in ShaderRead, as record() leaves them, even those never drawn.
  context_.submitAndWait([&](VkCommandBuffer cmd) {
    imageBarrier(cmd, map_.get(), VK_IMAGE_ASPECT_DEPTH_BIT, ImageUse::Undefined,
                 ImageUse::ShaderRead);
    if (!translucent) return;
    imageBarrier(cmd, opaqueDepth_.get(), VK_IMAGE_ASPECT_DEPTH_BIT, ImageUse::Undefined,
                 ImageUse::ShaderRead);
    imageBarrier(cmd, transmittance_.get(), VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::Undefined,
                 ImageUse::ShaderRead);
  });
  return true;
}

bool ShadowPass::release() {
  if (!map_) return false;
  context_.waitIdle();  // frames in flight read the map
  waitForWarmUp();
  warmed_ = false;
  layerViews_.clear();
  opaqueDepthViews_.clear();
  transmittanceViews_.clear();
  drawnFrom_.clear();
  map_ = Image{};
  opaqueDepth_ = Image{};
  transmittance_ = Image{};
  return true;
}

uint32_t ShadowPass::record(VkCommandBuffer cmd, const GpuScene& scene,
                            std::span<const DrawItem> draws, uint32_t sceneUpload,
                            std::span<const glm::mat4> objectTransforms,
                            std::span<const glm::mat4> worldToLightClip,
                            std::span<const glm::vec4> layerLights,
                            std::span<const VkDescriptorSet> materialSets, bool keep,
                            bool depthClamp) {
  assert(map_ && worldToLightClip.size() <= layerViews_.size());
  assert(layerLights.size() == worldToLightClip.size());
  if (sceneUpload != drawnUpload_) {
    drawnFrom_.assign(drawnFrom_.size(), {});
    drawnUpload_ = sceneUpload;
  }
  // Each layer's casters, culled against its frustum, and what the layer is
  // drawn from. With depth clamp a caster wholly before the near plane still
  // casts (flattened onto it), so only the side and far planes cull then; the
  // side planes alone already cull what lies behind the light.
  assert(draws.size() == scene.draws.size());
  std::vector<std::vector<const DrawItem*>> casters(worldToLightClip.size());
  std::vector<size_t> toDraw;
  bool clamped = depthClamp && context_.features().depthClamp;
  for (size_t layer = 0; layer < worldToLightClip.size(); ++layer) {
    Frustum frustum = frustumFromMatrix(worldToLightClip[layer]);
    if (clamped) frustum.planes[4] = Plane{glm::vec3(0.0f), 1.0f};  // near: everything inside
    std::vector<uint32_t> from;
    auto add = [&](const glm::mat4& matrix) {
      for (int i = 0; i < 16; ++i)
        from.push_back(std::bit_cast<uint32_t>(glm::value_ptr(matrix)[i]));
    };
    add(worldToLightClip[layer]);
    from.push_back(depthClamp ? 1 : 0);
    for (const DrawItem& draw : draws) {
      if (!draw.castsShadows || draw.hidden || !boxIntersectsFrustum(draw.worldBounds, frustum))
        continue;
      casters[layer].push_back(&draw);
      from.push_back(uint32_t(&draw - draws.data()));
      from.push_back(draw.firstIndex);  // the level of detail drawn
      from.push_back(uint32_t(draw.vertexOffset));
      add(objectTransforms[size_t(draw.constants.object.x)]);
      // A masked caster's holes depend on its texture's sampler (the filter override).
      if (isMaskedCaster(draw)) {
        uint64_t set = uint64_t(materialSets[draw.material]);
        from.push_back(uint32_t(set));
        from.push_back(uint32_t(set >> 32));
      }
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
  if (translucent()) {
    imageBarrier(cmd, opaqueDepth_.get(), VK_IMAGE_ASPECT_DEPTH_BIT, ImageUse::ShaderRead,
                 ImageUse::DepthAttachment);
    imageBarrier(cmd, transmittance_.get(), VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::ShaderRead,
                 ImageUse::ColorAttachment);
  }
  uint32_t drawn = 0;
  std::vector<const DrawItem*> translucentCasters;
  for (size_t layer : toDraw) {
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};  // unused slot
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    // With translucent casters the opaque ones go to their own array first
    // (recordTranslucent adds the translucent ones to a copy).
    depth.imageView = translucent() ? opaqueDepthViews_[layer] : layerViews_[layer];
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
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline(false, depthClamp));
    VkDeviceSize offset = 0;
    VkBuffer vertexBuffer = scene.vertices.get();
    vkCmdBindVertexBuffers(cmd, 0, 1, &vertexBuffer, &offset);
    vkCmdBindIndexBuffer(cmd, scene.indices.get(), 0, VK_INDEX_TYPE_UINT32);
    bool maskedBound = false;
    translucentCasters.clear();
    for (const DrawItem* caster : casters[layer]) {
      const DrawItem& draw = *caster;
      // Without the translucent layers (a scene without such casters has
      // none) every caster is opaque here.
      if (translucent() && isTranslucentCaster(draw)) {
        translucentCasters.push_back(caster);
        continue;
      }
      glm::mat4 objectToClip =
          worldToLightClip[layer] * objectTransforms[size_t(draw.constants.object.x)];
      bool masked = isMaskedCaster(draw);
      if (masked != maskedBound) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline(masked, depthClamp));
        maskedBound = masked;
      }
      if (masked) {
        assert(draw.material < materialSets.size() && "masked caster without its material set");
        VkDescriptorSet set = materialSets[draw.material];
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, maskedLayout_, 0, 1, &set, 0,
                                nullptr);
        const gpu::DrawConstants& constants = draw.constants;
        // MASK (a BLEND caster is translucent: recordTranslucent).
        assert(draw.masked);
        MaskedShadowDraw push{objectToClip,
                              glm::vec4(constants.texturing.x, constants.texturing.y,
                                        constants.ka.w, constants.texturing.w),
                              constants.diffuseUv};
        vkCmdPushConstants(cmd, maskedLayout_,
                           VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                           sizeof(push), &push);
      } else {
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(objectToClip),
                           &objectToClip);
      }
      vkCmdDrawIndexed(cmd, draw.indexCount, 1, draw.firstIndex, draw.vertexOffset, 0);
      ++drawn;
    }
    vkCmdEndRendering(cmd);
    if (translucent()) {
      recordTranslucent(cmd, scene, translucentCasters, layer, worldToLightClip[layer],
                        layerLights[layer], objectTransforms, materialSets, depthClamp);
      drawn += uint32_t(translucentCasters.size());
    }
  }
  imageBarrier(cmd, map_.get(), VK_IMAGE_ASPECT_DEPTH_BIT, ImageUse::DepthAttachment,
               ImageUse::ShaderRead);
  if (translucent()) {
    imageBarrier(cmd, opaqueDepth_.get(), VK_IMAGE_ASPECT_DEPTH_BIT, ImageUse::DepthAttachment,
                 ImageUse::ShaderRead);
    imageBarrier(cmd, transmittance_.get(), VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::ColorAttachment,
                 ImageUse::ShaderRead);
  }
  return drawn;
}

void ShadowPass::recordTranslucent(VkCommandBuffer cmd, const GpuScene& scene,
                                   std::span<const DrawItem* const> casters, size_t layer,
                                   const glm::mat4& worldToLightClip, const glm::vec4& light,
                                   std::span<const glm::mat4> objectTransforms,
                                   std::span<const VkDescriptorSet> materialSets, bool depthClamp) {
  uint32_t size = map_.desc().width;
  VkViewport viewport{0.0f, 0.0f, float(size), float(size), 0.0f, 1.0f};
  VkRect2D scissor{{0, 0}, {size, size}};
  VkDeviceSize offset = 0;
  VkBuffer vertexBuffer = scene.vertices.get();
  // The depth array's layer: the opaque casters' depth, then the
  // translucent ones drawn over it, so it holds the nearest of all (what
  // the lookup tests first).
  imageBarrier(cmd, opaqueDepth_.get(), VK_IMAGE_ASPECT_DEPTH_BIT, ImageUse::DepthAttachment,
               ImageUse::TransferSource);
  imageBarrier(cmd, map_.get(), VK_IMAGE_ASPECT_DEPTH_BIT, ImageUse::DepthAttachment,
               ImageUse::TransferDest);
  VkImageCopy copy{};
  copy.srcSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, uint32_t(layer), 1};
  copy.dstSubresource = copy.srcSubresource;
  copy.extent = {size, size, 1};
  vkCmdCopyImage(cmd, opaqueDepth_.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, map_.get(),
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
  imageBarrier(cmd, map_.get(), VK_IMAGE_ASPECT_DEPTH_BIT, ImageUse::TransferDest,
               ImageUse::DepthAttachment);
  imageBarrier(cmd, opaqueDepth_.get(), VK_IMAGE_ASPECT_DEPTH_BIT, ImageUse::TransferSource,
               ImageUse::DepthAttachment);
  VkRenderingAttachmentInfo none{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};  // unused slot
  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  depth.imageView = layerViews_[layer];
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, {size, size}};
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachments = &none;
  rendering.pDepthAttachment = &depth;
  vkCmdBeginRendering(cmd, &rendering);
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline(false, depthClamp));
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertexBuffer, &offset);
  vkCmdBindIndexBuffer(cmd, scene.indices.get(), 0, VK_INDEX_TYPE_UINT32);
  for (const DrawItem* draw : casters) {
    glm::mat4 objectToClip = worldToLightClip * objectTransforms[size_t(draw->constants.object.x)];
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(objectToClip),
                       &objectToClip);
    vkCmdDrawIndexed(cmd, draw->indexCount, 1, draw->firstIndex, draw->vertexOffset, 0);
  }
  vkCmdEndRendering(cmd);

  // Scope 2: what every crossing passes, multiplied together (1: nothing crossed).
  VkRenderingAttachmentInfo colour{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  colour.imageView = transmittanceViews_[layer];
  colour.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  colour.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  colour.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  colour.clearValue.color = {{1.0f, 1.0f, 1.0f, 1.0f}};
  rendering.pColorAttachments = &colour;
  rendering.pDepthAttachment = nullptr;
  vkCmdBeginRendering(cmd, &rendering);
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertexBuffer, &offset);
  vkCmdBindIndexBuffer(cmd, scene.indices.get(), 0, VK_INDEX_TYPE_UINT32);
  glm::mat4 worldToLight = worldToLightFrame(light);
  std::optional<bool> texturedBound;
  for (const DrawItem* draw : casters) {
    const glm::mat4& objectToWorld = objectTransforms[size_t(draw->constants.object.x)];
    const gpu::DrawConstants& constants = draw->constants;
    bool textured = isBlendedTextureCaster(*draw);
    if (texturedBound != textured) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                        translucentPipeline(depthClamp, textured));
      texturedBound = textured;
    }
    if (textured) {
      // Each texel passes 1 - its coverage, kd.w times its alpha.
      assert(draw->material < materialSets.size() && "textured caster without its material set");
      VkDescriptorSet set = materialSets[draw->material];
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, maskedLayout_, 0, 1, &set, 0,
                              nullptr);
      MaskedShadowDraw push{worldToLightClip * objectToWorld,
                            glm::vec4(constants.texturing.x, constants.texturing.y, constants.kd.w,
                                      constants.texturing.w),
                            constants.diffuseUv};
      vkCmdPushConstants(cmd, maskedLayout_,
                         VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(push),
                         &push);
      vkCmdDrawIndexed(cmd, draw->indexCount, 1, draw->firstIndex, draw->vertexOffset, 0);
      continue;
    }
    TranslucentShadowDraw push{worldToLightClip * objectToWorld, worldToLight * objectToWorld};
    // The affine map's free last row: kt, ior, Fresnel (not for coverage
    // materials, whose optics.y is 0), point light.
    float kt = 1.0f - constants.kd.w;
    glm::vec4 packed(kt, constants.optics.z, constants.optics.y > 0.0f ? 1.0f : 0.0f,
                     light.w != 0.0f ? 1.0f : 0.0f);
    for (int column = 0; column < 4; ++column) push.objectToLight[column][3] = packed[column];
    vkCmdPushConstants(cmd, translucentLayout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(push), &push);
    vkCmdDrawIndexed(cmd, draw->indexCount, 1, draw->firstIndex, draw->vertexOffset, 0);
  }
  vkCmdEndRendering(cmd);
}

}  // namespace shadelab
