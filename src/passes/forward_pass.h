#pragma once
// Forward shading pass: draws the visible objects of a GpuScene with the
// Phong illumination equation under one of the shading models.
// Reads: set 0 = FrameData (uniform) + ObjectData[] (storage) + the environment
// cube (environment term: kr, kt and ior per draw) + ShadowData (uniform) and
// the shadow maps (ShadowPass's array, with shadows on), vertex/index buffers;
// textured draws also set 1 (their material's textures).
// Textured draws use their own variants (the TEXTURED rows of the shader
// table): they read the uv and tangent attributes, which the others do not
// declare. Transparent draws use blended variants that do not write depth.
// Writes: the colour and depth attachments of the rendering scope it is recorded in.
#include <array>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/scene/shading.h"
#include "core/scene/shadows.h"
#include "core/vulkan/context.h"
#include "core/vulkan/depth.h"
#include "core/vulkan/gpu_scene.h"
#include "core/vulkan/resources.h"
#include "core/vulkan/shader_table.h"
#include "passes/graphics_pipeline.h"

namespace shadelab {

// What a pipeline must match in the render target: sample count and depth
// mode (format, compare op).
struct TargetLayout {
  uint32_t samples = 1;
  DepthMode depth = DepthMode::D32F;
  auto operator<=>(const TargetLayout&) const = default;
};

// A draw's material as compiled in: ka, kd, ks and n as float bit patterns,
// then its emission's RGB9E5 bits (DrawConstants::object.w).
using MaterialBits = std::array<uint32_t, 11>;

// One forward pipeline: everything its specialization constants, stages and
// fixed state are chosen by.
struct ForwardVariant {
  ShadingModel model = ShadingModel::Phong;
  LightLayout lights;        // light counts and attenuation: specialization constants
  TargetLayout target;       // sample count, depth format and compare op
  bool textured = false;     // forward_textured.* stages, with the uv and tangent attributes
  bool blended = false;      // transparent draws: "over" blending, no depth writes
  bool wireframe = false;    // polygonMode LINE, depth-biased towards the eye
  bool environment = false;  // SPEC_ENVIRONMENT: reflection and refraction of the cube
  bool refracts = false;     // SPEC_ENVIRONMENT_REFRACTS: with the environment, kt > 0
  ShadowMethod shadows =
      ShadowMethod::Off;            // SPEC_SHADOW_FILTER; flat and Gouraud: SHADOW_VARYINGS
  bool translucentShadows = false;  // SHADOW_TRANSLUCENT in SPEC_SHADOW_FILTER
  bool masked = false;              // SPEC_ALPHA_MASK: glTF alphaMode MASK
  bool doubleSided = false;         // SPEC_DOUBLE_SIDED, no culling: glTF doubleSided
  uint32_t textureMaps = 0;         // SPEC_TEXTURE_MAPS (textured only): appliedTextureMaps
  // SPEC_MATERIAL_CONSTANTS: the draw's ka, kd, ks, n and emission compiled
  // in (SPEC_MATERIAL_EMISSIVE) instead of read from its push constants; empty: read.
  std::optional<MaterialBits> material;
  // SPEC_LIGHT_CONSTANTS: ForwardFrame::lightSet compiled in; 0: read.
  uint32_t lightSet = 0;
  auto operator<=>(const ForwardVariant&) const = default;
};

// Scenes with more distinct materials than this draw every material with
// the pipelines that read it from push constants (a pipeline per material
// would cost more to build than it saves; see materialConstants).
inline constexpr size_t kMaxMaterialPipelines = 16;

// What one frame's forward draws are recorded with, besides the draws.
struct ForwardFrame {
  TargetLayout target;
  VkDescriptorSet frameSet = VK_NULL_HANDLE;  // set 0
  // Set 1 per DrawItem::material, for the frame's filter (SceneTextures).
  std::span<const VkDescriptorSet> materialSets;
  bool environment = false;                  // the variants with the environment term
  ShadowMethod shadows = ShadowMethod::Off;  // the variants that look the shadow maps up
  bool translucentShadows = false;  // the maps have translucent layers (ShadowPass::translucent)
  // Applied to the textured draws' TEXTURE_* flags (appliedTextureMaps).
  bool bump = true;      // false: normal and height maps ignored
  bool mipTint = false;  // diffuse texels tinted by mip level
  // Each material's values as specialization constants, a pipeline per
  // material (ForwardVariant::material), when the scene has at most
  // kMaxMaterialPipelines of them. llvmpipe compiles a constant into the
  // fragment code; a push-constant value is loaded per fragment, per use
  // (docs/PERFORMANCE.md has the figures). The JIT may round a folded
  // constant differently: a few linear values move by one RGBA16F step.
  bool materialConstants = false;
  // The frame's ambient term and eye-space lights compiled into every
  // pipeline (SPEC_LIGHT_CONSTANTS), as the materials are; empty: read from
  // FrameData. Values that change build new pipelines, so only a run whose
  // camera and lights hold still sets them (Renderer::compileLights). An id
  // of the passes' LightSets; 0: none.
  uint32_t lightSet = 0;
  bool impostorBlend = false;  // FrameSettings::impostorBlend (the billboard pass's)
};

// The TEXTURE_* flags a textured draw's pipeline applies (SPEC_TEXTURE_MAPS):
// its material's maps, without the normal and height maps when `bump` is
// off, with the mip-level tint when `mipTint` is on (ForwardFrame's switches).
uint32_t appliedTextureMaps(uint32_t materialMaps, bool bump, bool mipTint);

class ForwardPass {
 public:
  // `lightSets`: where ForwardFrame::lightSet's values are (outlives the pass).
  ForwardPass(const Context& context, VkFormat colorFormat, const LightSets& lightSets);

  VkDescriptorSetLayout descriptorSetLayout() const { return setLayout_.get(); }
  VkDescriptorSetLayout materialSetLayout() const { return materialSetLayout_.get(); }
  // Builds, before any frame records with them, the pipelines that drawing
  // `scene`'s draws under each of `models` with `frame`'s settings needs (and
  // the wireframe's, if asked for); those built before are kept.
  void prepare(const GpuScene& scene, std::span<const ShadingModel> models,
               const ForwardFrame& frame, bool wireframe);
  // Records `draws` (visibleDraws: opaque first, then transparent ones, which
  // blend over what is drawn) inside an active dynamic-rendering scope; sets
  // its own viewport.
  void record(VkCommandBuffer cmd, ShadingModel model, const ForwardFrame& frame,
              const GpuScene& scene, std::span<const DrawItem> draws,
              const VkViewport& viewport) const;
  // Triangle edges of `draws` over what record() drew (polygonMode LINE,
  // depth-biased towards the eye); a no-op without fillModeNonSolid.
  void recordWireframe(VkCommandBuffer cmd, const ForwardFrame& frame, const GpuScene& scene,
                       std::span<const DrawItem> draws, const VkViewport& viewport) const;

  // How many materials (distinct ka, kd, ks and n) `scene`'s draws have:
  // with ForwardFrame::materialConstants, a pipeline each per variant.
  static size_t materialCount(const GpuScene& scene);

  // The shader table rows (shaders/CMakeLists.txt) compiled from the forward bodies.
  static std::vector<ShaderVariant> shaderVariants();
  // New SPIR-V by row name; rebuilds every pipeline prepared so far.
  void reloadShaders(const std::map<std::string, std::vector<uint32_t>>& spirv);

 private:
  Pipeline createPipeline(const ForwardVariant& key) const;
  // The pipeline `draw` is recorded with: prepare() builds and record()
  // binds exactly these.
  static ForwardVariant variantOf(ShadingModel model, const ForwardFrame& frame,
                                  const GpuScene& scene, const DrawItem& draw);
  // The viewport and scissor, set 0 and the scene's vertex and index buffers.
  void bindFrame(VkCommandBuffer cmd, const ForwardFrame& frame, const GpuScene& scene,
                 const VkViewport& viewport) const;

  const Context& context_;
  VkFormat colorFormat_;
  const LightSets& lightSets_;
  DescriptorSetLayout setLayout_;
  DescriptorSetLayout materialSetLayout_;
  PipelineLayout layout_;
  std::map<std::string, ShaderModule> modules_;  // by row name: every one of shaderVariants()
  std::map<ForwardVariant, Pipeline> pipelines_;
};

}  // namespace shadelab
