#pragma once
// Billboard pass: textured quads that turn towards the viewer (screen-aligned,
// spherical, cylindrical: shaders/billboard.vert), one instanced draw per
// billboard object, lit as flat surfaces with the Phong equation and cut out
// (alpha test) or blended by their texture's alpha.
// Reads: set 0 = the forward pass's frame set (FrameData, ShadowData and the
// shadow maps: billboards receive shadows); set 1 = the material's textures
// (SceneTextures); set 2 = this frame slot's BillboardInstance[] (eye space),
// which prepareFrame fills with the instances that survive culling.
// Writes: the colour and depth attachments of the rendering scope it is
// recorded in; cut-out quads write depth (real depth: they meet the ground
// where they stand), blended ones only test it.
// Shadows: billboards do not cast. A quad that turns with the camera would
// cast a shadow that turns with it, and a light's view needs its own turn
// (towards the light) to cast anything sensible; neither is honest, so the
// shadow pass leaves them out and they only receive.
#include <glm/glm.hpp>
#include <map>
#include <optional>
#include <span>
#include <vector>

#include "core/scene/shading.h"
#include "core/scene/shadows.h"
#include "core/vulkan/context.h"
#include "core/vulkan/gpu_scene.h"
#include "core/vulkan/resources.h"
#include "passes/forward_pass.h"

namespace shadelab {

// Instances [firstInstance, firstInstance + instanceCount) of this frame's
// buffer, all of GpuScene::billboards[billboard].
struct BillboardDraw {
  uint32_t billboard = 0;
  uint32_t firstInstance = 0;
  uint32_t instanceCount = 0;
  float depth = 0.0f;     // blended: the quad centre's eye-space z (the sort key)
  uint32_t vertices = 6;  // 6: the quad; 3: trimmed (each copy its outline triangle)
};

// How prepareFrame trims copies to their outlines (core/scene/
// billboard_outline.h): per copy, the outline of the coarsest mip level it
// can sample (billboardLevelBound), or the quad where there is none.
struct BillboardTrim {
  // FrameSettings::trimBillboards on a single-sampled target: a sample of a
  // multisampled pixel outside the triangle would lose the colour the
  // pixel's centre gave it, so multisampled frames draw quads.
  bool enabled = false;
  std::optional<TextureFilter> filterOverride;  // anisotropic (own or this): the quad
  float focalPixels = 0.0f;                     // projection[1][1] * target height / 2
};

// An object drawn as its impostor this frame (Renderer::chooseLevels):
// GpuScene::billboards[billboard], placed by the object's model matrix.
struct ImpostorCopy {
  uint32_t billboard = 0;
  glm::mat4 model{1.0f};
};

// An impostor copy's instance: the three atlas cells blended for the
// direction from the object to the eye (world space) and their weights
// (impostorBlend), the mesh's rotation to eye space, and its quad's width
// by the model matrix's largest scale. The quad itself faces the eye
// (billboard.vert) and each fragment finds the cells' images on it
// (billboard.frag).
// `blend` off: the nearest cell alone, its quad across that cell's
// direction (BillboardInstance's first meaning).
gpu::BillboardInstance impostorInstance(const ImpostorAtlas& atlas, const glm::mat4& model,
                                        const glm::mat4& view, glm::vec3 eyeWorld, bool blend);

// What prepareFrame culled and laid out for one frame.
struct BillboardFrame {
  std::vector<BillboardDraw> cutOut;   // one per alpha-tested billboard with visible instances
  std::vector<BillboardDraw> blended;  // one per visible blended instance, back to front
  uint32_t instances = 0;              // drawn (after culling)
  uint32_t trimmed = 0;                // of those, drawn as their outline triangles
  uint32_t culled = 0;                 // instances outside the view frustum
};

class BillboardPass {
 public:
  // `lightSets`: where ForwardFrame::lightSet's values are (outlives the pass).
  BillboardPass(const Context& context, VkFormat colorFormat, VkDescriptorSetLayout frameSetLayout,
                VkDescriptorSetLayout materialSetLayout, const LightSets& lightSets);
  // Sizes each frame slot's instance buffer for `scene` (no frame in flight).
  void upload(const GpuScene& scene);
  // The pipelines that drawing `scene`'s billboards under each of `models`
  // with `frame`'s settings needs (those built before are kept).
  void prepare(const GpuScene& scene, std::span<const ShadingModel> models,
               const ForwardFrame& frame);
  // Culls each instance's bounding sphere against the frustum (unless
  // `cull` is off), moves the survivors to eye space into `frameSlot`'s
  // buffer with their outlines (`trim`) (cut-out ones per billboard in scene
  // order, trimmed before whole, then `impostors`
  // per impostor billboard, then blended ones back to front) and says how
  // to draw them. The slot's previous frame must be finished.
  BillboardFrame prepareFrame(uint32_t frameSlot, const GpuScene& scene, const glm::mat4& view,
                              const glm::mat4& projection, bool cull, const BillboardTrim& trim,
                              std::span<const ImpostorCopy> impostors = {},
                              bool impostorBlend = false);
  // Records `draws` (of prepareFrame's, for this slot) inside an active
  // dynamic-rendering scope; adjacent draws of one billboard over adjacent
  // instances become one instanced draw.
  void record(VkCommandBuffer cmd, uint32_t frameSlot, ShadingModel model,
              const ForwardFrame& frame, const GpuScene& scene,
              std::span<const BillboardDraw> draws, const VkViewport& viewport) const;

  static constexpr uint32_t kFrameSlots = 2;  // Renderer::kFramesInFlight

 private:
  struct Variant {
    ShadingModel model;
    LightLayout lights;
    TargetLayout target;
    ShadowMethod shadows;
    bool translucentShadows;  // SHADOW_TRANSLUCENT in SPEC_SHADOW_FILTER
    bool blended;
    uint32_t textureMaps;  // SPEC_TEXTURE_MAPS
    int kind;              // SPEC_BILLBOARD_KIND
    uint32_t lightSet;     // ForwardFrame::lightSet
    bool impostorBlend;    // an impostor drawn with billboard_impostor_blend.*
    auto operator<=>(const Variant&) const = default;
  };
  Pipeline createPipeline(const Variant& key) const;
  // The pipeline `billboard` is drawn with under `model`: prepare() builds
  // and record() binds exactly these.
  static Variant variantOf(ShadingModel model, const ForwardFrame& frame, const GpuScene& scene,
                           const GpuBillboard& billboard);

  const Context& context_;
  VkFormat colorFormat_;
  const LightSets& lightSets_;
  DescriptorSetLayout instanceSetLayout_;
  PipelineLayout layout_;
  ShaderModule vertex_, fragment_;
  ShaderModule blendVertex_, blendFragment_;  // IMPOSTOR_BLEND
  DescriptorPool pool_;
  Buffer instances_[kFrameSlots];  // BillboardInstance[], host-visible
  VkDescriptorSet sets_[kFrameSlots] = {};
  std::map<Variant, Pipeline> pipelines_;
  // prepareFrame's scratch, kept so that a frame allocates nothing: one
  // billboard's cut-out copies, trimmed and whole, and their sort keys.
  std::vector<gpu::BillboardInstance> cutOutCopies_[2];
  std::vector<uint64_t> cutOutKeys_[2];
  std::vector<uint64_t> sortScratch_;
  std::vector<glm::uvec4> packedOutlines_;  // one billboard's, by level; w = 0: none
};

}  // namespace shadelab
