#pragma once
// The renderer every front end shares (CLI, tests, benchmark, viewer): it
// owns the frames in flight and the render target and runs the passes.
// Headless capture is one call: renderToImage(scene, settings).
#include <array>
#include <memory>
#include <vector>

#include "core/barriers.h"
#include "core/context.h"
#include "core/gpu_scene.h"
#include "core/image.h"
#include "core/resources.h"
#include "core/scene.h"
#include "core/shading.h"
#include "passes/environment_builder.h"
#include "passes/forward_pass.h"
#include "passes/scene_textures.h"
#include "passes/skybox_pass.h"

namespace shadelab {

struct RenderSettings {
  uint32_t width = 1280;
  uint32_t height = 720;
  ShadingModel shadingModel = ShadingModel::Phong;
  uint32_t frames = 1;  // frames drawn back to back; the last one is read back
  uint32_t msaaSamples = 1;  // 1 or 4 (what lavapipe offers)
  // Split screen: when not empty, the frame is cut into this many equal
  // columns, side by side, each drawn with its model and the same camera.
  std::vector<ShadingModel> splitModels;
  NormalTransform normalTransform = NormalTransform::InverseTranspose;
  TextureOptions textures;  // --filter override, --bump, --mip-tint
  DepthMode depth = DepthMode::D32F;  // z-buffer format; ReversedZ: D32F, near -> 1, far -> 0
  bool frustumCulling = true;  // off only to show that culling changes no pixel
  // --env: with a scene environment, the environment term and the skybox;
  // off (or a scene without one) renders with the background colour only.
  bool environment = true;
};

struct RenderStats {
  std::vector<double> deviceMs;  // per frame, from GPU timestamps around the frame's commands
  std::vector<double> wallMs;    // per frame, interval between successive frame completions
  uint64_t triangles = 0;        // submitted per frame (after culling)
  uint32_t drawCalls = 0;        // submitted per frame (after culling)
  uint32_t culledDraws = 0;      // objects outside the view frustum, not drawn
  // Device memory allocated in the process while the frames ran (target,
  // meshes, per-frame buffers, readback), from resources.h's accounting.
  uint64_t deviceMemoryBytes = 0;
};

struct RenderResult {
  ImageRgba image;  // linear RGBA
  RenderStats stats;
};

class Renderer {
 public:
  static constexpr uint32_t kFramesInFlight = 2;
  static constexpr VkFormat kColorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;  // linear, HDR

  explicit Renderer(const Context& context);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Throws InputError for an impossible size.
  RenderResult renderToImage(const Scene& scene, const RenderSettings& settings);

 private:
  struct Frame {
    CommandPool pool;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    Fence fence;
    QueryPool timestamps;
    Buffer frameData;    // FrameData, host-visible
    Buffer objectData;   // ObjectData[], host-visible
    uint32_t objectCapacity = 0;
    VkDescriptorSet set = VK_NULL_HANDLE;
    bool pending = false;  // submitted, fence not yet waited on
  };
  struct Target {
    Image color;         // single-sampled: what is read back
    Image depth;
    Image multisampled;  // colour when msaaSamples > 1, resolved into `color`
    ImageUse colorUse = ImageUse::Undefined;
    ImageUse depthUse = ImageUse::Undefined;
    ImageUse multisampledUse = ImageUse::Undefined;
    TargetLayout layout;
  };

  void createFrame(Frame& frame);
  void ensureObjectCapacity(Frame& frame, uint32_t count);
  // Throws InputError when the device cannot use the depth format as an attachment.
  void checkDepthSupport(DepthMode mode) const;
  void ensureTarget(uint32_t width, uint32_t height, TargetLayout layout);
  void beginRendering(VkCommandBuffer cmd, const Scene& source, uint32_t width, uint32_t height);
  // Waits for the frame's previous submission and records its timings.
  void retire(Frame& frame, RenderStats& stats, double& lastCompletion);
  void recordFrame(Frame& frame, const GpuScene& scene, const Scene& source,
                   const RenderSettings& settings, const Buffer* readback, RenderStats& stats);
  // Builds the scene's cube (kept while the scene's environment stays the
  // same) or picks the placeholder, and points every frame's descriptor at
  // it; call with no frame in flight.
  void bindEnvironment(const Scene& scene, bool enabled);
  void writeEnvironmentDescriptor(const Frame& frame) const;

  const Context& context_;
  ForwardPass forward_;
  SceneTextures textures_;
  SkyboxPass skybox_;
  EnvironmentBuilder environmentBuilder_;
  EnvironmentCube placeholderEnvironment_;
  EnvironmentCube sceneEnvironment_;    // empty when the scene has none or it is off
  Environment sceneEnvironmentSource_;  // what sceneEnvironment_ was built from
  DescriptorPool descriptorPool_;
  std::array<Frame, kFramesInFlight> frames_;
  Target target_;
};

}  // namespace shadelab
