#include "passes/renderer.h"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <cstring>
#include <glm/gtc/packing.hpp>

#include "core/base/errors.h"
#include "core/base/split_screen.h"
#include "core/scene/frustum.h"
#include "core/scene/lod.h"
#include "core/vulkan/barriers.h"
#include "core/vulkan/vk_check.h"

namespace shadelab {
static_assert(BillboardPass::kFrameSlots == Renderer::kFramesInFlight);
namespace {

double nowMs() {
  using Clock = std::chrono::steady_clock;
  return std::chrono::duration<double, std::milli>(Clock::now().time_since_epoch()).count();
}

}  // namespace

ImageRgba unpackHalfImage(const void* data, uint32_t width, uint32_t height) {
  ImageRgba image(width, height);
  const auto* texels = static_cast<const uint64_t*>(data);
  for (size_t p = 0; p < size_t(width) * height; ++p) {
    glm::vec4 value = glm::unpackHalf4x16(texels[p]);
    std::memcpy(&image.pixels[p * 4], &value, sizeof(value));
  }
  return image;
}

Renderer::Renderer(const Context& context)
    : context_(context),
      forward_(context, kColorFormat, lightSets_),
      textures_(context, forward_.materialSetLayout()),
      skybox_(context, kColorFormat, forward_.descriptorSetLayout()),
      shadow_(context, forward_.materialSetLayout()),
      billboards_(context, kColorFormat, forward_.descriptorSetLayout(),
                  forward_.materialSetLayout(), lightSets_),
      impostors_(context),
      environmentBuilder_(context),
      placeholderEnvironment_(environmentBuilder_.placeholder()) {
  VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 2 * kFramesInFlight},
                                  {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kFramesInFlight},
                                  {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4 * kFramesInFlight}};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = kFramesInFlight;
  poolInfo.poolSizeCount = uint32_t(std::size(sizes));
  poolInfo.pPoolSizes = sizes;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorPool(context.device(), &poolInfo, nullptr, &pool));
  descriptorPool_ = DescriptorPool(context.device(), pool);
  for (Frame& frame : frames_) createFrame(frame);
  lastCompletion_ = nowMs();
}

Renderer::~Renderer() {
  vkDeviceWaitIdle(context_.device());
}

void Renderer::createFrame(Frame& frame) {
  VkDevice device = context_.device();
  CommandBufferPool commands = createCommandBuffer(context_, VK_COMMAND_POOL_CREATE_TRANSIENT_BIT);
  frame.pool = std::move(commands.pool);
  frame.cmd = commands.cmd;
  frame.fence = createFence(device);

  VkQueryPoolCreateInfo queryInfo{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  queryInfo.queryType = VK_QUERY_TYPE_TIMESTAMP;
  // Scene start, scene end, end of the command buffer, end of the shadow pass.
  queryInfo.queryCount = 4;
  VkQueryPool queries = VK_NULL_HANDLE;
  VK_CHECK(vkCreateQueryPool(device, &queryInfo, nullptr, &queries));
  frame.timestamps = QueryPool(device, queries);

  frame.frameData = Buffer(context_, sizeof(gpu::FrameData), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                           MemoryUse::HostVisible);
  VkDescriptorSetLayout layout = forward_.descriptorSetLayout();
  VkDescriptorSetAllocateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  setInfo.descriptorPool = descriptorPool_;
  setInfo.descriptorSetCount = 1;
  setInfo.pSetLayouts = &layout;
  VK_CHECK(vkAllocateDescriptorSets(device, &setInfo, &frame.set));
  frame.shadowData = Buffer(context_, sizeof(gpu::ShadowData), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                            MemoryUse::HostVisible);
  // Every binding is written now: lavapipe crashes on never-written descriptors.
  ensureObjectCapacity(frame, 64);
  writeEnvironmentDescriptor(frame);
  writeShadowMapDescriptor(frame);
  VkDescriptorBufferInfo shadowInfo{frame.shadowData.get(), 0, VK_WHOLE_SIZE};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = frame.set;
  write.dstBinding = BINDING_SHADOWS;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  write.pBufferInfo = &shadowInfo;
  vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
}

// One combined image sampler of a frame's set (the shadow map, the environment cube).
void Renderer::writeSampledImage(const Frame& frame, uint32_t binding, VkSampler sampler,
                                 VkImageView view) const {
  VkDescriptorImageInfo image{sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = frame.set;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  write.pImageInfo = &image;
  vkUpdateDescriptorSets(context_.device(), 1, &write, 0, nullptr);
}

void Renderer::writeShadowMapDescriptor(const Frame& frame) const {
  writeSampledImage(frame, BINDING_SHADOW_MAP, shadow_.sampler(), shadow_.view());
  writeSampledImage(frame, BINDING_OPAQUE_SHADOW_MAP, shadow_.sampler(), shadow_.opaqueDepthView());
  writeSampledImage(frame, BINDING_TRANSMITTANCE, shadow_.transmittanceSampler(),
                    shadow_.transmittanceView());
}

void Renderer::writeEnvironmentDescriptor(const Frame& frame) const {
  const EnvironmentCube& cube = sceneEnvironment_ ? sceneEnvironment_ : placeholderEnvironment_;
  writeSampledImage(frame, BINDING_ENVIRONMENT, cube.sampler.get(), cube.image.view());
}

void Renderer::bindEnvironment(const Scene& scene, bool enabled) {
  bool wanted = enabled && scene.environment.present();
  if (wanted && sceneEnvironment_ && sceneEnvironmentSource_ == scene.environment) return;
  EnvironmentCube previous = std::move(sceneEnvironment_);
  sceneEnvironmentSource_ = wanted ? scene.environment : Environment{};
  if (wanted) sceneEnvironment_ = environmentBuilder_.build(scene.environment);
  // Re-point the descriptors before the previous cube's view is destroyed.
  for (const Frame& frame : frames_) writeEnvironmentDescriptor(frame);
}

void Renderer::ensureObjectCapacity(Frame& frame, uint32_t count) {
  if (count <= frame.objectCapacity) return;
  frame.objectCapacity = std::max(count, frame.objectCapacity * 2);
  frame.objectData = Buffer(context_, VkDeviceSize(frame.objectCapacity) * sizeof(gpu::ObjectData),
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::HostVisible);
  VkDescriptorBufferInfo frameInfo{frame.frameData.get(), 0, VK_WHOLE_SIZE};
  VkDescriptorBufferInfo objectInfo{frame.objectData.get(), 0, VK_WHOLE_SIZE};
  VkWriteDescriptorSet writes[2] = {{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET},
                                    {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}};
  writes[0].dstSet = frame.set;
  writes[0].dstBinding = BINDING_FRAME;
  writes[0].descriptorCount = 1;
  writes[0].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  writes[0].pBufferInfo = &frameInfo;
  writes[1] = writes[0];
  writes[1].dstBinding = BINDING_OBJECTS;
  writes[1].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  writes[1].pBufferInfo = &objectInfo;
  vkUpdateDescriptorSets(context_.device(), 2, writes, 0, nullptr);
}

void Renderer::checkDepthSupport(DepthMode mode) const {
  VkFormatProperties properties;
  vkGetPhysicalDeviceFormatProperties(context_.physicalDevice(), depthFormat(mode), &properties);
  if (!(properties.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT))
    throw InputError("depth '" + std::string(depthModeName(mode)) + "': this device (" +
                     context_.properties().deviceName + ") cannot render to " +
                     std::string(depthFormatName(mode)) + " depth; choose another --depth");
}

void Renderer::ensureTarget(uint32_t width, uint32_t height, TargetLayout layout) {
  TargetShape shape{width, height, layout};
  if (shape == targetShape_) return;
  // Frames in flight may still draw into the old images.
  if (std::any_of(targets_.begin(), targets_.end(), [](const Target& t) { return bool(t.color); }))
    context_.waitIdle();
  targets_ = {};
  targetShape_ = shape;
}

Renderer::Target& Renderer::frameTarget() {
  Target& target = targets_[frameSlot()];
  if (target.color) return target;
  const TargetShape& shape = targetShape_;
  uint32_t samples = shape.layout.samples;
  ImageDesc color{kColorFormat, shape.width, shape.height};
  color.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  target.color = Image(context_, color);
  ImageDesc depth{depthFormat(shape.layout.depth), shape.width, shape.height};
  depth.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  depth.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
  depth.samples = VkSampleCountFlagBits(samples);
  target.depth = Image(context_, depth);
  if (samples > 1) {
    ImageDesc multisampled = color;
    multisampled.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    multisampled.samples = VkSampleCountFlagBits(samples);
    target.multisampled = Image(context_, multisampled);
  }
  return target;
}

void Renderer::retire(Frame& frame, RenderStats& stats) {
  if (!frame.pending) return;
  VkFence fence = frame.fence;
  VK_CHECK(vkWaitForFences(context_.device(), 1, &fence, VK_TRUE, UINT64_MAX));
  double completion = nowMs();
  // Queries 0 and 1 are always written; 2 and 3 only when something was
  // recorded for them (recordScene and submitFrame say why). An unwritten
  // query reads as the scene's end (2) or its start (3).
  uint64_t ticks[4] = {};
  for (uint32_t query = 0; query < 4; ++query)
    if (frame.writtenTimestamps & (1u << query))
      VK_CHECK(vkGetQueryPoolResults(context_.device(), frame.timestamps, query, 1,
                                     sizeof(uint64_t), &ticks[query], sizeof(uint64_t),
                                     VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  if (!(frame.writtenTimestamps & (1u << 2))) ticks[2] = ticks[1];
  if (!(frame.writtenTimestamps & (1u << 3))) ticks[3] = ticks[0];
  double period = context_.properties().limits.timestampPeriod;  // ns per tick
  stats.deviceMs.push_back(double(ticks[1] - ticks[0]) * period * 1e-6);
  stats.frameDeviceMs.push_back(double(ticks[2] - ticks[0]) * period * 1e-6);
  stats.shadowMs.push_back(double(ticks[3] - ticks[0]) * period * 1e-6);
  stats.wallMs.push_back(completion - lastCompletion_);
  lastCompletion_ = completion;
  frame.pending = false;
}

void Renderer::beginRendering(VkCommandBuffer cmd, const Scene& source, uint32_t width,
                              uint32_t height) {
  Target& target = frameTarget();
  // The slot's images were last drawn by the frame kFramesInFlight before,
  // whose fence beginFrame's caller waited on: while they are still
  // attachments, that wait orders this frame's writes after its writes and
  // no barrier is recorded. lavapipe flushes its rasteriser at every barrier,
  // and the one a shared target needs here cost ~6% of a frame on glmark2's
  // cat (docs/PERFORMANCE.md).
  auto attach = [cmd](const Image& image, VkImageAspectFlags aspect, ImageUse& use,
                      ImageUse attachment) {
    if (use != attachment) imageBarrier(cmd, image.get(), aspect, use, attachment);
    use = attachment;
  };
  attach(target.color, VK_IMAGE_ASPECT_COLOR_BIT, target.colorUse, ImageUse::ColorAttachment);
  attach(target.depth, VK_IMAGE_ASPECT_DEPTH_BIT, target.depthUse, ImageUse::DepthAttachment);
  bool multisampled = targetShape_.layout.samples > 1;
  if (multisampled)
    attach(target.multisampled, VK_IMAGE_ASPECT_COLOR_BIT, target.multisampledUse,
           ImageUse::ColorAttachment);
  VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  color.imageView = multisampled ? target.multisampled.view() : target.color.view();
  color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  // With MSAA the samples are averaged into the single-sampled image and dropped.
  color.storeOp = multisampled ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
  if (multisampled) {
    color.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
    color.resolveImageView = target.color.view();
    color.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  }
  color.clearValue.color = {{source.background.r, source.background.g, source.background.b, 1.0f}};
  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  depth.imageView = target.depth.view();
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.clearValue.depthStencil = {depthClearValue(targetShape_.layout.depth), 0};
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, {width, height}};
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachments = &color;
  rendering.pDepthAttachment = &depth;
  vkCmdBeginRendering(cmd, &rendering);
}

GpuScene Renderer::upload(const Scene& scene, const SceneUploadOptions& options) {
  context_.waitIdle();
  ++uploadCount_;
  settingsApplied_ = false;  // the material sets and pipelines depend on the scene
  GpuScene gpuScene = uploadScene(context_, scene, options.detailChains);
  if (options.detailChains)
    impostors_.addImpostors(scene, gpuScene, options.impostorCells, kImpostorCellTexels);
  drawnLevels_.assign(scene.objects.size(), kNoLevel);
  textures_.upload(scene, gpuScene);
  billboards_.upload(gpuScene);
  bindEnvironment(scene, options.environmentCube);
  return gpuScene;
}

void Renderer::validate(const GpuScene& scene, const FrameSettings& settings) const {
  uint32_t maxSize = context_.properties().limits.maxImageDimension2D;
  if (settings.width == 0 || settings.height == 0 || settings.width > maxSize ||
      settings.height > maxSize)
    throw InputError("size " + std::to_string(settings.width) + "x" +
                     std::to_string(settings.height) + ": width and height must be 1.." +
                     std::to_string(maxSize));
  if (settings.msaaSamples != 1 && settings.msaaSamples != 4)
    throw InputError("msaa " + std::to_string(settings.msaaSamples) + ": expected 1 or 4");
  if (settings.splitModels.size() > settings.width)
    throw InputError("split screen: more views than pixel columns");
  checkDepthSupport(settings.depth);
  if (settings.shadows != ShadowMethod::Off) {
    if (settings.shadowMapSize == 0 || settings.shadowMapSize > maxSize)
      throw InputError("--shadow-size " + std::to_string(settings.shadowMapSize) +
                       ": expected 1.." + std::to_string(maxSize) +
                       " (this device's largest 2D image)");
    uint32_t maxLayers = context_.properties().limits.maxImageArrayLayers;
    if (scene.shadowLayers > maxLayers)
      throw InputError("shadows: the scene's lights need " + std::to_string(scene.shadowLayers) +
                       " shadow-map layers, this device offers " + std::to_string(maxLayers));
    const ShadowBias& bias = settings.shadowBias;
    for (auto [name, value] :
         {std::pair{"--shadow-bias", bias.constant}, std::pair{"--shadow-slope-bias", bias.slope},
          std::pair{"--shadow-normal-offset", bias.normalOffset}})
      if (!(value >= 0.0f && value <= kMaxShadowBias))
        throw InputError(std::string(name) + " " + std::to_string(value) + ": expected 0.." +
                         std::to_string(int(kMaxShadowBias)) + " texels");
  }
  if (scene.anyTextured || !scene.billboards.empty())
    textures_.checkFilter(settings.textures.filterOverride);
}

void Renderer::applyFrameSettings(const GpuScene& scene, const FrameSettings& settings) {
  validate(scene, settings);  // every InputError before anything changes
  bool billboards = !scene.billboards.empty();
  if (scene.anyTextured || billboards) textures_.prepareFilter(settings.textures.filterOverride);
  ForwardFrame forward = forwardFrame(scene, settings);
  if (forward.shadows != ShadowMethod::Off) {
    if (shadow_.prepare(scene.shadowLayers, settings.shadowMapSize, forward.translucentShadows)) {
      context_.waitIdle();  // no frame in flight may hold the descriptors being re-pointed
      for (const Frame& frame : frames_) writeShadowMapDescriptor(frame);
    }
    // Its code compiles on the queue's thread while this one builds the
    // forward pipelines (the first frame of `render default` waited for it).
    shadow_.warmUp(settings.shadowDepthClamp);
  } else if (shadow_.release()) {
    // Without shadows the map's memory is given back (a bench row without
    // shadows after one with them reported the maps), and the frames' sets
    // point at the placeholder until a later setting wants a map again.
    for (const Frame& frame : frames_) writeShadowMapDescriptor(frame);
  }
  settings_ = settings;
  compiledLights_.reset();
  lightsMoved_ = false;
  preparedWithLights_.reset();
  // With light constants the first frame's values are not known yet:
  // compileLights builds the pipelines then.
  if (!settings.lightConstants) preparePipelines(scene, forward);
  TargetLayout layout = forward.target;
  if (forward.environment) skybox_.prepare(layout);
  ensureTarget(settings.width, settings.height, layout);
  settingsApplied_ = true;
}

void Renderer::preparePipelines(const GpuScene& scene, const ForwardFrame& forward) {
  std::vector<ShadingModel> models = settings_.splitModels;
  if (models.empty()) models.push_back(settings_.shadingModel);
  forward_.prepare(scene, models, forward, settings_.wireframe);
  if (!scene.billboards.empty()) billboards_.prepare(scene, models, forward);
  preparedWithLights_ = forward.lightSet != 0;
}

void Renderer::compileLights(const GpuScene& scene, const gpu::FrameData& frameData,
                             ForwardFrame& forward) {
  if (!lightsMoved_) {
    LightValues values = lightValuesOf(frameData);
    if (!compiledLights_) compiledLights_ = values;
    if (*compiledLights_ == values)
      forward.lightSet = lightSets_.intern(values);
    else
      lightsMoved_ = true;  // a pipeline set per frame would cost more than it saves
  }
  if (preparedWithLights_ != (forward.lightSet != 0)) preparePipelines(scene, forward);
}

ForwardFrame Renderer::forwardFrame(const GpuScene& scene, const FrameSettings& settings) const {
  // No map to draw: the variants without shadows (the images of before them).
  bool shadowed = settings.shadows != ShadowMethod::Off && scene.shadowLayers > 0;
  return {.target = {settings.msaaSamples, settings.depth},
          .environment = settings.environment && sceneEnvironment_,
          .shadows = shadowed ? settings.shadows : ShadowMethod::Off,
          .translucentShadows = shadowed && ShadowPass::anyTranslucentCaster(scene.draws),
          .bump = settings.textures.bump,
          .mipTint = settings.textures.mipTint,
          .materialConstants = settings.materialConstants &&
                               ForwardPass::materialCount(scene) <= kMaxMaterialPipelines,
          .impostorBlend = settings.impostorBlend};
}

void Renderer::waitForFrame(RenderStats& stats) {
  retire(frames_[frameIndex_ % kFramesInFlight], stats);
}

VkCommandBuffer Renderer::beginFrame() {
  Frame& frame = frames_[frameIndex_ % kFramesInFlight];
  assert(!frame.pending && "waitForFrame() first");
  frame.writtenTimestamps = 0;
  frame.commandsAfterScene = false;
  VK_CHECK(vkResetCommandPool(context_.device(), frame.pool, 0));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(frame.cmd, &begin));
  return frame.cmd;
}

void Renderer::recordScene(const GpuScene& scene, const Scene& source, RenderStats& stats) {
  assert(settingsApplied_ && "applyFrameSettings() after upload(), before recording");
  const FrameSettings& settings = settings_;
  Frame& frame = frames_[frameIndex_ % kFramesInFlight];
  uint32_t width = settings.width, height = settings.height;
  glm::mat4 view = source.camera.viewMatrix();
  float viewAspect =
      float(width) / float(std::max<size_t>(1, settings.splitModels.size())) / float(height);
  glm::mat4 projection = source.camera.projectionMatrix(viewAspect, isReversedZ(settings.depth));
  gpu::FrameData frameData = makeFrameData(source, view, projection);
  std::memcpy(frame.frameData.mapped(), &frameData, sizeof(frameData));
  std::vector<gpu::ObjectData> objects = makeObjectData(source, view, settings.normalTransform);
  std::vector<DrawItem> draws = visibleDraws(scene, view, projection, settings.frustumCulling,
                                             settings.frontToBack, stats.culledDraws);
  stats.coarserDraws = 0;
  stats.impostors = 0;
  std::vector<ImpostorCopy> impostors;
  if (settings.lod) chooseLevels(scene, source, draws, impostors, stats);
  if (settings.instancing) batchInstances(draws, objects);
  ensureObjectCapacity(frame, uint32_t(objects.size()));
  stats.drawCalls = uint32_t(draws.size());
  stats.triangles = 0;
  for (const DrawItem& draw : draws)
    stats.triangles += uint64_t(draw.indexCount / 3) * draw.instanceCount;
  // A scene without objects has no data (objects.data() may be null, which
  // memcpy forbids even for zero bytes: UBSan reported it).
  if (!objects.empty())
    std::memcpy(frame.objectData.mapped(), objects.data(), objects.size() * sizeof(objects[0]));
  ForwardFrame forwardFrame = this->forwardFrame(scene, settings);
  forwardFrame.frameSet = frame.set;
  if (settings.lightConstants) compileLights(scene, frameData, forwardFrame);
  bool shadowed = forwardFrame.shadows != ShadowMethod::Off;
  if (scene.anyTextured || !scene.billboards.empty())
    forwardFrame.materialSets = textures_.materialSets(settings.textures.filterOverride);
  BillboardFrame billboards;
  if (!scene.billboards.empty()) {
    BillboardTrim trim{settings.trimBillboards && settings.msaaSamples == 1,
                       settings.textures.filterOverride,
                       std::abs(projection[1][1]) * 0.5f * float(settings.height)};
    billboards =
        billboards_.prepareFrame(frameSlot(), scene, view, projection, settings.frustumCulling,
                                 trim, impostors, settings.impostorBlend);
    stats.billboardInstances = billboards.instances;
    stats.culledInstances = billboards.culled;
    stats.trimmedInstances = billboards.trimmed;
    stats.triangles += 2 * uint64_t(billboards.instances) - billboards.trimmed;
    stats.drawCalls += uint32_t(billboards.cutOut.size());
  }

  VkCommandBuffer cmd = frame.cmd;
  vkCmdResetQueryPool(cmd, frame.timestamps, 0, 4);
  // lavapipe flushes its rasteriser at every timestamp written after
  // TOP_OF_PIPE, and each flush costs ~0.2 ms even with nothing to draw
  // (docs/PERFORMANCE.md): the shadow maps' end is timed only when maps
  // were drawn, and what follows the scene only when something does.
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, frame.timestamps, 0);
  frame.writtenTimestamps = 0b11;
  stats.shadowDraws = 0;
  if (shadowed) recordShadows(cmd, frame, scene, source, view, projection, stats);
  if (stats.shadowDraws > 0) {
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, frame.timestamps, 3);
    frame.writtenTimestamps |= 1u << 3;
  }

  beginRendering(cmd, source, width, height);
  // Split screen: equal columns, one shading model each, one camera.
  std::vector<ShadingModel> models = settings.splitModels;
  if (models.empty()) models.push_back(settings.shadingModel);
  std::vector<ScreenColumn> columns = splitColumns(width, uint32_t(models.size()));
  for (size_t i = 0; i < models.size(); ++i) {
    VkViewport viewport{float(columns[i].left), 0.0f, float(columns[i].width),
                        float(height),          0.0f, 1.0f};
    // Opaque draws, the skybox where they left the far plane, then the
    // transparent draws, which write no depth, over both.
    auto firstTransparent = std::find_if(draws.begin(), draws.end(),
                                         [](const DrawItem& draw) { return draw.transparent; });
    std::span<const DrawItem> opaque(draws.begin(), firstTransparent);
    std::span<const DrawItem> transparent(firstTransparent, draws.end());
    forward_.record(cmd, models[i], forwardFrame, scene, opaque, viewport);
    billboards_.record(cmd, frameSlot(), models[i], forwardFrame, scene, billboards.cutOut,
                       viewport);
    if (forwardFrame.environment)
      skybox_.record(cmd, targetShape_.layout, frame.set, view, projection, viewport);
    if (!billboards.blended.empty())
      recordTransparent(cmd, models[i], forwardFrame, scene, transparent, billboards, view,
                        viewport);
    else if (!transparent.empty())
      forward_.record(cmd, models[i], forwardFrame, scene, transparent, viewport);
    if (settings.wireframe) forward_.recordWireframe(cmd, forwardFrame, scene, draws, viewport);
  }
  vkCmdEndRendering(cmd);
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, frame.timestamps, 1);
}

void Renderer::recordTransparent(VkCommandBuffer cmd, ShadingModel model,
                                 const ForwardFrame& forwardFrame, const GpuScene& scene,
                                 std::span<const DrawItem> transparent,
                                 const BillboardFrame& billboards, const glm::mat4& view,
                                 const VkViewport& viewport) const {
  // Both lists are back to front (visibleDraws' key for the meshes); merged
  // by that key, meshes first on a tie, each run of one kind recorded at once.
  auto meshDepth = [&](size_t i) {
    return (view * glm::vec4(centre(transparent[i].worldBounds), 1.0f)).z;
  };
  std::span<const BillboardDraw> blended = billboards.blended;
  size_t mesh = 0, quad = 0;
  while (mesh < transparent.size() || quad < blended.size()) {
    size_t meshEnd = mesh;
    while (meshEnd < transparent.size() &&
           (quad == blended.size() || meshDepth(meshEnd) <= blended[quad].depth))
      ++meshEnd;
    if (meshEnd > mesh)
      forward_.record(cmd, model, forwardFrame, scene, transparent.subspan(mesh, meshEnd - mesh),
                      viewport);
    mesh = meshEnd;
    size_t quadEnd = quad;
    while (quadEnd < blended.size() &&
           (mesh == transparent.size() || blended[quadEnd].depth < meshDepth(mesh)))
      ++quadEnd;
    billboards_.record(cmd, frameSlot(), model, forwardFrame, scene,
                       blended.subspan(quad, quadEnd - quad), viewport);
    quad = quadEnd;
  }
}

void Renderer::chooseLevels(const GpuScene& scene, const Scene& source,
                            std::vector<DrawItem>& draws, std::vector<ImpostorCopy>& impostors,
                            RenderStats& stats) {
  double start = nowMs();
  stats.levelDraws.fill(0);
  ViewSize view{source.camera, settings_.width, settings_.height};
  std::vector<float> projected;
  for (DrawItem& draw : draws) {
    if (draw.levelCount == 0) continue;
    uint32_t& drawn = drawnLevels_[uint32_t(draw.constants.object.x)];
    drawn = chooseDrawLevel(scene.levels, draw, view, drawn, settings_.lodErrorPixels,
                            settings_.lodHysteresis, projected);
    ++stats.levelDraws[std::min<size_t>(drawn, stats.levelDraws.size() - 1)];
    if (drawn == 0) continue;
    ++stats.coarserDraws;
    uint32_t impostor = scene.levels[draw.firstLevel + drawn - 1].impostor;
    if (impostor != DrawLevel::kNoImpostor) {
      uint32_t object = uint32_t(draw.constants.object.x);
      impostors.push_back({impostor, source.objects[object].transform});
      draw.indexCount = 0;  // leaves the list below
      ++stats.impostors;
      continue;
    }
    applyLevel(scene, draw, drawn);
  }
  if (stats.impostors > 0)
    draws.erase(std::remove_if(draws.begin(), draws.end(),
                               [](const DrawItem& draw) { return draw.indexCount == 0; }),
                draws.end());
  stats.lodSelectMs = nowMs() - start;
}

void Renderer::applyLevel(const GpuScene& scene, DrawItem& draw, uint32_t level) {
  if (level == 0 || level > draw.levelCount) return;  // kNoLevel too: in full
  if (scene.levels[draw.firstLevel + level - 1].impostor != DrawLevel::kNoImpostor) --level;
  if (level == 0) return;
  const DrawLevel& range = scene.levels[draw.firstLevel + level - 1];
  draw.firstIndex = range.firstIndex;
  draw.indexCount = range.indexCount;
  draw.vertexOffset = range.vertexOffset;
}

void Renderer::recordShadows(VkCommandBuffer cmd, Frame& frame, const GpuScene& scene,
                             const Scene& source, const glm::mat4& view,
                             const glm::mat4& projection, RenderStats& stats) {
  // The map is fitted to the camera's view: with split columns, the whole frame's.
  ShadowFrame shadows = makeShadowFrame(source, scene, view, projection, settings_.shadowBias,
                                        settings_.shadowMapSize);
  std::memcpy(frame.shadowData.mapped(), &shadows.data, sizeof(shadows.data));
  std::vector<glm::mat4> transforms;
  transforms.reserve(source.objects.size());
  for (const Object& object : source.objects) transforms.push_back(object.transform);
  // Casters at the level the view draws them (objects out of view: their
  // last one), so a simplified surface is not shadowed by its full self.
  std::span<const DrawItem> casters = scene.draws;
  std::vector<DrawItem> levelled;  // a copy only when levels may differ
  if (settings_.lod) {
    levelled = scene.draws;
    for (DrawItem& draw : levelled)
      applyLevel(scene, draw, drawnLevels_[uint32_t(draw.constants.object.x)]);
    casters = levelled;
  }
  stats.shadowDraws =
      shadow_.record(cmd, scene, casters, uploadCount_, transforms, shadows.worldToLightClip,
                     shadows.layerLights, textures_.materialSets(settings_.textures.filterOverride),
                     settings_.keepShadowMaps, settings_.shadowDepthClamp);
}

void Renderer::recordReadback(const Buffer& readback) {
  VkCommandBuffer cmd = commandBuffer();
  Target& target = targets_[frameSlot()];
  assert(target.color && "recordScene() first");
  const ImageDesc& desc = target.color.desc();
  assert(readback.size() >= VkDeviceSize(desc.width) * desc.height * 8);
  frames_[frameIndex_ % kFramesInFlight].commandsAfterScene = true;
  imageBarrier(cmd, target.color.get(), VK_IMAGE_ASPECT_COLOR_BIT, target.colorUse,
               ImageUse::TransferSource);
  target.colorUse = ImageUse::TransferSource;
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {desc.width, desc.height, 1};
  vkCmdCopyImageToBuffer(cmd, target.color.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         readback.get(), 1, &region);
  transferToHostBarrier(cmd);
}

void Renderer::submitFrame(const FrameSync& sync) {
  Frame& frame = frames_[frameIndex_ % kFramesInFlight];
  if (frame.commandsAfterScene || sync.commandsAfterScene) {
    vkCmdWriteTimestamp2(frame.cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, frame.timestamps, 2);
    frame.writtenTimestamps |= 1u << 2;
  }
  VK_CHECK(vkEndCommandBuffer(frame.cmd));
  VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cmdInfo.commandBuffer = frame.cmd;
  VkSemaphoreSubmitInfo waitInfo{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  waitInfo.semaphore = sync.wait;
  waitInfo.stageMask = sync.waitStage;
  VkSemaphoreSubmitInfo signalInfo{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  signalInfo.semaphore = sync.signal;
  signalInfo.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.waitSemaphoreInfoCount = sync.wait ? 1 : 0;
  submit.pWaitSemaphoreInfos = &waitInfo;
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cmdInfo;
  submit.signalSemaphoreInfoCount = sync.signal ? 1 : 0;
  submit.pSignalSemaphoreInfos = &signalInfo;
  VkFence fence = frame.fence;
  VK_CHECK(vkResetFences(context_.device(), 1, &fence));
  VK_CHECK(vkQueueSubmit2(context_.queue(), 1, &submit, fence));
  frame.pending = true;
  ++frameIndex_;
}

void Renderer::finishFrames(RenderStats& stats) {
  // Oldest first, so the per-frame timings stay in submission order.
  for (uint32_t i = 0; i < kFramesInFlight; ++i)
    retire(frames_[(frameIndex_ + i) % kFramesInFlight], stats);
}

std::vector<ShaderVariant> Renderer::shaderVariants() {
  return ForwardPass::shaderVariants();
}

void Renderer::reloadShaders(const std::map<std::string, std::vector<uint32_t>>& spirv) {
  context_.waitIdle();  // pending frames use the old pipelines
  forward_.reloadShaders(spirv);
}

RenderResult Renderer::renderToImage(const Scene& scene, const RenderSettings& settings) {
  if (settings.frames == 0) throw InputError("frames: expected at least 1");
  // A cube the settings would not draw is not built.
  GpuScene gpuScene = upload(scene, {.environmentCube = settings.environment,
                                     .detailChains = settings.lod,
                                     .impostorCells = settings.impostorCells});
  applyFrameSettings(gpuScene, settings);
  Buffer readback(context_, VkDeviceSize(settings.width) * settings.height * 8,
                  VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::HostVisible);

  RenderResult result;
  lastCompletion_ = nowMs();
  for (uint32_t i = 0; i < settings.frames; ++i) {
    waitForFrame(result.stats);
    beginFrame();
    recordScene(gpuScene, scene, result.stats);
    if (i + 1 == settings.frames) recordReadback(readback);
    submitFrame();
  }
  finishFrames(result.stats);
  // Sampled after the frames: the targets and shadow maps are made (or
  // remade for these settings) when the first frame is recorded.
  result.stats.deviceMemoryBytes = deviceMemoryInUse();
  if (settings.srgb8)
    result.srgb8 = encodeSrgb8FromHalf(static_cast<const uint16_t*>(readback.mapped()),
                                       settings.width, settings.height);
  else
    result.image = unpackHalfImage(readback.mapped(), settings.width, settings.height);
  return result;
}

RenderStats Renderer::renderSequence(const Scene& scene, const FrameSettings& settings,
                                     const std::vector<Camera>& cameras,
                                     const std::function<void(uint32_t, ImageRgba&&)>& onFrame) {
  GpuScene gpuScene = upload(scene, {.environmentCube = settings.environment,
                                     .detailChains = settings.lod,
                                     .impostorCells = settings.impostorCells});
  applyFrameSettings(gpuScene, settings);
  Buffer readback(context_, VkDeviceSize(settings.width) * settings.height * 8,
                  VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::HostVisible);
  RenderStats stats;
  Scene moving = scene;  // only its camera changes
  lastCompletion_ = nowMs();
  for (uint32_t i = 0; i < cameras.size(); ++i) {
    moving.camera = cameras[i];
    waitForFrame(stats);
    beginFrame();
    recordScene(gpuScene, moving, stats);
    recordReadback(readback);
    submitFrame();
    // One readback buffer: this frame is read before the next is recorded.
    finishFrames(stats);
    stats.deviceMemoryBytes = std::max(stats.deviceMemoryBytes, deviceMemoryInUse());
    onFrame(i, unpackHalfImage(readback.mapped(), settings.width, settings.height));
  }
  return stats;
}

}  // namespace shadelab
