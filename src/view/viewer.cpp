#include "view/viewer.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#include "core/base/errors.h"
#include "core/base/files.h"
#include "core/base/image.h"
#include "core/base/split_screen.h"
#include "core/base/stats.h"
#include "core/scene/camera_path.h"
#include "core/scene/lod.h"
#include "core/vulkan/vk_check.h"
#include "view/present_pass.h"

namespace shadelab {
namespace {

constexpr size_t kTimingWindow = 120;

double nowSeconds() {
  using Clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
}

void pushBounded(std::deque<double>& samples, const std::vector<double>& values) {
  for (double value : values) {
    samples.push_back(value);
    if (samples.size() > kTimingWindow) samples.pop_front();
  }
}

long residentKilobytes() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmRSS:") {
      long kilobytes = 0;
      status >> kilobytes;
      return kilobytes;
    }
    status.ignore(4096, '\n');
  }
  return -1;
}

// A swapchain image as read back: 4 bytes per pixel, BGRA or RGBA.
ImageU8 toImage(const Buffer& buffer, VkExtent2D extent, VkFormat format) {
  ImageU8 image(extent.width, extent.height);
  const auto* bytes = static_cast<const uint8_t*>(buffer.mapped());
  bool bgra = format == VK_FORMAT_B8G8R8A8_SRGB || format == VK_FORMAT_B8G8R8A8_UNORM;
  for (size_t p = 0; p < size_t(extent.width) * extent.height; ++p) {
    const uint8_t* texel = bytes + p * 4;
    image.pixels[p * 4 + 0] = bgra ? texel[2] : texel[0];
    image.pixels[p * 4 + 1] = texel[1];
    image.pixels[p * 4 + 2] = bgra ? texel[0] : texel[2];
    image.pixels[p * 4 + 3] = 255;  // presented opaque
  }
  return image;
}

Semaphore createSemaphore(VkDevice device) {
  VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VkSemaphore semaphore = VK_NULL_HANDLE;
  VK_CHECK(vkCreateSemaphore(device, &info, nullptr, &semaphore));
  return Semaphore(device, semaphore);
}

}  // namespace

Viewer::Viewer(Window& window, const Context& context, Scene scene, const ViewerOptions& options)
    : window_(window),
      context_(context),
      scene_(std::move(scene)),
      options_(options),
      surface_(context.instance(), window.createSurface(context.instance())),
      renderer_(context),
      swapchain_(context, surface_.get(), options.presentMode),
      sceneCamera_(scene_.camera),
      camera_(scene_.camera),
      settings_(options.initial),
      tessellation_(options.tessellation) {
  if (tessellation_ != 1.0f) scene_.retessellate(tessellation_);
  glm::ivec2 size = window.framebufferSize();
  if (size.x > 0 && size.y > 0) {
    settings_.width = uint32_t(size.x);
    settings_.height = uint32_t(size.y);
  }
  if (options.autoTessellation && settings_.width > 0 && settings_.height > 0)
    tessellateForView(scene_, ViewSize{camera_.camera(), settings_.width, settings_.height},
                      kAutoTessellationErrorPixels);
  // Settings the device cannot draw are an InputError here, before any frame.
  uploadScene();
  for (Semaphore& semaphore : imageAvailable_) semaphore = createSemaphore(context.device());
  swapchain_.recreate({uint32_t(size.x), uint32_t(size.y)});
  overlay_ = std::make_unique<Overlay>(context, swapchain_.format(), swapchain_.minImageCount(),
                                       std::max(3u, swapchain_.imageCount()));
  if (swapchain_.valid()) {
    overlay_->setTargets(swapchain_.views(), swapchain_.extent(), swapchain_.minImageCount());
    swapchainStale_ = false;
    ++swapchainBuilds_;
  }
  lastFrameTime_ = nowSeconds();
}

Viewer::~Viewer() {
  context_.waitIdle();
}

void Viewer::say(const std::string& message, bool error) {
  message_ = message;
  messageIsError_ = error;
  std::printf("view: %s\n", message.c_str());
  std::fflush(stdout);
}

void Viewer::run() {
  while (!quit_) {
    // A script that ends (or quits) right after keys still has them
    // handled, and draws one more frame for them: a setting is drawn, P's
    // screenshot written, V's camera printed.
    bool scriptGoesOn = !options_.script || advanceScript();
    if (!options_.script && minimized_)
      window_.waitEvents(0.1);  // nothing to draw: sleep until something happens
    else
      window_.pollEvents();
    bool keysPending = !window_.events().empty();
    handleEvents();
    if (window_.closeRequested()) break;
    if (!scriptGoesOn) {
      if (keysPending && !minimized_) drawFrame();
      break;
    }
    glm::ivec2 size = window_.framebufferSize();
    bool wasMinimized = minimized_;
    minimized_ = minimizedByScript_ || window_.iconified() || size.x == 0 || size.y == 0;
    if (wasMinimized && !minimized_) swapchainStale_ = true;  // restored: rebuild for the new state
    // A script's frame is a presented one (an out-of-date swapchain is
    // rebuilt first), or an idle tick while minimised.
    bool presented = !minimized_ && drawFrame();
    if (framesToRun_ > 0 && (presented || minimized_)) {
      --framesToRun_;
      // A camera path's frame ticks by while minimised too, so the path ends
      // with its frames and later steps see its last camera.
      if (!presented && !pathCameras_.empty()) {
        camera_.set(pathCameras_.front());
        pathCameras_.pop_front();
      }
    }
    if (waitingForReference_) waitForReference();
  }
  RenderStats stats;
  renderer_.finishFrames(stats);
  for (SlotWork& work : slotWork_) finishSlotWork(work);
  reference_.cancel();
  std::vector<double> device(deviceMs_.begin(), deviceMs_.end());
  std::vector<double> frameDevice(frameDeviceMs_.begin(), frameDeviceMs_.end());
  std::vector<double> wall(wallMs_.begin(), wallMs_.end());
  if (device.empty())
    std::printf(
        "view: %llu frames; none timed (a frame's times are read when its slot is reused)\n",
        static_cast<unsigned long long>(framesDrawn_));
  else
    std::printf(
        "view: %llu frames; median of the last %zu: %.3f ms device (scene), %.3f ms device "
        "(frame), %.3f ms wall\n",
        static_cast<unsigned long long>(framesDrawn_), device.size(), median(device),
        median(frameDevice), median(wall));
  std::printf("view: swapchain built %u times (%u out of date, %u suboptimal)\n", swapchainBuilds_,
              outOfDate_, suboptimal_);
  std::printf("view: %u scene uploads (geometry, textures, environment)\n",
              renderer_.uploadCount());
  if (!lodSelectMs_.empty()) {
    std::vector<double> select(lodSelectMs_.begin(), lodSelectMs_.end());
    std::printf(
        "view: levels of detail chosen in %.3f ms per frame (median of the last %zu), "
        "%zu objects\n",
        median(select), select.size(), scene_.objects.size());
  }
}

void Viewer::uploadScene() {
  gpuScene_ = renderer_.upload(scene_, {.environmentCube = true,
                                        .detailChains = settings_.lod,
                                        .impostorCells = settings_.impostorCells});
  renderer_.applyFrameSettings(gpuScene_, settings_);
}

bool Viewer::applySettings(const FrameSettings& next) {
  try {
    renderer_.applyFrameSettings(gpuScene_, next);
  } catch (const InputError& error) {
    say(error.what(), true);
    return false;
  }
  settings_ = next;
  referenceMeasured_ = false;  // the columns changed: measure them again
  return true;
}

// The frame follows the swapchain's size. A window narrower than the split
// screen's columns cannot show them: split screen goes off, saying why.
bool Viewer::followSwapchainSize() {
  VkExtent2D extent = swapchain_.extent();
  if (extent.width == settings_.width && extent.height == settings_.height) return true;
  FrameSettings resized = settings_;
  resized.width = extent.width;
  resized.height = extent.height;
  if (applySettings(resized)) return true;
  resized.splitModels.clear();
  if (!applySettings(resized)) return false;
  splitErrors_.clear();
  say("split screen off: the window is narrower than its columns", true);
  return true;
}

bool Viewer::advanceScript() {
  const std::vector<ScriptStep>& steps = *options_.script;
  while (framesToRun_ == 0 && !quit_) {
    if (scriptPosition_ >= steps.size()) return false;
    const ScriptStep& step = steps[scriptPosition_++];
    scriptLine_ = step.line;
    runStep(step);
  }
  return !quit_;
}

void Viewer::runStep(const ScriptStep& step) {
  switch (step.kind) {
    case ScriptStep::Kind::Key:
      window_.events().push_back({InputEvent::Kind::Key, step.key});
      break;
    case ScriptStep::Kind::Frames:
      framesToRun_ = step.count;
      break;
    case ScriptStep::Kind::Drag:
      window_.injectButton(step.button, true, step.from);
      window_.injectMove(step.to);
      window_.injectButton(step.button, false, step.to);
      break;
    case ScriptStep::Kind::Scroll: {
      InputEvent event{InputEvent::Kind::Scroll};
      event.scroll = step.scroll;
      window_.events().push_back(event);
      break;
    }
    case ScriptStep::Kind::Resize: {
      window_.setSize(step.width, step.height);
      // The X server applies the size asynchronously; wait (bounded) for it.
      double deadline = nowSeconds() + 2.0;
      while (window_.framebufferSize() != glm::ivec2(step.width, step.height) &&
             nowSeconds() < deadline)
        window_.waitEvents(0.01);
      swapchainStale_ = true;
      break;
    }
    case ScriptStep::Kind::Minimize:
      // Without a window manager (Xvfb) the X server ignores iconify
      // requests, so the script also puts the viewer in its minimised state.
      window_.iconify();
      minimizedByScript_ = true;
      break;
    case ScriptStep::Kind::Restore:
      window_.restore();
      minimizedByScript_ = false;
      break;
    case ScriptStep::Kind::Screenshot:
      screenshotRequest_ = step.path;
      framesToRun_ = 1;
      break;
    case ScriptStep::Kind::Memory:
      std::printf("view: memory VmRSS %ld kB after %llu frames\n", residentKilobytes(),
                  static_cast<unsigned long long>(framesDrawn_));
      std::fflush(stdout);
      break;
    case ScriptStep::Kind::WaitReference:
      // Checked after this frame's events, which may hold the script's X.
      waitingForReference_ = true;
      framesToRun_ = 1;
      break;
    case ScriptStep::Kind::CameraPath:
      pathCameras_.clear();
      // Checked against this scene's camera before the window opened
      // (checkScriptCameraPaths), so this does not throw.
      for (const Camera& camera : parseCameraPath(step.text, step.path, sceneCamera_))
        pathCameras_.push_back(camera);
      framesToRun_ = uint32_t(pathCameras_.size());
      break;
    case ScriptStep::Kind::Quit:
      quit_ = true;
      break;
  }
}

void Viewer::handleEvents() {
  float viewHeight = float(window_.windowSize().y);
  while (!window_.events().empty()) {
    InputEvent event = window_.events().front();
    window_.events().pop_front();
    switch (event.kind) {
      case InputEvent::Kind::Key:
        handleKey(event.key);
        break;
      case InputEvent::Kind::ButtonDown:
        dragging_ = event.button;
        lastMouse_ = event.position;
        break;
      case InputEvent::Kind::ButtonUp:
        dragging_.reset();
        break;
      case InputEvent::Kind::Move:
        if (dragging_ == MouseButton::Left)
          camera_.orbit(event.position - lastMouse_, viewHeight);
        else if (dragging_)
          camera_.pan(event.position - lastMouse_, viewHeight);
        lastMouse_ = event.position;
        break;
      case InputEvent::Kind::Scroll:
        camera_.zoom(event.scroll);
        break;
    }
  }
}

void Viewer::recreateSwapchain() {
  glm::ivec2 size = window_.framebufferSize();
  if (!swapchain_.recreate({uint32_t(size.x), uint32_t(size.y)})) return;
  ++swapchainBuilds_;
  overlay_->setTargets(swapchain_.views(), swapchain_.extent(), swapchain_.minImageCount());
  swapchainStale_ = false;
}

bool Viewer::drawFrame() {
  glm::ivec2 size = window_.framebufferSize();
  VkExtent2D current = swapchain_.extent();
  if (swapchainStale_ || !swapchain_.valid() || int(current.width) != size.x ||
      int(current.height) != size.y)
    recreateSwapchain();
  if (!swapchain_.valid() || swapchainStale_ || !followSwapchainSize()) return false;

  uint32_t slot = renderer_.frameSlot();
  RenderStats stats;
  renderer_.waitForFrame(stats);
  pushBounded(deviceMs_, stats.deviceMs);
  pushBounded(frameDeviceMs_, stats.frameDeviceMs);
  pushBounded(shadowMs_, stats.shadowMs);
  pushBounded(wallMs_, stats.wallMs);
  finishSlotWork(slotWork_[slot]);

  uint32_t imageIndex = 0;
  SwapchainStatus status = swapchain_.acquire(imageAvailable_[slot], imageIndex);
  if (status == SwapchainStatus::OutOfDate) {
    ++outOfDate_;
    swapchainStale_ = true;
    return false;
  }
  if (status == SwapchainStatus::Suboptimal) {  // draw this one, then rebuild
    ++suboptimal_;
    swapchainStale_ = true;
  }

  VkExtent2D extent = swapchain_.extent();
  if (!pathCameras_.empty()) {  // a script's camera path: one camera per frame
    camera_.set(pathCameras_.front());
    pathCameras_.pop_front();
  }
  scene_.camera = camera_.camera();
  updateReference();
  VkCommandBuffer cmd = renderer_.beginFrame();
  RenderStats counts;
  renderer_.recordScene(gpuScene_, scene_, counts);
  submittedTriangles_ = counts.triangles;
  coarserDraws_ = counts.coarserDraws;
  impostors_ = counts.impostors;
  billboardCopies_ = counts.billboardInstances;
  trimmedCopies_ = counts.trimmedInstances;
  levelDraws_ = counts.levelDraws;
  if (settings_.lod) pushBounded(lodSelectMs_, {counts.lodSelectMs});

  SlotWork& work = slotWork_[slot];
  // Against Phong, every metricsInterval frames; against a traced reference,
  // once per reference and settings (FLIP per column costs more than RMSE).
  bool againstReference =
      measureAgainstReference_ && reference_.state() == BackgroundTrace::State::Ready;
  bool metricsDue = !settings_.splitModels.empty() &&
                    (againstReference ? !referenceMeasured_
                                      : splitErrors_.empty() || splitErrorsAgainstReference_ ||
                                            framesDrawn_ % options_.metricsInterval == 0);
  if (metricsDue) {
    VkDeviceSize bytes = VkDeviceSize(extent.width) * extent.height * 8;
    if (!work.metrics || work.metrics.size() < bytes)
      work.metrics =
          Buffer(context_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::HostVisible);
    renderer_.recordReadback(work.metrics);
    work.metricsPending = true;
    work.metricsSettings = settings_;
    work.metricsView = referenceView();
  }
  VkImage image = swapchain_.image(imageIndex);
  recordBlitToSwapchain(cmd, renderer_.colorTarget(), renderer_.colorTargetUse(), image, extent);
  double now = nowSeconds();
  if (overlayVisible_)
    overlay_->record(cmd, imageIndex, overlayText(), float(now - lastFrameTime_));
  lastFrameTime_ = now;
  const Buffer* screenshot = nullptr;
  if (!screenshotRequest_.empty()) {
    work.screenshot = Buffer(context_, VkDeviceSize(extent.width) * extent.height * 4,
                             VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::HostVisible);
    work.screenshotPath = std::exchange(screenshotRequest_, {});
    work.screenshotExtent = extent;
    work.screenshotCamera = camera_.camera();
    screenshot = &work.screenshot;
  }
  recordPresentTransition(cmd, image, extent, screenshot);
  renderer_.submitFrame({.wait = imageAvailable_[slot],
                         .waitStage = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                         .signal = swapchain_.renderingDone(imageIndex),
                         .commandsAfterScene = true});
  status = swapchain_.present(imageIndex);
  if (status != SwapchainStatus::Ok) {
    ++(status == SwapchainStatus::OutOfDate ? outOfDate_ : suboptimal_);
    swapchainStale_ = true;
  }
  ++framesDrawn_;
  if (!keysAwaitingFrame_.empty()) reportKeyLatency(nowSeconds());
  return true;
}

// The frame just presented is the first to show the keys' effect; waiting for
// it here (only when a key is being timed) gives the time it finished on the
// device, which lavapipe reaches after the present call has returned.
void Viewer::reportKeyLatency(double presented) {
  RenderStats stats;
  renderer_.finishFrames(stats);
  pushBounded(deviceMs_, stats.deviceMs);
  pushBounded(frameDeviceMs_, stats.frameDeviceMs);
  pushBounded(shadowMs_, stats.shadowMs);
  pushBounded(wallMs_, stats.wallMs);
  double finished = nowSeconds();
  for (const auto& [name, handled] : keysAwaitingFrame_)
    std::printf(
        "view: key %s latency: %.2f ms to the next frame's present, %.2f ms to its end on "
        "the device\n",
        name.c_str(), (presented - handled) * 1e3, (finished - handled) * 1e3);
  std::fflush(stdout);
  keysAwaitingFrame_.clear();
}

void Viewer::finishSlotWork(SlotWork& work) {
  if (!work.screenshotPath.empty()) {
    writeImage(toImage(work.screenshot, work.screenshotExtent, swapchain_.format()),
               work.screenshotPath);
    // The sidecar: what a headless render of this view needs.
    std::filesystem::path sidecar =
        std::filesystem::path(work.screenshotPath).replace_extension(".json");
    const Camera& camera = work.screenshotCamera;
    std::string name;
    for (char c : scene_.name)
      name += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
    writeTextFile(sidecar, "{\"scene\": \"" + name + "\",\n \"camera\": " + cameraJson(camera) +
                               ",\n \"options\": \"" + cameraOptionLine(camera) + "\"}\n");
    say("wrote " + work.screenshotPath + " (" + std::to_string(work.screenshotExtent.width) + "x" +
        std::to_string(work.screenshotExtent.height) + ", as presented) and " + sidecar.string());
    work.screenshotPath.clear();
    work.screenshot = Buffer();
  }
  if (work.metricsPending) {
    computeSplitErrors(work);
    work.metricsPending = false;
  }
}

// Each split-screen column against the traced reference (X, once it is
// ready for the view the frame shows) or else against the Phong column: the
// same camera and view, so the difference is the shading model's alone.
void Viewer::computeSplitErrors(const SlotWork& work) {
  const FrameSettings& used = work.metricsSettings;
  ImageU8 frame = encodeSrgb8(unpackHalfImage(work.metrics.mapped(), used.width, used.height));
  const std::vector<ShadingModel>& models = used.splitModels;
  std::vector<ScreenColumn> columns = splitColumns(used.width, uint32_t(models.size()));
  auto column = [&](size_t i, uint32_t width) {
    return cropColumns(frame, columns[i].left, width);
  };
  if (measureAgainstReference_ && reference_.state() == BackgroundTrace::State::Ready &&
      work.metricsView && work.metricsView == referenceRequested_) {
    if (referenceMeasured_) return;  // the other frame in flight measured the same
    const ImageU8& reference = reference_.image();
    splitErrors_.clear();
    std::string line = "split-screen error against the traced reference (" +
                       std::to_string(reference.width) + "x" + std::to_string(reference.height) +
                       ", " + std::to_string(options_.referenceSamplesPerPixel) + " spp):";
    for (size_t i = 0; i < models.size(); ++i) {
      ImageU8 image = column(i, reference.width);
      ImageDifference difference = compareImages(reference, image);
      double flip = flipError(reference, image).mean;
      splitErrors_.push_back({models[i], difference, flip});
      char text[128];
      std::snprintf(text, sizeof(text), " %s FLIP %.4f RMSE %.3f PSNR %.2f dB;",
                    std::string(shadingModelName(models[i])).c_str(), flip, difference.rmse,
                    difference.psnr);
      line += text;
    }
    splitErrorsAgainstReference_ = true;
    referenceMeasured_ = true;
    // Logged once per reference and settings; the overlay shows them.
    std::printf("view: %s\n", line.c_str());
    std::fflush(stdout);
    return;
  }
  auto phong = std::find(models.begin(), models.end(), ShadingModel::Phong);
  if (phong == models.end()) return;
  size_t reference = size_t(phong - models.begin());
  // Columns differ by at most one pixel in width: compare the common part,
  // the first column's width.
  uint32_t width = columns[0].width;
  ImageU8 referenceImage = column(reference, width);
  bool first = splitErrors_.empty() || splitErrorsAgainstReference_;
  splitErrors_.clear();
  splitErrorsAgainstReference_ = false;
  std::string line = "split-screen error against phong:";
  for (size_t i = 0; i < models.size(); ++i) {
    if (i == reference) continue;
    ImageDifference difference = compareImages(referenceImage, column(i, width));
    splitErrors_.push_back({models[i], difference, std::nullopt});
    char text[96];
    std::snprintf(text, sizeof(text), " %s RMSE %.3f PSNR %.2f dB;",
                  std::string(shadingModelName(models[i])).c_str(), difference.rmse,
                  difference.psnr);
    line += text;
  }
  // Logged once per split-screen session; the overlay shows every update.
  if (first) std::printf("view: %s\n", line.c_str());
}

std::optional<Viewer::ReferenceView> Viewer::referenceView() const {
  if (settings_.splitModels.empty()) return std::nullopt;
  const uint32_t count = uint32_t(settings_.splitModels.size());
  const Camera& camera = scene_.camera;
  // The renderer's projection of a column (recordScene): the frame's width
  // over the columns. The tracer's aspect is the traced width's, the same
  // when the window's width divides by the columns.
  float aspect = float(settings_.width) / float(count) / float(settings_.height);
  return ReferenceView{camera.viewMatrix(), camera.projectionMatrix(aspect),
                       splitColumns(settings_.width, count)[0].width, settings_.height,
                       renderer_.uploadCount()};
}

void Viewer::updateReference() {
  if (!measureAgainstReference_) return;
  if (reference_.collect()) {
    referenceMeasured_ = false;  // new: measure the columns against it
    char text[128];
    std::snprintf(text, sizeof(text), "reference traced in %.2f s (%ux%u, %u spp)",
                  reference_.seconds(), reference_.image().width, reference_.image().height,
                  options_.referenceSamplesPerPixel);
    say(text);
  }
  if (reference_.state() == BackgroundTrace::State::Idle && !reference_.error().empty() &&
      message_.find(reference_.error()) == std::string::npos)
    say("reference: " + reference_.error(), true);
  std::optional<ReferenceView> view = referenceView();
  bool stopped = view && view == previousView_;
  previousView_ = view;
  if (view == referenceRequested_) return;  // traced, or being traced, for this view
  // The view moved on: what is traced or being traced is stale.
  if (reference_.state() != BackgroundTrace::State::Idle) reference_.cancel();
  referenceRequested_.reset();
  referenceMeasured_ = false;
  if (!stopped) return;  // no trace per frame of a drag: wait until the camera rests
  reference_.start(scene_, view->width, view->height, options_.referenceSamplesPerPixel);
  referenceRequested_ = view;
}

void Viewer::setMeasureAgainstReference(bool on) {
  measureAgainstReference_ = on;
  referenceRequested_.reset();
  previousView_.reset();
  referenceMeasured_ = false;
  splitErrors_.clear();
  if (!on) reference_.cancel();
}

// The script's wait-reference: frames until the split columns have been
// measured against a finished trace, sleeping a little each loop so that the
// trace thread gets the cores.
void Viewer::waitForReference() {
  bool failed = reference_.state() == BackgroundTrace::State::Idle && !reference_.error().empty();
  if (!measureAgainstReference_) say("wait-reference: X is off, no reference to wait for", true);
  // Minimised, no frame is drawn, so none is measured against the
  // reference: waiting would never end (a script's minimize, then
  // wait-reference, hung).
  bool undrawn = minimized_ && measureAgainstReference_ && !referenceMeasured_;
  if (undrawn) say("wait-reference: the window is minimised, nothing is drawn to measure", true);
  if (referenceMeasured_ || !measureAgainstReference_ || failed || undrawn) {
    waitingForReference_ = false;
    return;
  }
  framesToRun_ = std::max(framesToRun_, 1u);
  std::this_thread::sleep_for(std::chrono::milliseconds(10));
}

std::string Viewer::referenceStatus() const {
  if (settings_.splitModels.empty()) return "reference: split screen is off (C)";
  char text[160];
  switch (reference_.state()) {
    case BackgroundTrace::State::Tracing:
      std::snprintf(text, sizeof(text),
                    "reference: tracing %d%% (%ux%u, %u spp, in the background)",
                    int(reference_.progress() * 100.0f + 0.5f), referenceRequested_->width,
                    referenceRequested_->height, options_.referenceSamplesPerPixel);
      return text;
    case BackgroundTrace::State::Ready:
      std::snprintf(text, sizeof(text), "reference: ready, traced in %.2f s (%ux%u, %u spp)",
                    reference_.seconds(), reference_.image().width, reference_.image().height,
                    options_.referenceSamplesPerPixel);
      return text;
    case BackgroundTrace::State::Idle:
      break;
  }
  if (!reference_.error().empty()) return "reference: failed: " + reference_.error();
  return "reference: waiting for the camera to rest";
}

}  // namespace shadelab
