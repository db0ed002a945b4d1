#include "passes/billboard_pass.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cstring>
#include <glm/gtc/packing.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/base/radix_sort.h"
#include "core/scene/frustum.h"
#include "core/scene/impostor.h"
#include "core/vulkan/depth.h"
#include "core/vulkan/shader.h"
#include "core/vulkan/vk_check.h"
#include "interface.h"
#include "passes/graphics_pipeline.h"

namespace shadelab {

BillboardPass::BillboardPass(const Context& context, VkFormat colorFormat,
                             VkDescriptorSetLayout frameSetLayout,
                             VkDescriptorSetLayout materialSetLayout, const LightSets& lightSets)
    : context_(context), colorFormat_(colorFormat), lightSets_(lightSets) {
  VkDevice device = context.device();
  VkDescriptorSetLayoutBinding binding{BINDING_BILLBOARD_INSTANCES,
                                       VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                                       VK_SHADER_STAGE_VERTEX_BIT};
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.bindingCount = 1;
  setInfo.pBindings = &binding;
  VkDescriptorSetLayout instanceLayout = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &instanceLayout));
  instanceSetLayout_ = DescriptorSetLayout(device, instanceLayout);

  // The forward pass's push constants (lighting.glsl reads the material from them).
  VkPushConstantRange push{
      VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_GEOMETRY_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
      sizeof(gpu::DrawConstants)};
  VkDescriptorSetLayout setLayouts[] = {frameSetLayout, materialSetLayout, instanceLayout};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 3;
  layoutInfo.pSetLayouts = setLayouts;
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &push;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout));
  layout_ = PipelineLayout(device, layout);
  vertex_ = loadShader(device, "billboard.vert");
  fragment_ = loadShader(device, "billboard.frag");
  // Separate modules: the blend's inputs would cost every other billboard
  // their set-up per triangle on llvmpipe, used or not.
  blendVertex_ = loadShader(device, "billboard_impostor_blend.vert");
  blendFragment_ = loadShader(device, "billboard_impostor_blend.frag");

  // One set per frame slot, sized once.
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kFrameSlots};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = kFrameSlots;
  poolInfo.poolSizeCount = 1;
  poolInfo.pPoolSizes = &size;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorPool(device, &poolInfo, nullptr, &pool));
  pool_ = DescriptorPool(device, pool);
  VkDescriptorSetLayout layouts[kFrameSlots] = {instanceLayout, instanceLayout};
  VkDescriptorSetAllocateInfo allocInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  allocInfo.descriptorPool = pool;
  allocInfo.descriptorSetCount = kFrameSlots;
  allocInfo.pSetLayouts = layouts;
  VK_CHECK(vkAllocateDescriptorSets(device, &allocInfo, sets_));
}

void BillboardPass::upload(const GpuScene& scene) {
  // Every set written, even for a scene without billboards (lavapipe crashes
  // on a bound set with an unwritten descriptor).
  VkDeviceSize bytes = VkDeviceSize(std::max(1u, scene.billboardInstances + scene.impostorDraws)) *
                       sizeof(gpu::BillboardInstance);
  for (uint32_t slot = 0; slot < kFrameSlots; ++slot) {
    if (instances_[slot] && instances_[slot].size() >= bytes) continue;
    instances_[slot] =
        Buffer(context_, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::HostVisible);
    VkDescriptorBufferInfo info{instances_[slot].get(), 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = sets_[slot];
    write.dstBinding = BINDING_BILLBOARD_INSTANCES;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    write.pBufferInfo = &info;
    vkUpdateDescriptorSets(context_.device(), 1, &write, 0, nullptr);
  }
}

BillboardPass::Variant BillboardPass::variantOf(ShadingModel model, const ForwardFrame& frame,
                                                const GpuScene& scene,
                                                const GpuBillboard& billboard) {
  // --bump off drops bump maps, not an impostor's normals (its geometry).
  bool impostor = billboard.impostor.atlas >= 0;
  uint32_t maps = appliedTextureMaps(uint32_t(billboard.constants.object.y), frame.bump || impostor,
                                     frame.mipTint);
  return {model,
          scene.lights,
          frame.target,
          frame.shadows,
          frame.translucentShadows,
          billboard.blended,
          maps,
          int(billboard.constants.optics.x),
          frame.lightSet,
          impostor && frame.impostorBlend};
}

void BillboardPass::prepare(const GpuScene& scene, std::span<const ShadingModel> models,
                            const ForwardFrame& frame) {
  for (ShadingModel model : models)
    for (const GpuBillboard& billboard : scene.billboards) {
      Variant key = variantOf(model, frame, scene, billboard);
      if (!pipelines_.count(key)) pipelines_[key] = createPipeline(key);
    }
}

Pipeline BillboardPass::createPipeline(const Variant& key) const {
  struct {
    int32_t shadingModel;
    int32_t shadowFilter;
    VkBool32 alphaMask;
    int32_t textureMaps;
    int32_t kind;
    LightSpecialization lights;
  } constants{int32_t(key.model),
              shadowSpecialization(key.shadows, key.translucentShadows),
              key.blended ? VK_FALSE : VK_TRUE,
              int32_t(key.textureMaps),
              key.kind,
              lightSpecialization(key.lights, lightSets_.find(key.lightSet))};
  using C = decltype(constants);
  std::vector<VkSpecializationMapEntry> entries = {
      {/* constantID= */ SPEC_SHADING_MODEL, offsetof(C, shadingModel), 4},
      {/* constantID= */ SPEC_SHADOW_FILTER, offsetof(C, shadowFilter), 4},
      {/* constantID= */ SPEC_ALPHA_MASK, offsetof(C, alphaMask), 4},
      {/* constantID= */ SPEC_TEXTURE_MAPS, offsetof(C, textureMaps), 4},
      {/* constantID= */ SPEC_BILLBOARD_KIND, offsetof(C, kind), 4},
  };
  appendLightEntries(entries, offsetof(C, lights));
  VkSpecializationInfo specialization{uint32_t(entries.size()), entries.data(), sizeof(constants),
                                      &constants};
  VkPipelineShaderStageCreateInfo stages[2] = {
      {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
      {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = key.impostorBlend ? blendVertex_ : vertex_;
  stages[0].pName = "main";
  stages[0].pSpecializationInfo = &specialization;
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = key.impostorBlend ? blendFragment_ : fragment_;
  stages[1].pName = "main";
  stages[1].pSpecializationInfo = &specialization;
  // No vertex buffer: the quad's corners come from gl_VertexIndex.
  VkPipelineVertexInputStateCreateInfo vertexInput{
      VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  VkPipelineRasterizationStateCreateInfo raster{
      VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  // Not culled: a cylindrical quad seen past its axis shows its back.
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{
      VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VkSampleCountFlagBits(key.target.samples);
  VkPipelineDepthStencilStateCreateInfo depth{
      VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = key.blended ? VK_FALSE : VK_TRUE;
  depth.depthCompareOp = depthCompareOp(key.target.depth);
  // "Over" with the texel's alpha, as the forward pass blends transparent draws.
  VkPipelineColorBlendAttachmentState blend{};
  blend.blendEnable = key.blended ? VK_TRUE : VK_FALSE;
  blend.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
  blend.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
  blend.colorBlendOp = VK_BLEND_OP_ADD;
  blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
  blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
  blend.alphaBlendOp = VK_BLEND_OP_ADD;
  blend.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                         VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  return createGraphicsPipeline(
      context_.device(), {stages, &vertexInput, &raster, &multisample, &depth, blend, colorFormat_,
                          depthFormat(key.target.depth), layout_});
}

gpu::BillboardInstance impostorInstance(const ImpostorAtlas& atlas, const glm::mat4& model,
                                        const glm::mat4& view, glm::vec3 eyeWorld,
                                        bool blendCells) {
  // The view direction in mesh space picks the cells.
  glm::vec3 eye(glm::inverse(model) * glm::vec4(eyeWorld, 1.0f));
  glm::vec3 towards = eye - atlas.centre;
  float length = glm::length(towards);
  glm::vec3 direction = length > 0.0f ? towards / length : glm::vec3(0.0f, 0.0f, 1.0f);
  glm::mat4 modelView = view * model;
  if (!blendCells) {
    // The cell's frame, taken to eye space, lays the quad where its image
    // was captured.
    ImpostorCell cell = impostorCell(direction, atlas.cells);
    ImpostorFrame frame = impostorFrame(impostorCellDirection(cell, atlas.cells));
    glm::vec3 right = glm::mat3(modelView) * frame.right;
    glm::vec3 up = glm::mat3(modelView) * frame.up;
    float width = 2.0f * atlas.halfSize * glm::length(right);
    float height = 2.0f * atlas.halfSize * glm::length(up);
    return {glm::vec4(glm::vec3(modelView * glm::vec4(atlas.centre, 1.0f)), width),
            glm::vec4(glm::normalize(up), height),
            glm::vec4(glm::normalize(right), float(cell.index(atlas.cells))), glm::uvec4(0u)};
  }
  ImpostorBlend blend = impostorBlend(direction, atlas.cells);
  glm::mat3 linear(modelView);
  float scale = std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])});
  glm::quat rotation = glm::normalize(glm::quat_cast(
      glm::mat3(glm::normalize(linear[0]), glm::normalize(linear[1]), glm::normalize(linear[2]))));
  return {
      glm::vec4(glm::vec3(modelView * glm::vec4(atlas.centre, 1.0f)),
                2.0f * atlas.halfSize * scale),
      glm::vec4(rotation.x, rotation.y, rotation.z, rotation.w),
      glm::vec4(float(blend.cells[0].index(atlas.cells)), float(blend.cells[1].index(atlas.cells)),
                float(blend.cells[2].index(atlas.cells)), 0.0f),
      glm::uvec4(std::bit_cast<uint32_t>(blend.weights[0]),
                 std::bit_cast<uint32_t>(blend.weights[1]),
                 std::bit_cast<uint32_t>(blend.weights[2]), 0u)};
}

namespace {

// A float's bits as an unsigned integer in the float's order (for finite
// values and infinities): the sign bit set for positives, every bit
// flipped for negatives.
uint32_t orderedBits(float value) {
  if (value == 0.0f) value = 0.0f;  // -0 and +0 compare equal: one key
  uint32_t bits = std::bit_cast<uint32_t>(value);
  return bits & 0x80000000u ? ~bits : bits | 0x80000000u;
}

uint32_t packCorners(glm::vec2 corner) {
  return glm::packHalf2x16(corner);
}

}  // namespace

BillboardFrame BillboardPass::prepareFrame(uint32_t frameSlot, const GpuScene& scene,
                                           const glm::mat4& view, const glm::mat4& projection,
                                           bool cull, const BillboardTrim& trim,
                                           std::span<const ImpostorCopy> impostors,
                                           bool impostorBlend) {
  assert(frameSlot < kFrameSlots && instances_[frameSlot]);
  BillboardFrame result;
  Frustum frustum = frustumFromMatrix(projection * view);
  auto* out = static_cast<gpu::BillboardInstance*>(instances_[frameSlot].mapped());
  struct Blended {
    float depth;
    uint32_t billboard;
    gpu::BillboardInstance instance;
    bool trimmed;
  };
  std::vector<Blended> blended;
  glm::mat3 rotation(view);
  for (uint32_t b = 0; b < scene.billboards.size(); ++b) {
    const GpuBillboard& billboard = scene.billboards[b];
    glm::vec3 up = glm::normalize(rotation * billboard.up);
    float anchor = billboard.constants.optics.y;
    // Screen-aligned quads rise along the image's y, the others along `up` (or near it).
    glm::vec3 rise = billboard.kind == BillboardKind::Screen ? glm::vec3(0, 1, 0) : up;
    bool trims = trim.enabled && !billboard.outlines.empty() &&
                 trim.filterOverride.value_or(billboard.filter) != TextureFilter::Anisotropic;
    for (int whole = 0; whole < 2; ++whole) {
      cutOutCopies_[whole].clear();
      cutOutKeys_[whole].clear();
    }
    // Each level's outline as the vertex stage reads it, packed once here
    // rather than per copy.
    packedOutlines_.clear();
    if (trims)
      for (const std::optional<BillboardOutline>& outline : billboard.outlines)
        packedOutlines_.push_back(outline ? glm::uvec4(packCorners(outline->corners[0]),
                                                       packCorners(outline->corners[1]),
                                                       packCorners(outline->corners[2]), 1u)
                                          : glm::uvec4(0u));
    for (const BillboardPlacement& placement : billboard.instances) {
      // Any corner lies within the diagonal of the anchor, whichever way the quad turns.
      float radius = glm::length(placement.size);
      if (cull && !sphereIntersectsFrustum(placement.position, radius, frustum)) {
        ++result.culled;
        continue;
      }
      gpu::BillboardInstance instance{
          glm::vec4(glm::vec3(view * glm::vec4(placement.position, 1.0f)), placement.size.x),
          glm::vec4(up, placement.size.y), glm::vec4(0.0f), glm::uvec4(0u)};
      bool trimmed = false;
      if (trims) {
        glm::vec3 anchorEye(instance.centre);
        auto [right, quadUp] = billboardAxes(billboard.kind, anchorEye, up);
        glm::vec3 centre = anchorEye + quadUp * ((0.5f - anchor) * placement.size.y);
        uint32_t level = billboardLevelBound(
            {centre, right, quadUp, placement.size, billboard.texels, trim.focalPixels},
            uint32_t(billboard.outlines.size()));
        if (packedOutlines_[level].w) {
          instance.outline = glm::uvec4(glm::uvec3(packedOutlines_[level]), 0u);
          trimmed = true;
        }
      }
      float centreZ = instance.centre.z + rise.z * (0.5f - anchor) * placement.size.y;
      if (billboard.blended) {
        blended.push_back({centreZ, b, instance, trimmed});
      } else {
        int whole = trimmed ? 0 : 1;
        uint32_t index = uint32_t(cutOutCopies_[whole].size());
        cutOutCopies_[whole].push_back(instance);
        cutOutKeys_[whole].push_back(uint64_t(~orderedBits(centreZ)) << 32 | index);
      }
    }
    // Cut-out copies front to back (the largest eye-space z is the nearest):
    // the depth test then rejects the fragments of the trees behind before
    // their shading runs. In scatter order, the 3,000 trees of a first draft
    // of `lod` cost ~46 ms of a 1280x720 frame, front to back ~28 ms. The
    // keys sort by decreasing z, then scatter order: a stable sort's order,
    // at 8 bytes a key instead of the 64-byte copies.
    for (int whole = 0; whole < 2; ++whole) {
      std::vector<uint64_t>& keys = cutOutKeys_[whole];
      radixSort(keys, sortScratch_);
      BillboardDraw draw{b, result.instances, uint32_t(keys.size()), 0.0f, whole ? 6u : 3u};
      for (uint64_t key : keys) out[result.instances++] = cutOutCopies_[whole][uint32_t(key)];
      if (draw.instanceCount > 0) result.cutOut.push_back(draw);
      if (!whole) result.trimmed += draw.instanceCount;
    }
  }
  // Impostors: culled with their objects already, and in the draws' front
  // to back order, kept within each billboard.
  std::vector<uint32_t> order(impostors.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    return impostors[a].billboard < impostors[b].billboard;
  });
  glm::vec3 eyeWorld(glm::inverse(view)[3]);
  for (size_t i = 0; i < order.size();) {
    uint32_t b = impostors[order[i]].billboard;
    BillboardDraw draw{b, result.instances, 0, 0.0f};
    for (; i < order.size() && impostors[order[i]].billboard == b; ++i) {
      out[result.instances++] = impostorInstance(
          scene.billboards[b].impostor, impostors[order[i]].model, view, eyeWorld, impostorBlend);
      ++draw.instanceCount;
    }
    result.cutOut.push_back(draw);
  }
  // Back to front: eye space looks down -z. Ties keep scene order.
  std::stable_sort(blended.begin(), blended.end(),
                   [](const Blended& a, const Blended& b) { return a.depth < b.depth; });
  for (const Blended& entry : blended) {
    result.blended.push_back(
        {entry.billboard, result.instances, 1, entry.depth, entry.trimmed ? 3u : 6u});
    out[result.instances++] = entry.instance;
    result.trimmed += entry.trimmed ? 1 : 0;
  }
  return result;
}

void BillboardPass::record(VkCommandBuffer cmd, uint32_t frameSlot, ShadingModel model,
                           const ForwardFrame& frame, const GpuScene& scene,
                           std::span<const BillboardDraw> draws, const VkViewport& viewport) const {
  if (draws.empty()) return;
  VkRect2D scissor{{int32_t(viewport.x), int32_t(viewport.y)},
                   {uint32_t(viewport.width), uint32_t(viewport.height)}};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  VkDescriptorSet frameSet = frame.frameSet;
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &frameSet, 0,
                          nullptr);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 2, 1, &sets_[frameSlot], 0,
                          nullptr);
  VkDescriptorSet materialSet = VK_NULL_HANDLE;
  VkPipeline bound = VK_NULL_HANDLE;
  for (size_t i = 0; i < draws.size();) {
    // A run: one billboard's consecutive instances.
    BillboardDraw run = draws[i++];
    while (i < draws.size() && draws[i].billboard == run.billboard &&
           draws[i].vertices == run.vertices &&
           draws[i].firstInstance == run.firstInstance + run.instanceCount)
      run.instanceCount += draws[i++].instanceCount;
    const GpuBillboard& billboard = scene.billboards[run.billboard];
    assert(billboard.material < frame.materialSets.size() && "billboard without its material set");
    if (frame.materialSets[billboard.material] != materialSet) {
      materialSet = frame.materialSets[billboard.material];
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 1, 1, &materialSet, 0,
                              nullptr);
    }
    gpu::DrawConstants constants = billboard.constants;
    constants.optics.w = run.vertices == 3 ? 1.0f : 0.0f;
    auto pipeline = pipelines_.find(variantOf(model, frame, scene, billboard));
    assert(pipeline != pipelines_.end() && "BillboardPass::prepare() not called for these draws");
    if (pipeline->second.get() != bound) {
      bound = pipeline->second.get();
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound);
    }
    vkCmdPushConstants(
        cmd, layout_,
        VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_GEOMETRY_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
        sizeof(constants), &constants);
    vkCmdDraw(cmd, run.vertices, run.instanceCount, 0, run.firstInstance);
  }
}

}  // namespace shadelab
