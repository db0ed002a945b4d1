#include "passes/environment_builder.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <glm/gtc/packing.hpp>

#include "core/scene/texture.h"
#include "core/vulkan/barriers.h"
#include "core/vulkan/vk_check.h"

namespace shadelab {
namespace {

constexpr VkImageUsageFlags kCubeUsage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                                         VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                         VK_IMAGE_USAGE_TRANSFER_DST_BIT;

Sampler createSampler(const Context& context, VkSamplerAddressMode u, VkSamplerAddressMode v) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = VK_FILTER_LINEAR;
  info.minFilter = VK_FILTER_LINEAR;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
  info.addressModeU = u;
  info.addressModeV = v;
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.maxLod = VK_LOD_CLAMP_NONE;
  VkSampler sampler = VK_NULL_HANDLE;
  VK_CHECK(vkCreateSampler(context.device(), &info, nullptr, &sampler));
  return Sampler(context.device(), sampler);
}

// Half-float RGBA texels of `images`, one after the other, in a staging buffer.
Buffer stageHalfTexels(const Context& context, const std::vector<const ImageRgba*>& images) {
  size_t texels = 0;
  for (const ImageRgba* image : images) texels += size_t(image->width) * image->height;
  Buffer staging(context, VkDeviceSize(texels * 8), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                 MemoryUse::HostVisible);
  auto* out = static_cast<uint64_t*>(staging.mapped());
  for (const ImageRgba* image : images)
    for (size_t p = 0; p < size_t(image->width) * image->height; ++p) {
      glm::vec4 value;
      std::memcpy(&value, &image->pixels[p * 4], sizeof(value));
      *out++ = glm::packHalf4x16(value);
    }
  return staging;
}

ImageView levelArrayView(const Context& context, const Image& image, uint32_t level) {
  VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  info.image = image.get();
  info.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
  info.format = image.desc().format;
  info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, level, 1, 0, image.desc().layers};
  VkImageView view = VK_NULL_HANDLE;
  VK_CHECK(vkCreateImageView(context.device(), &info, nullptr, &view));
  return ImageView(context.device(), view);
}

}  // namespace

EnvironmentBuilder::EnvironmentBuilder(const Context& context)
    : context_(context), sky_(context), equirect_(context), mips_(context) {}

EnvironmentCube EnvironmentBuilder::allocate(uint32_t faceSize, uint32_t mipLevels) const {
  ImageDesc desc{kFormat, faceSize, faceSize, mipLevels, 6, kCubeUsage};
  EnvironmentCube cube;
  cube.image = Image(context_, desc);
  cube.sampler = createSampler(context_, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                               VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE);
  return cube;
}

EnvironmentCube EnvironmentBuilder::build(const Environment& environment) const {
  assert(environment.present());
  uint32_t size = cubeResolution(environment);
  EnvironmentCube cube = allocate(size, mipLevelCount(size, size));
  switch (environment.kind) {
    case EnvironmentKind::Sky:
      buildSky(environment, cube);
      break;
    case EnvironmentKind::Panorama:
      buildFromPanorama(environment, cube);
      break;
    case EnvironmentKind::CubeFaces:
      buildFromFaces(environment, cube);
      break;
    case EnvironmentKind::None:
      break;
  }
  return cube;
}

void EnvironmentBuilder::buildSky(const Environment& environment,
                                  const EnvironmentCube& cube) const {
  ImageView level0 = levelArrayView(context_, cube.image, 0);
  gpu::SkyParameters sky = skyParameters(environment.sky, environment.intensity, cube.faceSize());
  context_.submitAndWait([&](VkCommandBuffer cmd) {
    imageBarrier(cmd, cube.image.get(), VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::Undefined,
                 ImageUse::ComputeWrite, 0, 1);
    sky_.record(cmd, level0, sky);
    recordMips(cmd, cube.image, ImageUse::ComputeWrite);
  });
}

void EnvironmentBuilder::buildFromPanorama(const Environment& environment,
                                           const EnvironmentCube& cube) const {
  const ImageRgba& source = *environment.panorama;
  uint32_t levels = mipLevelCount(source.width, source.height);
  ImageDesc desc{kFormat,
                 source.width,
                 source.height,
                 levels,
                 1,
                 VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                     VK_IMAGE_USAGE_TRANSFER_DST_BIT};
  Image panorama(context_, desc);
  Sampler sampler = createSampler(context_, VK_SAMPLER_ADDRESS_MODE_REPEAT,
                                  VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE);
  Buffer staging = stageHalfTexels(context_, {&source});
  ImageView level0 = levelArrayView(context_, cube.image, 0);
  gpu::PanoramaParameters parameters{};
  parameters.face = glm::ivec4(int(cube.faceSize()), 0, 0, 0);
  // A face centre's texel spans (pi / 2) / size, a panorama texel 2 pi / width:
  // sample the level where they match.
  float lod = std::log2(float(source.width) / (4.0f * float(cube.faceSize())));
  parameters.sampling = glm::vec4(std::max(lod, 0.0f), glm::radians(environment.rotationDegrees),
                                  environment.intensity, 0.0f);
  context_.submitAndWait([&](VkCommandBuffer cmd) {
    imageBarrier(cmd, panorama.get(), VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::Undefined,
                 ImageUse::TransferDest, 0, 1);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {source.width, source.height, 1};
    vkCmdCopyBufferToImage(cmd, staging.get(), panorama.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           1, &region);
    recordMips(cmd, panorama, ImageUse::TransferDest);
    imageBarrier(cmd, panorama.get(), VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::ShaderRead,
                 ImageUse::ComputeRead);
    imageBarrier(cmd, cube.image.get(), VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::Undefined,
                 ImageUse::ComputeWrite, 0, 1);
    equirect_.record(cmd, level0, panorama.view(), sampler, parameters);
    recordMips(cmd, cube.image, ImageUse::ComputeWrite);
  });
}

void EnvironmentBuilder::buildFromFaces(const Environment& environment,
                                        const EnvironmentCube& cube) const {
  std::vector<const ImageRgba*> faces;
  std::vector<ImageRgba> scaled;
  scaled.reserve(6);
  for (const auto& face : environment.faces) {
    assert(face && face->width == cube.faceSize() && face->height == cube.faceSize());
    if (environment.intensity == 1.0f) {
      faces.push_back(face.get());
      continue;
    }
    scaled.push_back(*face);
    for (float& value : scaled.back().pixels) value *= environment.intensity;
    faces.push_back(&scaled.back());
  }
  Buffer staging = stageHalfTexels(context_, faces);
  context_.submitAndWait([&](VkCommandBuffer cmd) {
    imageBarrier(cmd, cube.image.get(), VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::Undefined,
                 ImageUse::TransferDest, 0, 1);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 6};
    region.imageExtent = {cube.faceSize(), cube.faceSize(), 1};
    vkCmdCopyBufferToImage(cmd, staging.get(), cube.image.get(),
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    recordMips(cmd, cube.image, ImageUse::TransferDest);
  });
}

void EnvironmentBuilder::recordMips(VkCommandBuffer cmd, const Image& image,
                                    ImageUse level0Use) const {
  // MipGeneration takes every level in TransferDest use.
  const ImageDesc& desc = image.desc();
  if (level0Use != ImageUse::TransferDest)
    imageBarrier(cmd, image.get(), VK_IMAGE_ASPECT_COLOR_BIT, level0Use, ImageUse::TransferDest, 0,
                 1);
  if (desc.mipLevels > 1)
    imageBarrier(cmd, image.get(), VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::Undefined,
                 ImageUse::TransferDest, 1, desc.mipLevels - 1);
  mips_.record(cmd, image.get(), desc.width, desc.height, desc.mipLevels, desc.layers);
}

EnvironmentCube EnvironmentBuilder::placeholder() const {
  EnvironmentCube cube = allocate(1, 1);
  context_.submitAndWait([&](VkCommandBuffer cmd) {
    imageBarrier(cmd, cube.image.get(), VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::Undefined,
                 ImageUse::TransferDest);
    VkClearColorValue black{};
    VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 6};
    vkCmdClearColorImage(cmd, cube.image.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &black, 1,
                         &range);
    imageBarrier(cmd, cube.image.get(), VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::TransferDest,
                 ImageUse::ShaderRead);
  });
  return cube;
}

std::array<ImageRgba, 6> readCubeLevel(const Context& context, const EnvironmentCube& cube,
                                       uint32_t level) {
  assert(level < cube.mipLevels());
  uint32_t size = std::max(1u, cube.faceSize() >> level);
  Buffer readback(context, VkDeviceSize(size) * size * 8 * 6, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                  MemoryUse::HostVisible);
  context.submitAndWait([&](VkCommandBuffer cmd) {
    imageBarrier(cmd, cube.image.get(), VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::ShaderRead,
                 ImageUse::TransferSource, level, 1);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 6};
    region.imageExtent = {size, size, 1};
    vkCmdCopyImageToBuffer(cmd, cube.image.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           readback.get(), 1, &region);
    imageBarrier(cmd, cube.image.get(), VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::TransferSource,
                 ImageUse::ShaderRead, level, 1);
    transferToHostBarrier(cmd);
  });
  std::array<ImageRgba, 6> faces;
  const auto* texels = static_cast<const uint64_t*>(readback.mapped());
  for (uint32_t face = 0; face < 6; ++face) {
    faces[face] = ImageRgba(size, size);
    for (size_t p = 0; p < size_t(size) * size; ++p) {
      glm::vec4 value = glm::unpackHalf4x16(texels[face * size_t(size) * size + p]);
      std::memcpy(&faces[face].pixels[p * 4], &value, sizeof(value));
    }
  }
  return faces;
}

}  // namespace shadelab
