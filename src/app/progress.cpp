#include "app/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace shadelab {

Progress::Progress(std::string what, double total)
    : Progress(std::move(what), total, isatty(STDERR_FILENO) == 1, stderr) {}

Progress::Progress(std::string what, double total, bool enabled, FILE* out)
    : what_(std::move(what)),
      total_(std::max(total, 0.0)),
      enabled_(enabled),
      out_(out),
      start_(std::chrono::steady_clock::now()),
      lastDraw_(start_ - std::chrono::seconds(1)) {}

Progress::~Progress() { finish(); }

std::string Progress::formatSeconds(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) return "?";
  long whole = std::lround(seconds);
  char text[32];
  if (whole < 60)
    std::snprintf(text, sizeof text, "%ld s", whole);
  else if (whole < 3600)
    std::snprintf(text, sizeof text, "%ld:%02ld", whole / 60, whole % 60);
  else
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", whole / 3600, whole / 60 % 60, whole % 60);
  return text;
}

void Progress::set(double done, const std::string& detail) {
  done_ = done;
  if (!enabled_) return;
  auto now = std::chrono::steady_clock::now();
  bool complete = total_ > 0.0 && done_ >= total_;
  if (!complete && now - lastDraw_ < std::chrono::milliseconds(100)) return;
  lastDraw_ = now;
  draw(detail);
}

void Progress::draw(const std::string& detail) {
  double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::string figures;
  char text[96];
  if (total_ > 0.0) {
    double fraction = std::clamp(done_ / total_, 0.0, 1.0);
    std::string eta = done_ > 0.0 ? formatSeconds(elapsed * (total_ - done_) / done_) : "?";
    if (total_ == std::floor(total_) && total_ > 1.0)
      std::snprintf(text, sizeof text, "%.0f/%.0f, %3.0f%%, %s, ETA %s", done_, total_,
                    100.0 * fraction, formatSeconds(elapsed).c_str(), eta.c_str());
    else
      std::snprintf(text, sizeof text, "%3.0f%%, %s, ETA %s", 100.0 * fraction,
                    formatSeconds(elapsed).c_str(), eta.c_str());
  } else {
    std::snprintf(text, sizeof text, "%.0f done, %s", done_, formatSeconds(elapsed).c_str());
  }
  figures = text;
  // \r and clear to the end of the line: a shorter line leaves no tail.
  std::fprintf(out_, "\r\033[K%s: %s%s%s", what_.c_str(), figures.c_str(),
               detail.empty() ? "" : "  ", detail.c_str());
  std::fflush(out_);
  open_ = true;
}

void Progress::finish() {
  if (!open_) return;
  draw("");
  std::fputc('\n', out_);
  std::fflush(out_);
  open_ = false;
}

}  // namespace shadelab
