#pragma once
// A scene's textures on the device: every Scene::textures entry uploaded with
// its full mip chain (MipGeneration), samplers made from SamplerDesc (created
// once, cached for the renderer's life), and descriptor set 1 per material,
// written once at upload with every binding (dummies for empty slots).
// Not a pass: the renderer calls upload() once per scene, before any frame.
#include <map>
#include <optional>
#include <vector>

#include "core/vulkan/context.h"
#include "core/vulkan/gpu_scene.h"
#include "core/vulkan/resources.h"
#include "core/scene/scene.h"
#include "passes/mip_generation.h"

namespace shadelab {

struct GpuTexture {
  Image image;  // R8G8B8A8 _SRGB (colour) or _UNORM (data), all mip levels
  uint32_t width = 0, height = 0, levels = 0;
};

struct TextureOptions {
  std::optional<TextureFilter> filterOverride;  // replaces every sampler's filter
  bool bump = true;                             // false: normal and height maps ignored
  bool mipTint = false;                         // diffuse texels tinted by mip level
};

class SceneTextures {
 public:
  SceneTextures(const Context& context, VkDescriptorSetLayout materialLayout);
  // Replaces the previous scene's textures and sets (no frame may be in
  // flight), then points each textured draw at its material's set and applies
  // the options to its flags. Throws InputError for a texture the device
  // cannot hold or anisotropy it does not offer.
  void upload(const Scene& scene, GpuScene& gpuScene, const TextureOptions& options);
  const GpuTexture& texture(size_t index) const { return textures_.at(index); }
  size_t samplerCount() const { return samplers_.size(); }

 private:
  VkSampler sampler(const SamplerDesc& desc);
  VkDescriptorSet writeSet(const Scene& scene, const Material& material,
                           const TextureOptions& options);

  const Context& context_;
  VkDescriptorSetLayout materialLayout_;
  MipGeneration mips_;
  std::map<SamplerDesc, Sampler> samplers_;
  GpuTexture white_, flatNormal_;
  // Members destroy in reverse order: the sets' pool before the images.
  std::vector<GpuTexture> textures_;
  DescriptorPool pool_;
};

// Uploads textures with one submit; each gets its complete mip chain.
std::vector<GpuTexture> uploadTextures(const Context& context, const MipGeneration& mips,
                                       const std::vector<const Texture*>& textures);
// Reads one mip level back as 8-bit RGBA, row 0 at the top (tests, debugging).
std::vector<uint8_t> readTextureLevel(const Context& context, const GpuTexture& texture,
                                      uint32_t level);

}  // namespace shadelab
