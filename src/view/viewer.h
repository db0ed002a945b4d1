#pragma once
// The interactive viewer: a window showing the scene drawn by the same
// Renderer as headless capture, blitted into the swapchain, with a text
// overlay; keys toggle FrameSettings, the mouse moves the camera, and a
// script can drive all of it (tests, README screenshots).
#include <array>
#include <deque>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/metrics/metrics.h"
#include "core/vulkan/context.h"
#include "core/vulkan/gpu_scene.h"
#include "passes/renderer.h"
#include "view/background_trace.h"
#include "view/camera_controller.h"
#include "view/overlay.h"
#include "view/swapchain.h"
#include "view/viewer_script.h"
#include "view/window.h"

namespace shadelab {

// A and --tess auto: the chord error bound, in pixels (render --tess-error's default).
inline constexpr float kAutoTessellationErrorPixels = 0.5f;

struct ViewerOptions {
  VkPresentModeKHR presentMode = VK_PRESENT_MODE_FIFO_KHR;
  std::optional<std::vector<ScriptStep>> script;  // none: interactive
  std::filesystem::path shaderDirectory;          // where R reloads GLSL from
  uint32_t metricsInterval = 30;                  // frames between split-screen error readbacks
  uint32_t referenceSamplesPerPixel = 4;          // X's traced reference, as compare's default
  FrameSettings initial;                          // model, MSAA, ...; the size follows the window
  float tessellation = 1.0f;                      // as render --tess; T and G change it
  bool autoTessellation = false;  // --tess auto: tessellate for the initial view (as A does)
  // --key-latency: print, per key, the wall time from handling it to the next
  // frame's present and to that frame finishing on the device.
  bool logKeyLatency = false;
};

class Viewer;
struct KeyBinding {
  int key = 0;       // GLFW key code
  std::string name;  // as typed in a script: "1", "C"
  std::string help;
  std::function<void(Viewer&)> action;
};

class Viewer {
 public:
  Viewer(Window& window, const Context& context, Scene scene, const ViewerOptions& options);
  ~Viewer();
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  // Until the window closes or the script ends.
  void run();
  static const std::vector<KeyBinding>& keyBindings();
  static std::vector<std::string> keyNames();

 private:
  // What a split column shows and the reference must be traced for: the
  // camera's matrices, the first (narrowest) column's size, the scene's upload.
  struct ReferenceView {
    glm::mat4 view{1.0f}, projection{1.0f};
    uint32_t width = 0, height = 0;
    uint32_t upload = 0;
    bool operator==(const ReferenceView&) const = default;
  };
  // What a frame slot still has to do once its fence has signalled.
  struct SlotWork {
    Buffer screenshot;
    std::string screenshotPath;
    Camera
        screenshotCamera;  // the frame's, for the sidecar (the view may move before it is written)
    VkExtent2D screenshotExtent{};
    Buffer metrics;
    bool metricsPending = false;
    FrameSettings metricsSettings;
    std::optional<ReferenceView> metricsView;  // the reference's view when the frame was drawn
  };
  // One split column's error against the Phong column or the traced reference.
  struct SplitError {
    ShadingModel model;
    ImageDifference difference;
    std::optional<double> flip;  // against the reference only (FLIP costs more)
  };

  bool advanceScript();
  void runStep(const ScriptStep& step);
  void handleEvents();
  void handleKey(int key);
  bool drawFrame();  // false when nothing was presented
  void recreateSwapchain();
  void finishSlotWork(SlotWork& work);
  void computeSplitErrors(const SlotWork& work);
  // The split screen's current view as the reference sees it; none with split screen off.
  std::optional<ReferenceView> referenceView() const;
  // Per frame with X on: collects a finished trace, cancels a stale one and
  // starts one for the view once the camera has stopped (the same view two
  // frames running).
  void updateReference();
  void setMeasureAgainstReference(bool on);
  void waitForReference();
  std::string referenceStatus() const;
  OverlayText overlayText() const;
  void say(const std::string& message, bool error = false);
  void notAvailable(const std::string& feature);
  // Every settings change goes through here: the renderer validates it once;
  // on InputError the message shows and the current settings stay.
  bool applySettings(const FrameSettings& next);
  bool applyTextureOptions(const TextureOptions& textures, const std::string& message);
  bool followSwapchainSize();
  // Geometry, textures and the environment cube (built even when the
  // environment is off, so E only switches it), then the settings again.
  void uploadScene();
  void setModel(ShadingModel model);
  void setTessellation(float scale);
  void autoTessellate();
  void reloadShaders();
  std::string nextScreenshotName() const;
  void reportKeyLatency(double presented);

  Window& window_;
  const Context& context_;
  Scene scene_;
  ViewerOptions options_;
  Surface surface_;
  Renderer renderer_;
  GpuScene gpuScene_;
  Swapchain swapchain_;
  std::unique_ptr<Overlay> overlay_;
  std::array<Semaphore, Renderer::kFramesInFlight> imageAvailable_;
  std::array<SlotWork, Renderer::kFramesInFlight> slotWork_;
  Camera sceneCamera_;  // as loaded; scene_.camera follows camera_
  CameraController camera_;
  FrameSettings settings_;  // as applied to renderer_

  float tessellation_;
  bool overlayVisible_ = true;
  bool helpVisible_ = false;
  bool minimizedByScript_ = false;
  bool minimized_ = false;
  bool swapchainStale_ = true;
  bool quit_ = false;
  std::optional<MouseButton> dragging_;
  glm::vec2 lastMouse_{0.0f};

  std::deque<double> deviceMs_, frameDeviceMs_, wallMs_, shadowMs_;  // the last 120 frames
  uint64_t framesDrawn_ = 0;
  uint64_t submittedTriangles_ = 0;       // last frame, after frustum culling, per view
  uint32_t coarserDraws_ = 0;             // last frame: draws at a simplified level (--lod)
  uint32_t impostors_ = 0;                // last frame: of those, objects drawn as impostors
  uint32_t billboardCopies_ = 0;          // last frame: billboard copies drawn
  uint32_t trimmedCopies_ = 0;            // last frame: of those, as their outline triangles
  std::array<uint32_t, 6> levelDraws_{};  // last frame: objects per level (--lod)
  std::deque<double> lodSelectMs_;        // host time choosing the levels, the last 120 frames
  uint32_t swapchainBuilds_ = 0, outOfDate_ = 0, suboptimal_ = 0;
  std::vector<SplitError> splitErrors_;
  bool splitErrorsAgainstReference_ = false;
  // X: split-screen errors against the traced reference instead of Phong.
  bool measureAgainstReference_ = false;
  BackgroundTrace reference_;
  std::optional<ReferenceView> referenceRequested_;  // the view traced or being traced
  std::optional<ReferenceView> previousView_;        // last frame's, to see the camera stop
  bool referenceMeasured_ = false;    // errors against the current reference computed
  bool waitingForReference_ = false;  // script step wait-reference
  std::string message_;
  bool messageIsError_ = false;
  std::string screenshotRequest_;
  double lastFrameTime_ = 0.0;
  // Keys handled since the last presented frame, with when (--key-latency).
  std::vector<std::pair<std::string, double>> keysAwaitingFrame_;

  size_t scriptPosition_ = 0;
  uint32_t framesToRun_ = 0;
  std::deque<Camera> pathCameras_;  // a script's camera-path step: the frames still to draw
  int scriptLine_ = 0;
};

}  // namespace shadelab
