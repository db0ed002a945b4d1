#pragma once
// The split screen's reference: the CPU Whitted ray tracer (core/trace) run
// on a thread of its own over a copy of the scene and camera, so the viewer
// keeps drawing while it works. One trace at a time; starting another
// cancels the running one (the tracer stops at its next row). The viewer
// polls it once per frame; nothing here blocks except start() and the
// destructor, which wait for a cancelled trace to leave its current row.
#include <atomic>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "core/base/image.h"
#include "core/scene/scene.h"

namespace shadelab {

class BackgroundTrace {
 public:
  enum class State { Idle, Tracing, Ready };

  BackgroundTrace() = default;
  ~BackgroundTrace();
  BackgroundTrace(const BackgroundTrace&) = delete;
  BackgroundTrace& operator=(const BackgroundTrace&) = delete;

  // Traces `scene` (its camera, aspect width / height) at width x height
  // with `samplesPerPixel` (a square) and shadow rays, as `compare`'s
  // default reference does. Cancels a trace still running.
  void start(Scene scene, uint32_t width, uint32_t height, uint32_t samplesPerPixel);
  void cancel();  // back to Idle
  // Takes a finished trace's image (sRGB, as the split columns are
  // measured): true once per finished trace. A trace that threw (an
  // impossible size) goes back to Idle with error() set.
  bool collect();
  const std::string& error() const { return error_; }

  State state() const { return state_; }
  float progress() const { return progress_.load(); }  // 0..1, in hundredths while tracing
  const ImageU8& image() const { return image_; }      // valid when Ready
  double seconds() const { return seconds_; }          // how long the last trace took

 private:
  void join();

  std::thread worker_;
  std::atomic<bool> cancel_{false};
  std::atomic<float> progress_{0.0f};
  std::mutex mutex_;                 // guards the three below
  std::optional<ImageU8> finished_;  // handed over by the worker
  double finishedSeconds_ = 0.0;
  std::optional<std::string> failed_;
  std::string error_;
  State state_ = State::Idle;
  ImageU8 image_;
  double seconds_ = 0.0;
};

}  // namespace shadelab
