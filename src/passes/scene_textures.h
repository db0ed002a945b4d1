#pragma once
// A scene's textures on the device: every Scene::textures entry uploaded with
// its full mip chain (MipGeneration), samplers made from SamplerDesc (created
// once, cached for the renderer's life), and descriptor set 1 per material
// and filter choice, each written once with every binding (dummies for empty
// slots). Not a pass: the renderer calls upload() once per scene, before any
// frame, and prepareFilter() when the frame settings pick a filter.
#include <array>
#include <map>
#include <optional>
#include <span>
#include <tuple>
#include <vector>

#include "core/scene/scene.h"
#include "core/vulkan/context.h"
#include "core/vulkan/gpu_scene.h"
#include "core/vulkan/resources.h"
#include "passes/mip_generation.h"

namespace shadelab {

struct GpuTexture {
  Image image;  // R8G8B8A8 _SRGB (colour) or _UNORM (data), all mip levels
  uint32_t width = 0, height = 0, levels = 0;
};

// Per-frame texture switches: none of them re-uploads anything.
struct TextureOptions {
  std::optional<TextureFilter> filterOverride;  // replaces every sampler's filter
  bool bump = true;                             // false: normal and height maps ignored
  bool mipTint = false;                         // diffuse texels tinted by mip level
  bool operator==(const TextureOptions&) const = default;
};

class SceneTextures {
 public:
  SceneTextures(const Context& context, VkDescriptorSetLayout materialLayout);
  // Replaces the previous scene's textures and sets (no frame may be in
  // flight), uploads the scene's and numbers the textured draws' materials
  // (DrawItem::material). Throws InputError for a texture the device cannot
  // hold.
  void upload(const Scene& scene, GpuScene& gpuScene);
  // Throws InputError when the device cannot sample the scene's materials
  // with this choice (anisotropy it does not offer).
  void checkFilter(std::optional<TextureFilter> filterOverride) const;
  // Writes the materials' sets for a filter choice, once per scene and
  // choice: sets already written are never touched, so frames in flight
  // keep theirs. checkFilter first.
  void prepareFilter(std::optional<TextureFilter> filterOverride);
  // Set 1 per material (index DrawItem::material) under a prepared choice.
  std::span<const VkDescriptorSet> materialSets(std::optional<TextureFilter> filterOverride) const;
  const GpuTexture& texture(size_t index) const { return textures_.at(index); }
  size_t samplerCount() const { return samplers_.size(); }

 private:
  // A material as its set sees it: the texture and sampler of each map.
  using MaterialMaps = std::tuple<int32_t, SamplerDesc, int32_t, SamplerDesc, int32_t, SamplerDesc>;
  // Each material's own samplers, or every sampler with one filter.
  static constexpr size_t kFilterChoices = 1 + size_t(TextureFilter::Anisotropic) + 1;
  static size_t choiceIndex(std::optional<TextureFilter> filterOverride) {
    return filterOverride ? 1 + size_t(*filterOverride) : 0;
  }
  VkSampler sampler(const SamplerDesc& desc);
  VkDescriptorSet writeSet(const MaterialMaps& maps, std::optional<TextureFilter> filterOverride);

  const Context& context_;
  VkDescriptorSetLayout materialLayout_;
  MipGeneration mips_;
  std::map<SamplerDesc, Sampler> samplers_;
  GpuTexture white_, flatNormal_;
  std::vector<MaterialMaps> materials_;  // distinct, in the order of DrawItem::material
  // Members destroy in reverse order: the sets' pool before the images.
  std::vector<GpuTexture> textures_;
  DescriptorPool pool_;
  std::array<std::vector<VkDescriptorSet>, kFilterChoices> sets_;  // empty until prepared
};

// Uploads textures with one submit; each gets its complete mip chain.
std::vector<GpuTexture> uploadTextures(const Context& context, const MipGeneration& mips,
                                       const std::vector<const Texture*>& textures);
// Reads one mip level back as 8-bit RGBA, row 0 at the top (tests, debugging).
std::vector<uint8_t> readTextureLevel(const Context& context, const GpuTexture& texture,
                                      uint32_t level);

}  // namespace shadelab
