#include "passes/scene_textures.h"

#include <algorithm>
#include <cassert>
#include <cstring>
#include <tuple>

#include "core/base/errors.h"
#include "core/scene/texture.h"
#include "core/vulkan/barriers.h"
#include "core/vulkan/vk_check.h"
#include "interface.h"

namespace shadelab {
namespace {

VkSamplerAddressMode addressMode(TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::Repeat:
      return VK_SAMPLER_ADDRESS_MODE_REPEAT;
    case TextureWrap::ClampToEdge:
      return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    case TextureWrap::MirroredRepeat:
      return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
  }
  return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

VkDeviceSize byteSize(const Texture& texture) {
  return VkDeviceSize(texture.width) * texture.height * 4;
}

}  // namespace

std::vector<GpuTexture> uploadTextures(const Context& context, const MipGeneration& mips,
                                       const std::vector<const Texture*>& textures) {
  uint32_t maxSize = context.properties().limits.maxImageDimension2D;
  std::vector<GpuTexture> uploaded;
  std::vector<Buffer> staging;
  for (const Texture* texture : textures) {
    if (texture->width == 0 || texture->height == 0 || texture->width > maxSize ||
        texture->height > maxSize)
      throw InputError("texture '" + texture->name + "' is " + std::to_string(texture->width) +
                       "x" + std::to_string(texture->height) + ", expected 1.." +
                       std::to_string(maxSize) + " texels per side");
    assert(texture->rgba8.size() == byteSize(*texture));
    GpuTexture gpu;
    gpu.width = texture->width;
    gpu.height = texture->height;
    gpu.levels = mipLevelCount(texture->width, texture->height);
    ImageDesc desc{texture->srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM, gpu.width,
                   gpu.height, gpu.levels};
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                 VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    gpu.image = Image(context, desc);
    staging.emplace_back(context, byteSize(*texture), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                         MemoryUse::HostVisible);
    std::memcpy(staging.back().mapped(), texture->rgba8.data(), texture->rgba8.size());
    uploaded.push_back(std::move(gpu));
  }
  if (uploaded.empty()) return uploaded;
  context.submitAndWait([&](VkCommandBuffer cmd) {
    for (size_t i = 0; i < uploaded.size(); ++i) {
      const GpuTexture& gpu = uploaded[i];
      imageBarrier(cmd, gpu.image.get(), VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::Undefined,
                   ImageUse::TransferDest);
      VkBufferImageCopy region{};
      region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      region.imageExtent = {gpu.width, gpu.height, 1};
      vkCmdCopyBufferToImage(cmd, staging[i].get(), gpu.image.get(),
                             VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
      mips.record(cmd, gpu.image.get(), gpu.width, gpu.height, gpu.levels);
    }
  });
  return uploaded;
}

std::vector<uint8_t> readTextureLevel(const Context& context, const GpuTexture& texture,
                                      uint32_t level) {
  assert(level < texture.levels);
  glm::uvec2 size = mipLevelSize(texture.width, texture.height, level);
  Buffer readback(context, VkDeviceSize(size.x) * size.y * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                  MemoryUse::HostVisible);
  context.submitAndWait([&](VkCommandBuffer cmd) {
    VkImage image = texture.image.get();
    imageBarrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::ShaderRead,
                 ImageUse::TransferSource, level, 1);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
    region.imageExtent = {size.x, size.y, 1};
    vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.get(), 1,
                           &region);
    imageBarrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::TransferSource,
                 ImageUse::ShaderRead, level, 1);
    transferToHostBarrier(cmd);
  });
  const auto* bytes = static_cast<const uint8_t*>(readback.mapped());
  return {bytes, bytes + readback.size()};
}

SceneTextures::SceneTextures(const Context& context, VkDescriptorSetLayout materialLayout)
    : context_(context), materialLayout_(materialLayout), mips_(context) {
  // Empty slots are bound to these: lavapipe crashes on unwritten descriptors.
  Texture white = solidTexture({255, 255, 255, 255}, TextureRole::Color, "dummy white");
  Texture flat = solidTexture({128, 128, 255, 255}, TextureRole::Data, "dummy flat normal");
  std::vector<GpuTexture> dummies = uploadTextures(context, mips_, {&white, &flat});
  white_ = std::move(dummies[0]);
  flatNormal_ = std::move(dummies[1]);
}

VkSampler SceneTextures::sampler(const SamplerDesc& desc) {
  auto found = samplers_.find(desc);
  if (found != samplers_.end()) return found->second;
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  bool linear = desc.filter != TextureFilter::Nearest;
  info.magFilter = info.minFilter = linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  // Nearest samples the base level only (point sampling, no mipmapping);
  // bilinear the nearest mip level; trilinear and anisotropic blend two.
  info.mipmapMode = desc.filter == TextureFilter::Nearest || desc.filter == TextureFilter::Bilinear
                        ? VK_SAMPLER_MIPMAP_MODE_NEAREST
                        : VK_SAMPLER_MIPMAP_MODE_LINEAR;
  info.maxLod = desc.filter == TextureFilter::Nearest ? 0.0f : VK_LOD_CLAMP_NONE;
  info.addressModeU = addressMode(desc.wrapU);
  info.addressModeV = addressMode(desc.wrapV);
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  if (desc.filter == TextureFilter::Anisotropic) {
    if (!context_.features().samplerAnisotropy)
      throw InputError("filter aniso: this device offers no anisotropic filtering");
    info.anisotropyEnable = VK_TRUE;
    info.maxAnisotropy =
        std::clamp(desc.maxAnisotropy, 1.0f, context_.properties().limits.maxSamplerAnisotropy);
  }
  VkSampler handle = VK_NULL_HANDLE;
  VK_CHECK(vkCreateSampler(context_.device(), &info, nullptr, &handle));
  return samplers_.emplace(desc, Sampler(context_.device(), handle)).first->second;
}

VkDescriptorSet SceneTextures::writeSet(const MaterialMaps& maps,
                                        std::optional<TextureFilter> filterOverride) {
  VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  allocate.descriptorPool = pool_;
  allocate.descriptorSetCount = 1;
  allocate.pSetLayouts = &materialLayout_;
  VkDescriptorSet set = VK_NULL_HANDLE;
  VK_CHECK(vkAllocateDescriptorSets(context_.device(), &allocate, &set));
  const auto& [diffuse, diffuseSampler, normal, normalSampler, height, heightSampler] = maps;
  const std::tuple<uint32_t, int32_t, SamplerDesc, const GpuTexture*> slots[] = {
      {BINDING_DIFFUSE_MAP, diffuse, diffuseSampler, &white_},
      {BINDING_NORMAL_MAP, normal, normalSampler, &flatNormal_},
      {BINDING_HEIGHT_MAP, height, heightSampler, &flatNormal_},  // any constant height is flat
  };
  VkDescriptorImageInfo images[3];
  VkWriteDescriptorSet writes[3];
  for (int i = 0; i < 3; ++i) {
    auto [binding, textureIndex, desc, dummy] = slots[i];
    assert(textureIndex < int32_t(textures_.size()));
    const GpuTexture& texture = textureIndex >= 0 ? textures_[size_t(textureIndex)] : *dummy;
    if (filterOverride) desc.filter = *filterOverride;
    images[i] = {sampler(desc), texture.image.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[i].dstSet = set;
    writes[i].dstBinding = binding;
    writes[i].descriptorCount = 1;
    writes[i].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    writes[i].pImageInfo = &images[i];
  }
  vkUpdateDescriptorSets(context_.device(), 3, writes, 0, nullptr);
  return set;
}

void SceneTextures::upload(const Scene& scene, GpuScene& gpuScene) {
  for (std::vector<VkDescriptorSet>& sets : sets_) sets.clear();
  pool_.reset();
  materials_.clear();
  textures_.clear();
  std::vector<const Texture*> sources;
  for (const Texture& texture : scene.textures) sources.push_back(&texture);
  for (const Texture& texture : gpuScene.impostorTextures) sources.push_back(&texture);
  textures_ = uploadTextures(context_, mips_, sources);

  // Objects whose materials use the same textures and samplers share a set.
  std::map<MaterialMaps, uint32_t> numbers;
  auto number = [&](const Material& material) {
    auto index = [](const TextureSlot& slot) { return slot.present() ? slot.texture : -1; };
    MaterialMaps maps{index(material.diffuseMap), material.diffuseMap.sampler,
                      index(material.normalMap),  material.normalMap.sampler,
                      index(material.heightMap),  material.heightMap.sampler};
    auto [found, added] = numbers.emplace(maps, uint32_t(materials_.size()));
    if (added) materials_.push_back(maps);
    return found->second;
  };
  for (DrawItem& draw : gpuScene.draws)
    if (draw.textured)
      draw.material = number(scene.objects[size_t(draw.constants.object.x)].material);
  // Billboards after the objects, so the objects' numbers are those they had before billboards.
  for (size_t i = 0; i < scene.billboards.size(); ++i)
    gpuScene.billboards[i].material = number(scene.billboards[i].material);
  // Impostors: the atlas's coverage as the diffuse map, its normals as the
  // normal map, clamped at the edges, after the scene's own textures.
  for (size_t i = scene.billboards.size(); i < gpuScene.billboards.size(); ++i) {
    int32_t first = int32_t(scene.textures.size()) + 2 * gpuScene.billboards[i].impostor.atlas;
    Material atlas;
    atlas.diffuseMap.texture = first;
    atlas.normalMap.texture = first + 1;
    for (TextureSlot* slot : {&atlas.diffuseMap, &atlas.normalMap})
      slot->sampler.wrapU = slot->sampler.wrapV = TextureWrap::ClampToEdge;
    gpuScene.billboards[i].material = number(atlas);
  }
  if (materials_.empty()) return;
  // Sized once for the scene: a set per material and filter choice.
  uint32_t maxSets = uint32_t(materials_.size() * kFilterChoices);
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 3 * maxSets};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = maxSets;
  poolInfo.poolSizeCount = 1;
  poolInfo.pPoolSizes = &size;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorPool(context_.device(), &poolInfo, nullptr, &pool));
  pool_ = DescriptorPool(context_.device(), pool);
}

void SceneTextures::checkFilter(std::optional<TextureFilter> filterOverride) const {
  if (context_.features().samplerAnisotropy) return;
  for (const MaterialMaps& maps : materials_) {
    const auto& [diffuse, diffuseSampler, normal, normalSampler, height, heightSampler] = maps;
    for (const SamplerDesc& desc : {diffuseSampler, normalSampler, heightSampler})
      if (filterOverride.value_or(desc.filter) == TextureFilter::Anisotropic)
        throw InputError("filter aniso: this device offers no anisotropic filtering");
  }
}

void SceneTextures::prepareFilter(std::optional<TextureFilter> filterOverride) {
  std::vector<VkDescriptorSet>& sets = sets_[choiceIndex(filterOverride)];
  if (sets.size() == materials_.size()) return;
  for (const MaterialMaps& maps : materials_) sets.push_back(writeSet(maps, filterOverride));
}

std::span<const VkDescriptorSet> SceneTextures::materialSets(
    std::optional<TextureFilter> filterOverride) const {
  const std::vector<VkDescriptorSet>& sets = sets_[choiceIndex(filterOverride)];
  assert(sets.size() == materials_.size() && "SceneTextures::prepareFilter() first");
  return sets;
}

}  // namespace shadelab
