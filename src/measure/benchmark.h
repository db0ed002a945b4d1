#pragma once
// The speed-against-accuracy measurement behind `shadelab bench`: one
// renderer, one scene, a list of settings, each measured over many frames in
// several interleaved rounds (A B C A B C ...) so that slow spells of a
// shared machine fall on every setting alike rather than on whichever ran at
// the time; and each setting's image measured against a reference with the
// chosen error metrics.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/metrics/error_metric.h"
#include "core/scene/scene.h"
#include "core/scene/shading.h"
#include "measure/reference.h"
#include "passes/renderer.h"

namespace shadelab {

// One setting. A new axis is a field here, a list in BenchAxes, a loop in
// benchPoints() and a column in benchCsv().
struct BenchPoint {
  ShadingModel model = ShadingModel::Phong;
  float tessellation = 1.0f;  // Scene::retessellate factor
  uint32_t msaaSamples = 1;
  std::optional<TextureFilter> filter;  // overrides every sampler; none: the materials' own
  ShadowMethod shadows = ShadowMethod::Off;
  uint32_t shadowMapSize = kDefaultShadowMapSize;  // meaningless with shadows off
  uint32_t width = 1280, height = 720;             // frame size
  uint32_t lights = 0;  // 0: the scene's own lights; else that many on a ring (withLightRing)
  // 0: every object drawn in full (--lod off); else --lod auto with this
  // error bound in pixels.
  float lodError = 0.0f;
  bool operator==(const BenchPoint&) const = default;
};

// The sweep: every combination, models varying fastest.
struct BenchAxes {
  std::vector<ShadingModel> models;
  std::vector<float> tessellations{1.0f};
  std::vector<uint32_t> msaa{1};
  std::vector<std::optional<TextureFilter>> filters{std::nullopt};
  std::vector<ShadowMethod> shadows{ShadowMethod::Off};
  std::vector<uint32_t> shadowMapSizes{kDefaultShadowMapSize};  // only with shadows on
  std::vector<glm::uvec2> sizes{{1280, 720}};
  std::vector<uint32_t> lights{0};
  std::vector<float> lodErrors{0.0f};
};
std::vector<BenchPoint> benchPoints(const BenchAxes& axes);
// "phong t2 4x", "phong t2 4x nearest", "phong t1 1x hard 2048"
std::string benchPointName(const BenchPoint& point);
// "off", or the method and map size: "hard 2048".
std::string benchShadowName(const BenchPoint& point);
// "material" for no override, else the filter's name.
std::string benchFilterName(const std::optional<TextureFilter>& filter);

// `scene` with its lights replaced by `count` white point lights of
// intensity 1 / count, evenly spaced on a ring above the scene's bounds (the
// lights axis: how the cost grows with the lights, not a way to light it).
Scene withLightRing(const Scene& scene, uint32_t count);

struct BenchOptions {
  uint32_t frames = 120;  // per round and point; the first tenth is warm-up
  uint32_t rounds = 3;
  // The error of each point's image against the reference (traced once per
  // frame size and light count), per metric; no reference (empty render):
  // no errors measured.
  Reference reference;
  std::vector<ErrorMetric> metrics;
};

struct BenchResult {
  BenchPoint point;
  uint64_t triangles = 0;
  uint32_t lights = 0;                             // in the frame's scene
  size_t frames = 0;                               // steady frames measured, over all rounds
  double deviceMedianMs = 0.0, deviceP95Ms = 0.0;  // GPU timestamps around each frame
  double wallMedianMs = 0.0, wallP95Ms = 0.0;      // between successive frame completions
  // Memory while this point ran: the device memory shadelab had allocated
  // (RenderStats::deviceMemoryBytes), and the process's peak resident set
  // (VmHWM, reset before each run where Linux allows), which on lavapipe also
  // holds the driver's vertex and tile buffers. The largest over all rounds.
  uint64_t deviceMemoryBytes = 0;
  uint64_t peakResidentBytes = 0;
  std::vector<double> errors;  // per BenchOptions::metrics, against the reference
  uint32_t coarserDraws = 0;   // --lod auto: draws at a simplified level, per frame
  // With --lod auto, when the sweep has the same setting at --lod off: the
  // mean FLIP of this image against that one (what the levels cost in
  // accuracy); -1 otherwise.
  double flipAgainstFull = -1.0;
};

// `progress` receives one line per measured run. Throws InputError for
// impossible settings (as renderToImage does).
std::vector<BenchResult> runBenchmark(Renderer& renderer, const Scene& scene,
                                      const std::vector<BenchPoint>& points,
                                      const BenchOptions& options,
                                      const std::function<void(const std::string&)>& progress);

// One header line and one line per result.
std::string benchCsv(const std::vector<BenchResult>& results, const BenchOptions& options,
                     const std::string& sceneName);

// A results.csv read back: the columns by name, each row's values as text.
struct BenchTable {
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
  // Index of a column; throws InputError naming `source` when it is missing.
  size_t column(const std::string& name, const std::string& source) const;
};
// Throws InputError naming `source` for a malformed table.
BenchTable parseBenchCsv(const std::string& text, const std::string& source);

}  // namespace shadelab
