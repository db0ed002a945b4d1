#include "passes/forward_pass.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cstddef>
#include <optional>
#include <set>
#include <string_view>
#include <vector>

#include "core/base/errors.h"
#include "core/scene/mesh.h"
#include "core/vulkan/shader.h"
#include "core/vulkan/vk_check.h"
#include "passes/graphics_pipeline.h"

namespace shadelab {

ForwardPass::ForwardPass(const Context& context, VkFormat colorFormat, const LightSets& lightSets)
    : context_(context), colorFormat_(colorFormat), lightSets_(lightSets) {
  VkDevice device = context.device();
  VkDescriptorSetLayoutBinding bindings[] = {
      {BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
       VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_GEOMETRY_BIT | VK_SHADER_STAGE_FRAGMENT_BIT},
      {BINDING_OBJECTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
       VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_GEOMETRY_BIT | VK_SHADER_STAGE_FRAGMENT_BIT},
      {BINDING_ENVIRONMENT, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
       VK_SHADER_STAGE_FRAGMENT_BIT},
      {BINDING_SHADOW_MAP, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
       VK_SHADER_STAGE_FRAGMENT_BIT},
      {BINDING_OPAQUE_SHADOW_MAP, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
       VK_SHADER_STAGE_FRAGMENT_BIT},
      {BINDING_TRANSMITTANCE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
       VK_SHADER_STAGE_FRAGMENT_BIT},
      {BINDING_SHADOWS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
       VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT},
  };
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.bindingCount = uint32_t(std::size(bindings));
  setInfo.pBindings = bindings;
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &setLayout));
  setLayout_ = DescriptorSetLayout(device, setLayout);

  VkDescriptorSetLayoutBinding textureBindings[3];
  for (uint32_t binding : {BINDING_DIFFUSE_MAP, BINDING_NORMAL_MAP, BINDING_HEIGHT_MAP})
    textureBindings[binding] = {binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                VK_SHADER_STAGE_FRAGMENT_BIT};
  VkDescriptorSetLayoutCreateInfo materialInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  materialInfo.bindingCount = 3;
  materialInfo.pBindings = textureBindings;
  VkDescriptorSetLayout materialLayout = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorSetLayout(device, &materialInfo, nullptr, &materialLayout));
  materialSetLayout_ = DescriptorSetLayout(device, materialLayout);

  VkPushConstantRange pushRange{
      VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_GEOMETRY_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
      sizeof(gpu::DrawConstants)};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  VkDescriptorSetLayout setLayouts[] = {setLayout, materialLayout};
  layoutInfo.setLayoutCount = 2;
  layoutInfo.pSetLayouts = setLayouts;
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &pushRange;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout));
  layout_ = PipelineLayout(device, layout);

  for (const ShaderVariant& variant : shaderVariants())
    modules_[std::string(variant.name)] = createShaderModule(device, variant.spirv);
}

// The forward pass's body for each stage; the shader table (shaders/CMakeLists.txt)
// compiles each with the defines of its variants.
static std::string_view forwardSource(VkShaderStageFlagBits stage) {
  switch (stage) {
    case VK_SHADER_STAGE_VERTEX_BIT:
      return "forward_vertex.glsl";
    case VK_SHADER_STAGE_GEOMETRY_BIT:
      return "forward_flat.geom";
    case VK_SHADER_STAGE_FRAGMENT_BIT:
      return "forward_fragment.glsl";
    default:
      return {};
  }
}

// The table row that runs `stage` for a shading model: its body with the
// defines that declare only the varyings the model passes
// (shaders/forward_vertex.glsl says why) and TEXTURED for the uv and tangent.
static const ShaderVariant& forwardStage(VkShaderStageFlagBits stage, ShadingModel model,
                                         bool textured, bool environment, bool shadows) {
  std::vector<std::string_view> defines;
  if (textured) defines.push_back("TEXTURED");
  // Flat and Gouraud with shadows pass each light's term on to the fragment
  // stage, which weighs it by k_shadow (shaders/lighting.glsl says why).
  bool lightedEarlier = model == ShadingModel::Flat || model == ShadingModel::Gouraud;
  if (shadows && lightedEarlier &&
      !(model == ShadingModel::Flat && stage == VK_SHADER_STAGE_VERTEX_BIT))
    defines.push_back("SHADOW_VARYINGS");
  // The others light per fragment: their vertex stage finds the map
  // coordinates, which are affine in the position (shaders/shadows.glsl).
  if (shadows && !lightedEarlier) defines.push_back("SHADOW_COORDINATES");
  if (model == ShadingModel::Gouraud) {
    defines.push_back("VERTEX_LIGHTING");
    if (environment) defines.push_back("ENVIRONMENT_VARYINGS");
  }
  // Flat's geometry stage hands the fragment stage one colour per triangle.
  if (model == ShadingModel::Flat && stage == VK_SHADER_STAGE_FRAGMENT_BIT)
    defines.push_back("FLAT_VARYINGS");
  for (const ShaderVariant& variant : shaderTable())
    if (variant.stage == stage && variant.source == forwardSource(stage) &&
        std::is_permutation(variant.defines.begin(), variant.defines.end(), defines.begin(),
                            defines.end()))
      return variant;
  throw VulkanError("the shader table (shaders/CMakeLists.txt) has no row for " +
                    std::string(forwardSource(stage)) + " with the defines of this variant");
}

std::vector<ShaderVariant> ForwardPass::shaderVariants() {
  std::vector<ShaderVariant> variants;
  for (const ShaderVariant& variant : shaderTable())
    if (variant.source == forwardSource(variant.stage)) variants.push_back(variant);
  return variants;
}

void ForwardPass::reloadShaders(const std::map<std::string, std::vector<uint32_t>>& spirv) {
  for (auto& [name, module] : modules_)
    module = createShaderModule(context_.device(), spirv.at(name));
  // Frames record with the variants already prepared, so each is rebuilt now.
  for (auto& [variant, pipeline] : pipelines_) pipeline = createPipeline(variant);
}

// A draw's ka, kd, ks, n and emission as bit patterns: equal keys, equal constants.
static MaterialBits materialBits(const gpu::DrawConstants& constants) {
  glm::vec3 ka(constants.ka), kd(constants.kd), ks(constants.ks);
  return {std::bit_cast<uint32_t>(ka.r),
          std::bit_cast<uint32_t>(ka.g),
          std::bit_cast<uint32_t>(ka.b),
          std::bit_cast<uint32_t>(kd.r),
          std::bit_cast<uint32_t>(kd.g),
          std::bit_cast<uint32_t>(kd.b),
          std::bit_cast<uint32_t>(ks.r),
          std::bit_cast<uint32_t>(ks.g),
          std::bit_cast<uint32_t>(ks.b),
          std::bit_cast<uint32_t>(constants.ks.w),
          std::bit_cast<uint32_t>(constants.object.w)};
}

size_t ForwardPass::materialCount(const GpuScene& scene) {
  std::set<MaterialBits> materials;
  for (const DrawItem& draw : scene.draws) materials.insert(materialBits(draw.constants));
  return materials.size();
}

uint32_t appliedTextureMaps(uint32_t materialMaps, bool bump, bool mipTint) {
  uint32_t maps = materialMaps;
  if (!bump) maps &= ~uint32_t(TEXTURE_NORMAL | TEXTURE_HEIGHT);
  if (mipTint) maps |= TEXTURE_MIP_TINT;
  return maps;
}

ForwardVariant ForwardPass::variantOf(ShadingModel model, const ForwardFrame& frame,
                                      const GpuScene& scene, const DrawItem& draw) {
  ForwardVariant variant{.model = model,
                         .lights = scene.lights,
                         .target = frame.target,
                         .textured = draw.textured,
                         .blended = draw.transparent,
                         .environment = frame.environment,
                         .refracts = frame.environment && draw.constants.optics.y > 0.0f,
                         .shadows = frame.shadows,
                         .translucentShadows = frame.translucentShadows,
                         .masked = draw.masked,
                         .doubleSided = draw.doubleSided};
  if (draw.textured)
    variant.textureMaps = appliedTextureMaps(draw.constants.object.y, frame.bump, frame.mipTint);
  if (frame.materialConstants) variant.material = materialBits(draw.constants);
  variant.lightSet = frame.lightSet;
  return variant;
}

void ForwardPass::prepare(const GpuScene& scene, std::span<const ShadingModel> models,
                          const ForwardFrame& frame, bool wireframe) {
  for (ShadingModel model : models)
    for (const DrawItem& draw : scene.draws) {
      ForwardVariant key = variantOf(model, frame, scene, draw);
      if (!pipelines_.count(key)) pipelines_[key] = createPipeline(key);
    }
  ForwardVariant wireframeKey{.model = ShadingModel::Unlit,
                              .lights = scene.lights,
                              .target = frame.target,
                              .wireframe = true};
  if (wireframe && context_.features().fillModeNonSolid && !pipelines_.count(wireframeKey))
    pipelines_[wireframeKey] = createPipeline(wireframeKey);
}

Pipeline ForwardPass::createPipeline(const ForwardVariant& key) const {
  const auto& [model, lights, target, textured, blended, wireframe, environment, refracts, shadows,
               translucentShadows, masked, doubleSided, textureMaps, material, lightSet] = key;
  struct {
    int32_t shadingModel;
    VkBool32 environment;
    int32_t shadowFilter;
    VkBool32 alphaMask;
    VkBool32 doubleSided;
    VkBool32 materialConstants;
    MaterialBits material;  // ka.rgb, kd.rgb, ks.rgb, n: float bit patterns; emission
    int32_t textureMaps;
    VkBool32 refracts;
    LightSpecialization lights;
  } constants{int32_t(model),
              environment ? VK_TRUE : VK_FALSE,
              shadowSpecialization(shadows, translucentShadows),
              masked ? VK_TRUE : VK_FALSE,
              doubleSided ? VK_TRUE : VK_FALSE,
              material ? VK_TRUE : VK_FALSE,
              material.value_or(MaterialBits{}),
              int32_t(textureMaps),
              refracts ? VK_TRUE : VK_FALSE,
              lightSpecialization(lights, lightSets_.find(lightSet))};
  std::vector<VkSpecializationMapEntry> entries = {
      {/* constantID= */ SPEC_SHADING_MODEL, offsetof(decltype(constants), shadingModel), 4},
      {/* constantID= */ SPEC_ENVIRONMENT, offsetof(decltype(constants), environment), 4},
      {/* constantID= */ SPEC_SHADOW_FILTER, offsetof(decltype(constants), shadowFilter), 4},
      {/* constantID= */ SPEC_ALPHA_MASK, offsetof(decltype(constants), alphaMask), 4},
      {/* constantID= */ SPEC_DOUBLE_SIDED, offsetof(decltype(constants), doubleSided), 4},
      {/* constantID= */ SPEC_MATERIAL_CONSTANTS, offsetof(decltype(constants), materialConstants),
       4},
      {SPEC_MATERIAL_KA, offsetof(decltype(constants), material) + 0, 4},
      {SPEC_MATERIAL_KA + 1, offsetof(decltype(constants), material) + 4, 4},
      {SPEC_MATERIAL_KA + 2, offsetof(decltype(constants), material) + 8, 4},
      {SPEC_MATERIAL_KD, offsetof(decltype(constants), material) + 12, 4},
      {SPEC_MATERIAL_KD + 1, offsetof(decltype(constants), material) + 16, 4},
      {SPEC_MATERIAL_KD + 2, offsetof(decltype(constants), material) + 20, 4},
      {SPEC_MATERIAL_KS, offsetof(decltype(constants), material) + 24, 4},
      {SPEC_MATERIAL_KS + 1, offsetof(decltype(constants), material) + 28, 4},
      {SPEC_MATERIAL_KS + 2, offsetof(decltype(constants), material) + 32, 4},
      {SPEC_MATERIAL_SHININESS, offsetof(decltype(constants), material) + 36, 4},
      {SPEC_MATERIAL_EMISSIVE, offsetof(decltype(constants), material) + 40, 4},
      {/* constantID= */ SPEC_TEXTURE_MAPS, offsetof(decltype(constants), textureMaps), 4},
      {/* constantID= */ SPEC_ENVIRONMENT_REFRACTS, offsetof(decltype(constants), refracts), 4},
  };
  appendLightEntries(entries, offsetof(decltype(constants), lights));
  VkSpecializationInfo specialization{uint32_t(entries.size()), entries.data(), sizeof(constants),
                                      &constants};

  std::vector<VkPipelineShaderStageCreateInfo> stages;
  auto addStage = [&](VkShaderStageFlagBits stage, VkShaderModule module) {
    VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage = stage;
    info.module = module;
    info.pName = "main";
    info.pSpecializationInfo = &specialization;
    stages.push_back(info);
  };
  // Flat shading needs the whole triangle to find its geometric normal. The
  // stages come in variants that differ only in the varyings they pass.
  auto add = [&](VkShaderStageFlagBits stage) {
    const ShaderVariant& variant =
        forwardStage(stage, model, textured, environment, shadows != ShadowMethod::Off);
    addStage(stage, modules_.at(std::string(variant.name)).get());
  };
  add(VK_SHADER_STAGE_VERTEX_BIT);
  if (model == ShadingModel::Flat) add(VK_SHADER_STAGE_GEOMETRY_BIT);
  add(VK_SHADER_STAGE_FRAGMENT_BIT);

  VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
  // Only the attributes the shaders read: lavapipe fetches every declared
  // attribute, and declaring the unused uv and tangent cost a third of the
  // constant-colour floor on a 14,400-triangle teapot at 800x600 (2.53 ms
  // against 1.68 ms, bench assets/scenes/peer-shading.json). Texturing adds
  // them back in the variants that sample textures.
  VkVertexInputAttributeDescription attributes[] = {
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal)},
      {2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(Vertex, uv)},
      {3, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(Vertex, tangent)},
  };
  VkPipelineVertexInputStateCreateInfo vertexInput{
      VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertexInput.vertexBindingDescriptionCount = 1;
  vertexInput.pVertexBindingDescriptions = &binding;
  vertexInput.vertexAttributeDescriptionCount = textured ? 4 : 2;
  vertexInput.pVertexAttributeDescriptions = attributes;

  VkPipelineRasterizationStateCreateInfo raster{
      VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = wireframe ? VK_POLYGON_MODE_LINE : VK_POLYGON_MODE_FILL;
  // Edges sit exactly on the filled surface: move them towards the eye (a
  // constant plus a slope-scaled offset; nearer is larger with reversed Z) so
  // the depth test keeps them.
  float towardsEye = target.depth == DepthMode::ReversedZ ? 1.0f : -1.0f;
  raster.depthBiasEnable = wireframe ? VK_TRUE : VK_FALSE;
  raster.depthBiasConstantFactor = towardsEye;
  raster.depthBiasSlopeFactor = towardsEye;
  // Back faces culled, unless the material is double-sided (glTF doubleSided).
  raster.cullMode = doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
  // The projection flips y for Vulkan; Vulkan's signed-area rule flips it back,
  // so triangles counter-clockwise in the course's y-up view stay front-facing.
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{
      VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VkSampleCountFlagBits(target.samples);
  VkPipelineDepthStencilStateCreateInfo depth{
      VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = VK_TRUE;
  // Translucent surfaces must not hide what is drawn behind them later.
  depth.depthWriteEnable = blended ? VK_FALSE : VK_TRUE;
  depth.depthCompareOp = depthCompareOp(target.depth);
  // Edges pass where they touch the surface they outline.
  if (wireframe && depth.depthCompareOp == VK_COMPARE_OP_LESS)
    depth.depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
  VkPipelineColorBlendAttachmentState blendAttachment{};
  // "Over": colour = a src + (1 - a) dst with a = 1 - transparency; the
  // target's alpha stays as the clear left it.
  blendAttachment.blendEnable = blended ? VK_TRUE : VK_FALSE;
  blendAttachment.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
  blendAttachment.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
  blendAttachment.colorBlendOp = VK_BLEND_OP_ADD;
  blendAttachment.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
  blendAttachment.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
  blendAttachment.alphaBlendOp = VK_BLEND_OP_ADD;
  blendAttachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                   VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  return createGraphicsPipeline(
      context_.device(), {stages, &vertexInput, &raster, &multisample, &depth, blendAttachment,
                          colorFormat_, depthFormat(target.depth), layout_});
}

void ForwardPass::bindFrame(VkCommandBuffer cmd, const ForwardFrame& frame, const GpuScene& scene,
                            const VkViewport& viewport) const {
  VkDescriptorSet frameSet = frame.frameSet;
  VkRect2D scissor{{int32_t(viewport.x), int32_t(viewport.y)},
                   {uint32_t(viewport.width), uint32_t(viewport.height)}};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &frameSet, 0,
                          nullptr);
  VkDeviceSize offset = 0;
  VkBuffer vertexBuffer = scene.vertices.get();
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertexBuffer, &offset);
  vkCmdBindIndexBuffer(cmd, scene.indices.get(), 0, VK_INDEX_TYPE_UINT32);
}

void ForwardPass::record(VkCommandBuffer cmd, ShadingModel model, const ForwardFrame& frame,
                         const GpuScene& scene, std::span<const DrawItem> draws,
                         const VkViewport& viewport) const {
  bindFrame(cmd, frame, scene, viewport);
  VkPipeline bound = VK_NULL_HANDLE;
  VkDescriptorSet materialSet = VK_NULL_HANDLE;
  for (const DrawItem& draw : draws) {
    auto pipeline = pipelines_.find(variantOf(model, frame, scene, draw));
    assert(pipeline != pipelines_.end() && "ForwardPass::prepare() not called for these draws");
    if (pipeline->second.get() != bound) {
      bound = pipeline->second.get();
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound);
    }
    if (draw.textured) {
      assert(draw.material < frame.materialSets.size() && "textured draw without its material set");
      if (frame.materialSets[draw.material] != materialSet) {
        materialSet = frame.materialSets[draw.material];
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 1, 1, &materialSet,
                                0, nullptr);
      }
    }
    gpu::DrawConstants constants = draw.constants;
    vkCmdPushConstants(
        cmd, layout_,
        VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_GEOMETRY_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
        sizeof(constants), &constants);
    vkCmdDrawIndexed(cmd, draw.indexCount, draw.instanceCount, draw.firstIndex, draw.vertexOffset,
                     0);
  }
}

void ForwardPass::recordWireframe(VkCommandBuffer cmd, const ForwardFrame& frame,
                                  const GpuScene& scene, std::span<const DrawItem> draws,
                                  const VkViewport& viewport) const {
  if (!context_.features().fillModeNonSolid) return;
  auto pipeline = pipelines_.find({.model = ShadingModel::Unlit,
                                   .lights = scene.lights,
                                   .target = frame.target,
                                   .wireframe = true});
  assert(pipeline != pipelines_.end() && "ForwardPass::prepare() not called for these lights");
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline->second);
  bindFrame(cmd, frame, scene, viewport);
  for (const DrawItem& draw : draws) {
    // Unlit writes kd: every edge in one light grey, textured or not.
    gpu::DrawConstants constants = draw.constants;
    constants.kd = glm::vec4(0.9f, 0.9f, 0.9f, 1.0f);
    vkCmdPushConstants(
        cmd, layout_,
        VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_GEOMETRY_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
        sizeof(constants), &constants);
    vkCmdDrawIndexed(cmd, draw.indexCount, draw.instanceCount, draw.firstIndex, draw.vertexOffset,
                     0);
  }
}

}  // namespace shadelab
