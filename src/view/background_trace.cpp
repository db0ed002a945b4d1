#include "view/background_trace.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <utility>

#include "core/trace/raytracer.h"

namespace shadelab {

BackgroundTrace::~BackgroundTrace() {
  cancel();
}

void BackgroundTrace::join() {
  if (!worker_.joinable()) return;
  cancel_ = true;
  worker_.join();
  cancel_ = false;
}

void BackgroundTrace::cancel() {
  join();
  std::lock_guard lock(mutex_);
  finished_.reset();
  failed_.reset();
  state_ = State::Idle;
  progress_ = 0.0f;
}

void BackgroundTrace::start(Scene scene, uint32_t width, uint32_t height,
                            uint32_t samplesPerPixel) {
  cancel();
  state_ = State::Tracing;
  error_.clear();
  // One core is the viewer's (and lavapipe's): the trace takes the others, at least one.
  uint32_t threads = std::max(2u, std::thread::hardware_concurrency()) - 1;  // 0: unknown
  worker_ = std::thread([this, scene = std::move(scene), width, height, samplesPerPixel, threads] {
    const auto started = std::chrono::steady_clock::now();
    try {
      TraceSettings settings;
      settings.width = width;
      settings.height = height;
      settings.samplesPerPixel = samplesPerPixel;
      settings.threads = threads;
      settings.cancel = &cancel_;
      settings.progress = [this](float fraction) { progress_ = fraction; };
      RayTracer tracer(scene);
      if (cancel_) return;
      TraceResult traced = tracer.render(settings);
      if (cancel_) return;  // a partial image is no reference
      ImageU8 image = encodeSrgb8(traced.image);
      std::lock_guard lock(mutex_);
      finished_ = std::move(image);
      finishedSeconds_ =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    } catch (const std::exception& error) {
      std::lock_guard lock(mutex_);
      failed_ = error.what();
    }
  });
}

bool BackgroundTrace::collect() {
  if (state_ != State::Tracing) return false;
  std::lock_guard lock(mutex_);
  if (failed_) {
    error_ = *std::exchange(failed_, std::nullopt);
    state_ = State::Idle;
    return false;
  }
  if (!finished_) return false;
  image_ = std::move(*finished_);
  finished_.reset();
  seconds_ = finishedSeconds_;
  state_ = State::Ready;
  return true;
}

}  // namespace shadelab
