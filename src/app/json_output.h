#pragma once
// --json on render, trace, compare, bench and study: one JSON object per run
// on stdout, for scripts. The human lines are unchanged but go to stderr, so
// stdout holds the object alone and `| jq` or json.loads reads it whole. The
// fields come from what the lower layers already return (RenderStats,
// TraceStats, BenchResult, StudyResult); README "Machine-readable output"
// describes the schema.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "measure/benchmark.h"
#include "passes/renderer.h"

namespace shadelab {

// Bumped when a field changes meaning or is removed (adding one is not a change).
inline constexpr int kJsonSchemaVersion = 1;

class JsonOutput {
 public:
  void add(CLI::App* command);  // registers --json
  bool enabled() const { return enabled_; }
  // Where the human lines go: stdout, or stderr with --json.
  FILE* human() const { return enabled_ ? stderr : stdout; }
  // With --json, prints {"schema_version", "command", ...fields} as one line on stdout.
  void emit(const std::string& command, const nlohmann::json& fields) const;

 private:
  bool enabled_ = false;
};

// An output file as an absolute path, so a script may run elsewhere.
std::string jsonPath(const std::filesystem::path& path);

// Frame time statistics over the frames after warm-up (warmupFrames()): the
// first frame apart, then medians and 95th percentiles.
struct FrameTimings {
  double firstWallMs = 0.0, firstDeviceMs = 0.0;
  size_t warmup = 0, steadyFrames = 0;
  double deviceMedianMs = 0.0, deviceP95Ms = 0.0;
  double wallMedianMs = 0.0, wallMeanMs = 0.0, wallP95Ms = 0.0;
  double shadowMedianMs = 0.0;  // the shadow pass's share of the device time
};
FrameTimings frameTimings(const RenderStats& stats);

nlohmann::json toJson(const FrameTimings& timings);
// The settings a frame was drawn with: size, model(s), MSAA, depth, look, shadows.
nlohmann::json toJson(const FrameSettings& settings);
nlohmann::json toJson(const BenchPoint& point);
// One measured setting; `metrics` names BenchResult::errors in order.
nlohmann::json toJson(const BenchResult& result, const std::vector<ErrorMetric>& metrics);

}  // namespace shadelab
