#pragma once
// Shadow pass: the depth of the shadow casters as each light sees them, one
// layer of a depth array per light view (a directional light's one, a point
// light's six cube faces: six passes, one per face).
// Reads: the scene's vertex and index buffers (positions; translucent
// casters also their normals); the draws whose object casts shadows, culled
// against each view's frustum. Casters with alphaMode MASK and a base colour
// texture also read their uv and their material's set (ForwardPass's
// material layout) and cut the same holes; BLEND ones over a texture with
// alpha read them too, as translucent casters (below) whose texels pass 1 -
// their coverage (kd.w times the texel's alpha), as the tracer's shadow rays
// do.
// Translucent casters (kt > 0 and no MASK texture: glass, glTF BLEND) pass
// some light. When a scene has any (prepare's
// `translucent`), each layer also gets the opaque casters' depth alone (a
// second depth array) and the product of what each crossing of a
// translucent one passes (an R16F array, multiplied into: kt (1 - F),
// Schlick's F at the light's angle to the surface, or kt alone for coverage
// materials, texel by texel over a texture with alpha). The lookup (shaders/shadows.glsl,
// SHADOW_TRANSLUCENT) reads them only where the depth array, which holds every caster, says shadow:
// behind no opaque caster, the point gets the transmittance. One layer
// cannot tell the crossings before a point from those after it: a point
// between two translucent surfaces (the far side of a glass sphere) gets
// them all.
// Writes: its depth array (and the translucent arrays), left in ShaderRead
// use for the forward pass (BINDING_SHADOW_MAP and BINDING_OPAQUE_SHADOW_MAP,
// compare samplers; BINDING_TRANSMITTANCE).
// Keeps: a layer whose view and casters (their transforms, after culling)
// are exactly those it was last drawn with is not drawn again: a static
// light over static casters costs its map once, however many frames follow
// (a point light's cube does not depend on the camera; a directional map
// is refitted, and redrawn, when the camera moves). The kept depth is the
// same as a redraw would give, so images do not change.
#include <glm/glm.hpp>
#include <span>

#include "core/vulkan/context.h"
#include "core/vulkan/gpu_scene.h"
#include "core/vulkan/resources.h"
#include "passes/graphics_pipeline.h"

namespace shadelab {

class ShadowPass {
 public:
  static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
  static constexpr VkFormat kTransmittanceFormat = VK_FORMAT_R16_SFLOAT;

  // A caster drawn into the translucent layers instead of the depth array.
  static bool isTranslucentCaster(const DrawItem& draw);
  // Whether any of `draws` is one.
  static bool anyTranslucentCaster(std::span<const DrawItem> draws);

  // `materialLayout`: the textured draws' set (ForwardPass::materialSetLayout).
  ShadowPass(const Context& context, VkDescriptorSetLayout materialLayout);
  // A depth array of `layers` layers of size x size texels, with the
  // translucent arrays if `translucent`, kept while all three stay the
  // same; returns true when the images changed (re-point the descriptors
  // that read them). Waits for the device before replacing them.
  bool prepare(uint32_t layers, uint32_t size, bool translucent);
  // Frees the map (frames without shadows need none; view() is then the
  // placeholder's); returns true when there was one. Waits for the device.
  bool release();
  ~ShadowPass();
  ShadowPass(const ShadowPass&) = delete;
  ShadowPass& operator=(const ShadowPass&) = delete;
  // Once per map, after prepare: one empty draw with the caster pipeline,
  // submitted without waiting. llvmpipe compiles a pipeline's rasteriser
  // code at its first draw (tens of ms, not kept in Mesa's disk cache); this
  // way its queue thread compiles it while the host goes on building the
  // forward pipelines, instead of at the first frame's shadow pass. Writes
  // nothing a frame reads: every frame clears the layers it draws.
  void warmUp(bool depthClamp);
  // Depth of every caster of `scene` into each layer, seen through
  // `worldToLightClip[layer]`, whose light is `layerLights[layer]` (world
  // space: a point light's position with w = 1, or the unit direction
  // towards a directional light with w = 0; for the translucent layers'
  // Fresnel term); `casters` are scene.draws as this frame draws
  // them (--lod may have swapped in coarser index ranges, so a surface
  // shadows itself exactly where it is drawn); `objectTransforms` are the
  // scene objects' model matrices; `materialSets` the textured draws' sets by
  // DrawItem::material; `sceneUpload` tells uploads apart
  // (Renderer::uploadCount). With `keep`, layers whose inputs are unchanged
  // since their last draw are left as they are. Returns the caster draws
  // recorded (after culling). Without `depthClamp` a caster nearer than a
  // view's near plane is clipped away as in any other pass (only to measure
  // what clamping saves: study shadow-near).
  uint32_t record(VkCommandBuffer cmd, const GpuScene& scene, std::span<const DrawItem> casters,
                  uint32_t sceneUpload, std::span<const glm::mat4> objectTransforms,
                  std::span<const glm::mat4> worldToLightClip,
                  std::span<const glm::vec4> layerLights,
                  std::span<const VkDescriptorSet> materialSets, bool keep, bool depthClamp = true);

  // The array (or a 1x1 placeholder before prepare) and its compare sampler.
  VkImageView view() const { return map_ ? map_.view() : placeholder_.view(); }
  VkSampler sampler() const { return sampler_.get(); }
  uint32_t size() const { return map_ ? map_.desc().width : 1; }
  // The translucent layers (placeholders without them): the opaque casters'
  // depth (sampler()) and the transmittance (transmittanceSampler()).
  bool translucent() const { return bool(opaqueDepth_); }
  VkImageView opaqueDepthView() const {
    return opaqueDepth_ ? opaqueDepth_.view() : placeholder_.view();
  }
  VkImageView transmittanceView() const {
    return transmittance_ ? transmittance_.view() : transmittancePlaceholder_.view();
  }
  VkSampler transmittanceSampler() const { return transmittanceSampler_.get(); }

 private:
  // What every caster pipeline shares (both faces, depth clamp, one sample,
  // the position and an optional `second` attribute) around `desc`'s depth,
  // blend, formats and layout; `fragment` may be null (depth only).
  Pipeline createCasterPipeline(VkShaderModule vertex, VkShaderModule fragment,
                                const VkVertexInputAttributeDescription* second, bool depthClamp,
                                GraphicsPipelineDesc desc) const;
  Pipeline createDepthPipeline(bool masked, bool depthClamp) const;
  VkPipeline pipeline(bool masked, bool depthClamp);  // created on first use
  // `textured`: glTF BLEND over a texture with alpha (its uv and material set).
  Pipeline createTranslucentPipeline(bool depthClamp, bool textured) const;
  VkPipeline translucentPipeline(bool depthClamp, bool textured);  // created on first use
  // One layer's translucent casters: their depth over a copy of the opaque
  // casters' (into the depth array), then their transmittance.
  void recordTranslucent(VkCommandBuffer cmd, const GpuScene& scene,
                         std::span<const DrawItem* const> casters, size_t layer,
                         const glm::mat4& worldToLightClip, const glm::vec4& light,
                         std::span<const glm::mat4> objectTransforms,
                         std::span<const VkDescriptorSet> materialSets, bool depthClamp);
  std::vector<ImageView> makeLayerViews(const Image& image, VkFormat format,
                                        VkImageAspectFlags aspect) const;

  const Context& context_;
  PipelineLayout layout_;
  ShaderModule vertex_;
  PipelineLayout maskedLayout_;  // set 0: a material's textures; push: ShadowDraw with its uv
  ShaderModule maskedVertex_, maskedFragment_;
  Pipeline pipelines_[2][2];          // [masked][depth clamp]
  PipelineLayout translucentLayout_;  // push: TranslucentShadowDraw
  ShaderModule translucentVertex_, translucentFragment_, texturedTranslucentFragment_;
  Pipeline translucentPipelines_[2][2];  // [depth clamp][textured]
  Sampler sampler_;
  Sampler transmittanceSampler_;
  Image placeholder_;  // bound while no map exists: lavapipe crashes on unwritten descriptors
  Image transmittancePlaceholder_;
  Image map_;
  std::vector<ImageView> layerViews_;  // one per layer: the attachment of its pass
  Image opaqueDepth_, transmittance_;  // with translucent casters only
  std::vector<ImageView> opaqueDepthViews_, transmittanceViews_;
  // warmUp's submission, kept until its fence signals.
  void waitForWarmUp();
  CommandBufferPool warmCommands_;
  Fence warmFence_;
  Buffer warmVertices_;
  bool warmPending_ = false;
  bool warmed_ = false;  // the current map's pipeline has drawn once
  // Per layer, what it was last drawn from: the view matrix, then each
  // caster's draw index, model matrix and (masked) material set, as bits
  // (empty: never drawn).
  std::vector<std::vector<uint32_t>> drawnFrom_;
  uint32_t drawnUpload_ = 0;
};

}  // namespace shadelab
