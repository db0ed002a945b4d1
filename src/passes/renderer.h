#pragma once
// The renderer every front end shares (CLI, tests, benchmark, viewer): it
// owns the frames in flight and the render target and runs the passes.
// Headless capture is one call: renderToImage(scene, settings).
#include <array>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/base/image.h"
#include "core/scene/impostor.h"
#include "core/scene/lod.h"
#include "core/scene/scene.h"
#include "core/scene/shading.h"
#include "core/vulkan/barriers.h"
#include "core/vulkan/context.h"
#include "core/vulkan/gpu_scene.h"
#include "core/vulkan/resources.h"
#include "passes/billboard_pass.h"
#include "passes/environment_builder.h"
#include "passes/forward_pass.h"
#include "passes/impostor_capture.h"
#include "passes/scene_textures.h"
#include "passes/shadow_pass.h"
#include "passes/skybox_pass.h"

namespace shadelab {

// What an upload builds from a scene and keeps until the next upload:
// geometry, every texture with its mip chain, and the environment cube.
struct SceneUploadOptions {
  // Build the scene's environment cube (when it has one). Without it,
  // FrameSettings::environment has nothing to draw. The viewer builds it so
  // that E is a per-frame switch; renderToImage only when its settings use it.
  bool environmentCube = true;
  // Build each loaded mesh's chain of simplified levels (FrameSettings::lod
  // draws from it; without a chain every object is drawn in full).
  bool detailChains = false;
  // With detailChains: end each opaque, untextured chain in an impostor
  // whose atlas has this many cells per side (passes/impostor_capture.h);
  // 0: no impostors.
  uint32_t impostorCells = kImpostorCells;
};

// How a frame is drawn. Renderer::applyFrameSettings validates them once,
// when they change; recordScene applies them to every frame it records.
// Changing any of them re-uploads nothing.
struct FrameSettings {
  uint32_t width = 1280;
  uint32_t height = 720;
  ShadingModel shadingModel = ShadingModel::Phong;
  // Split screen: when not empty, the frame is cut into this many equal
  // columns, side by side, each drawn with its model and the same camera.
  std::vector<ShadingModel> splitModels;
  uint32_t msaaSamples = 1;  // 1 or 4 (what lavapipe offers)
  NormalTransform normalTransform = NormalTransform::InverseTranspose;
  // --filter (which material descriptor sets are bound), --bump and
  // --mip-tint (flags in the textured draws' push constants).
  TextureOptions textures;
  DepthMode depth = DepthMode::D32F;  // z-buffer format; ReversedZ: D32F, near -> 1, far -> 0
  bool frustumCulling = true;         // off only to show that culling changes no pixel
  bool wireframe = false;  // triangle edges drawn over the shaded image (needs fillModeNonSolid)
  // --env: with an environment cube (the scene's, built at upload), the
  // environment term and the skybox; off (or no cube) renders with the
  // background colour only.
  bool environment = true;
  // Shadow maps: the filter (off: no map is drawn or read) and the bias are
  // per-frame; the map size is a resource size, like width and height
  // (changing it rebuilds the map, waiting for the device).
  ShadowMethod shadows = ShadowMethod::Off;
  ShadowBias shadowBias;
  uint32_t shadowMapSize = kDefaultShadowMapSize;
  // Keep a map layer whose light view and casters have not changed since
  // it was drawn (ShadowPass says how); off redraws every layer every frame,
  // to time the maps themselves. Images are the same either way.
  bool keepShadowMaps = true;
  // Casters nearer than a light view's near plane are flattened onto it
  // (depth clamp); off clips them as any other pass would. Only study
  // shadow-near turns it off, to measure what the clamp saves.
  bool shadowDepthClamp = true;
  // Opaque draws front to back (visibleDraws), so early depth testing skips
  // the fragments they hide; off keeps the scene's order (`--draw-order
  // scene`). The z-fight study turns it off: it draws its two planes in both
  // orders, and sorted the nearer one would always come first and win every
  // depth tie.
  bool frontToBack = true;
  // Materials compiled into the forward pipelines, a pipeline per material,
  // when the scene has at most kMaxMaterialPipelines (ForwardFrame says why);
  // off reads them from push constants. A few linear values may differ by
  // one RGBA16F step between the two (tests/test_gltf_render.cpp).
  bool materialConstants = true;
  // The frame's ambient term and eye-space lights compiled into the forward
  // and billboard pipelines (ForwardFrame::lights), for runs whose camera
  // and lights hold still from frame to frame (`render --frames N`, `bench`).
  // They are built at the first frame recorded; when a later frame's lights
  // differ (the camera moved), every frame after it reads them from memory.
  bool lightConstants = false;
  // Cut-out and blended billboards drawn as one triangle around what their
  // texture can show (core/scene/billboard_outline.h) instead of the quad,
  // on single-sampled targets without anisotropic filtering; off draws
  // quads. The pixels are the quad's, up to the interpolation's rounding.
  bool trimBillboards = true;
  // --lod auto: each object with a detail chain (SceneUploadOptions) is
  // drawn at the coarsest level whose error, projected at the object's
  // nearest point, stays within lodErrorPixels (with hysteresis between
  // frames: core/scene/lod.h, chooseLevel). Shadow maps draw each caster at
  // the level the view drew it.
  bool lod = false;
  float lodErrorPixels = 0.5f;
  // A coarser level only once its error is below this fraction of
  // lodErrorPixels (0 < h <= 1); 1 turns the hysteresis off. Only study
  // lod-popping changes it, to measure what the default saves.
  float lodHysteresis = kLodHysteresis;
  // With lod: the cells per side of the impostor atlases the chains end in
  // (SceneUploadOptions::impostorCells; 0: chains end in meshes). Like lod,
  // read when the scene is uploaded: renderToImage and renderSequence pass
  // it on, the viewer uploads with it.
  uint32_t impostorCells = kImpostorCells;
  // Impostors drawn from the three atlas cells around the view direction,
  // blended (core/scene/impostor.h, impostorBlend), instead of the nearest
  // one: no seams where neighbouring copies take different cells and no
  // jump when a turning view crosses into another cell, for three times
  // the texture lookups per fragment (README, "Impostors").
  bool impostorBlend = false;
  // The visible copies of an "instances" block drawn as one instanced draw
  // per level (batchInstances); off draws them one by one, to show the
  // image is the same.
  bool instancing = true;
};

// renderToImage: one scene, uploaded once, drawn `frames` times.
struct RenderSettings : FrameSettings {
  uint32_t frames = 1;  // frames drawn back to back; the last one is read back
  // Read back as 8-bit sRGB into RenderResult::srgb8 (the codes encodeSrgb8
  // gives) instead of linear floats into RenderResult::image: a PNG's
  // pixels without the 4-bytes-a-channel image in between.
  bool srgb8 = false;
};

struct RenderStats {
  std::vector<double> deviceMs;  // per frame, from GPU timestamps around the frame's commands
  // Per frame, from the scene's start to the end of everything recorded after
  // it (a readback; the viewer's blit, overlay and screenshot copy).
  std::vector<double> frameDeviceMs;
  std::vector<double> wallMs;       // per frame, interval between successive frame completions
  std::vector<double> shadowMs;     // per frame, the shadow pass's share of deviceMs (0 without)
  uint32_t shadowDraws = 0;         // caster draws per frame, summed over the maps' layers
  uint64_t triangles = 0;           // submitted per frame (after culling)
  uint32_t drawCalls = 0;           // submitted per frame (after culling)
  uint32_t culledDraws = 0;         // objects outside the view frustum, not drawn
  uint32_t billboardInstances = 0;  // drawn per frame (after culling), in drawCalls' draws
  uint32_t culledInstances = 0;     // billboard instances outside the view frustum
  uint32_t coarserDraws = 0;        // --lod auto: draws at a simplified level, per frame
  uint32_t impostors = 0;           // --lod auto: of those, objects drawn as their impostor
  uint32_t trimmedInstances = 0;    // billboard copies drawn as their outline triangles
  // --lod auto, per frame: the objects (with a detail chain, in view) drawn
  // at each level, 0 in full, the last entry that level and every coarser
  // one; and the host time the choice took (Renderer::chooseLevels).
  std::array<uint32_t, 6> levelDraws{};
  double lodSelectMs = 0.0;
  // Device memory allocated in the process while the frames ran (target,
  // meshes, per-frame buffers, readback), from resources.h's accounting.
  uint64_t deviceMemoryBytes = 0;
};

struct RenderResult {
  ImageRgba image;  // linear RGBA, unless RenderSettings::srgb8
  ImageU8 srgb8;    // with RenderSettings::srgb8
  RenderStats stats;
};

// Semaphores a frame's submission waits on and signals (a swapchain's), if any.
struct FrameSync {
  VkSemaphore wait = VK_NULL_HANDLE;
  VkPipelineStageFlags2 waitStage = VK_PIPELINE_STAGE_2_NONE;
  VkSemaphore signal = VK_NULL_HANDLE;
  // The caller recorded commands of its own after recordScene (a blit, an
  // overlay): they are timed as part of the frame (RenderStats::frameDeviceMs).
  bool commandsAfterScene = false;
};

// The colour target's RGBA16F texels as read back by recordReadback.
ImageRgba unpackHalfImage(const void* data, uint32_t width, uint32_t height);

class Renderer {
 public:
  static constexpr uint32_t kFramesInFlight = 2;
  static constexpr VkFormat kColorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;  // linear, HDR

  explicit Renderer(const Context& context);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Throws InputError for impossible settings.
  RenderResult renderToImage(const Scene& scene, const RenderSettings& settings);
  // A sequence (turntable, camera path): the scene uploaded once, one frame
  // per camera, each read back and handed to `onFrame(index, image)` before
  // the next is drawn. settings.frames is ignored. Returns the stats of all
  // frames (triangles and draws: the last frame's).
  RenderStats renderSequence(const Scene& scene, const FrameSettings& settings,
                             const std::vector<Camera>& cameras,
                             const std::function<void(uint32_t, ImageRgba&&)>& onFrame);

  // The steps renderToImage is made of, for front ends that own the loop (the
  // viewer): upload a scene, applyFrameSettings (again whenever a setting
  // changes), then per frame waitForFrame, beginFrame, recordScene, optional
  // recordReadback and commands of their own on commandBuffer(), submitFrame.
  // Geometry, textures and (options.environmentCube) the environment cube;
  // waits for frames in flight, which may use the previous scene's textures.
  // Settings are applied again before the next recordScene.
  GpuScene upload(const Scene& scene, const SceneUploadOptions& options = {});
  // Throws InputError, changing nothing, for settings the device cannot draw
  // (size, MSAA, depth format, more split columns than pixels, anisotropy);
  // otherwise builds what they need (pipelines, the filter's material sets,
  // the target) and keeps them for recordScene. Never waits for the device
  // unless the target changes size, samples or depth format.
  void applyFrameSettings(const GpuScene& scene, const FrameSettings& settings);
  const FrameSettings& frameSettings() const { return settings_; }
  // How many times upload() ran: what a per-frame setting must not change.
  uint32_t uploadCount() const { return uploadCount_; }
  // Waits for the oldest frame in flight and appends its timings to `stats`.
  void waitForFrame(RenderStats& stats);
  VkCommandBuffer beginFrame();
  // Records `scene` (uploaded from `source`, whose camera and lights this
  // frame uses) with the applied settings; sets stats' per-frame counts
  // (draws and triangles after culling).
  void recordScene(const GpuScene& scene, const Scene& source, RenderStats& stats);
  // Copies the colour target into `readback` (width * height * 8 bytes, host-visible).
  void recordReadback(const Buffer& readback);
  void submitFrame(const FrameSync& sync = {});
  // Waits for every frame in flight, appending their timings in submission order.
  void finishFrames(RenderStats& stats);
  VkCommandBuffer commandBuffer() const { return frames_[frameIndex_ % kFramesInFlight].cmd; }
  uint32_t frameSlot() const { return frameIndex_ % kFramesInFlight; }

  // What recordScene drew, for a step that copies it on (presentation); a
  // step that changes its layout records the new use.
  const Image& colorTarget() const { return targets_[frameSlot()].color; }
  ImageUse& colorTargetUse() { return targets_[frameSlot()].colorUse; }

  // The shader table rows the passes reload (shaders/CMakeLists.txt).
  static std::vector<ShaderVariant> shaderVariants();
  // Replaces the passes' shaders (SPIR-V by row name; every row of
  // shaderVariants() present) and rebuilds their pipelines. Waits for the device.
  void reloadShaders(const std::map<std::string, std::vector<uint32_t>>& spirv);

 private:
  struct Frame {
    CommandPool pool;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    Fence fence;
    QueryPool timestamps;
    Buffer frameData;   // FrameData, host-visible
    Buffer objectData;  // ObjectData[], host-visible
    Buffer shadowData;  // ShadowData, host-visible
    uint32_t objectCapacity = 0;
    VkDescriptorSet set = VK_NULL_HANDLE;
    bool pending = false;             // submitted, fence not yet waited on
    uint32_t writtenTimestamps = 0;   // bit i: query i was written this frame
    bool commandsAfterScene = false;  // recordReadback ran this frame
  };
  // One per frame in flight, made on the slot's first frame: a frame never
  // draws into images the frame before it may still be drawing, so needs no
  // barrier while they stay attachments (beginRendering says why that pays).
  struct Target {
    Image color;  // single-sampled: what is read back
    Image depth;
    Image multisampled;  // colour when msaaSamples > 1, resolved into `color`
    ImageUse colorUse = ImageUse::Undefined;
    ImageUse depthUse = ImageUse::Undefined;
    ImageUse multisampledUse = ImageUse::Undefined;
  };
  struct TargetShape {
    uint32_t width = 0;
    uint32_t height = 0;
    TargetLayout layout;
    bool operator==(const TargetShape&) const = default;
  };

  // The forward pass's settings of frames drawn with `settings` (set 0 and
  // the material sets are the frame's own; recordScene fills them in).
  ForwardFrame forwardFrame(const GpuScene& scene, const FrameSettings& settings) const;
  // Builds the forward and billboard pipelines `forward` draws with (those
  // built before are kept).
  void preparePipelines(const GpuScene& scene, const ForwardFrame& forward);
  // FrameSettings::lightConstants: puts this frame's light values into
  // `forward` while they stay those of the first frame, building the
  // pipelines they need on the way.
  void compileLights(const GpuScene& scene, const gpu::FrameData& frameData, ForwardFrame& forward);
  void createFrame(Frame& frame);
  void ensureObjectCapacity(Frame& frame, uint32_t count);
  // Throws InputError for settings the device cannot draw `scene` with.
  void validate(const GpuScene& scene, const FrameSettings& settings) const;
  // Throws InputError when the device cannot use the depth format as an attachment.
  void checkDepthSupport(DepthMode mode) const;
  // Sets the targets' size and layout; drops images of another shape.
  void ensureTarget(uint32_t width, uint32_t height, TargetLayout layout);
  // The frame slot's target, its images made if not yet.
  Target& frameTarget();
  void beginRendering(VkCommandBuffer cmd, const Scene& source, uint32_t width, uint32_t height);
  // Waits for the frame's previous submission and records its timings.
  void retire(Frame& frame, RenderStats& stats);
  // Builds the scene's cube (kept while the scene's environment stays the
  // same) or picks the placeholder, and points every frame's descriptor at
  // it; call with no frame in flight.
  void bindEnvironment(const Scene& scene, bool enabled);
  void writeSampledImage(const Frame& frame, uint32_t binding, VkSampler sampler,
                         VkImageView view) const;
  void writeEnvironmentDescriptor(const Frame& frame) const;
  void writeShadowMapDescriptor(const Frame& frame) const;
  // The shadow pass of a frame (with shadows on and some light casting).
  // The transparent draws and the blended billboards, back to front together.
  void recordTransparent(VkCommandBuffer cmd, ShadingModel model, const ForwardFrame& forwardFrame,
                         const GpuScene& scene, std::span<const DrawItem> transparent,
                         const BillboardFrame& billboards, const glm::mat4& view,
                         const VkViewport& viewport) const;
  // --lod auto: each draw's level for this frame, in place of its full range;
  // draws that chose their impostor leave `draws` for `impostors`.
  void chooseLevels(const GpuScene& scene, const Scene& source, std::vector<DrawItem>& draws,
                    std::vector<ImpostorCopy>& impostors, RenderStats& stats);
  // Level `level` of the draw's chain in place of its range (0: in full);
  // for the impostor level, the coarsest mesh before it (what casts its shadow).
  static void applyLevel(const GpuScene& scene, DrawItem& draw, uint32_t level);
  void recordShadows(VkCommandBuffer cmd, Frame& frame, const GpuScene& scene, const Scene& source,
                     const glm::mat4& view, const glm::mat4& projection, RenderStats& stats);

  const Context& context_;
  LightSets lightSets_;  // every set compiled in so far, for the passes' keys
  ForwardPass forward_;
  SceneTextures textures_;
  SkyboxPass skybox_;
  ShadowPass shadow_;
  BillboardPass billboards_;
  ImpostorCapture impostors_;
  EnvironmentBuilder environmentBuilder_;
  EnvironmentCube placeholderEnvironment_;
  EnvironmentCube sceneEnvironment_;    // empty when the scene has none or it is off
  Environment sceneEnvironmentSource_;  // what sceneEnvironment_ was built from
  DescriptorPool descriptorPool_;
  std::array<Frame, kFramesInFlight> frames_;
  uint64_t frameIndex_ = 0;  // frames begun; the slot is frameIndex_ % kFramesInFlight
  double lastCompletion_ = 0.0;
  std::array<Target, kFramesInFlight> targets_;  // by frame slot
  TargetShape targetShape_;
  std::vector<uint32_t> drawnLevels_;  // by object: the level of its last frame (--lod auto)
  FrameSettings settings_;             // as last applied
  bool settingsApplied_ = false;       // since the last upload
  // FrameSettings::lightConstants, since the settings were applied: the
  // values compiled in, whether a frame's differed, and which of the two
  // sets of pipelines (with the values, without) prepare has built.
  std::optional<LightValues> compiledLights_;
  bool lightsMoved_ = false;
  std::optional<bool> preparedWithLights_;
  uint32_t uploadCount_ = 0;
};

}  // namespace shadelab
