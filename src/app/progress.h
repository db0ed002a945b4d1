#pragma once
// Progress of a long command on stderr: how far, how long so far and how
// long still to go (from the rate so far), redrawn in place on one line. Only
// when stderr is a terminal: logs, pipes and tests get the command's summary
// alone. Time is read here only; nothing it prints reaches an output file.
#include <chrono>
#include <cstdio>
#include <string>

namespace shadelab {

class Progress {
 public:
  // `total` units of work (0: unknown, no ETA). `enabled` defaults to
  // whether stderr is a terminal.
  Progress(std::string what, double total);
  Progress(std::string what, double total, bool enabled, FILE* out);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // `done` units finished; `detail` is shown after the figures. Redrawn at
  // most ten times a second, and always when the work is complete.
  void set(double done, const std::string& detail = {});
  // Counts one more unit.
  void step(const std::string& detail = {}) { set(done_ + 1.0, detail); }
  // Shows `detail` without counting.
  void note(const std::string& detail) { set(done_, detail); }
  // Ends the line (also on destruction), leaving the last figures.
  void finish();

  // "1:05", "12 s": a duration for people.
  static std::string formatSeconds(double seconds);

 private:
  void draw(const std::string& detail);

  std::string what_;
  double total_ = 0.0, done_ = 0.0;
  bool enabled_ = false, open_ = false;
  FILE* out_ = nullptr;
  std::chrono::steady_clock::time_point start_, lastDraw_;
};

}  // namespace shadelab
