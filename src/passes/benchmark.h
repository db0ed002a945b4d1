#pragma once
// The speed measurement behind `shadelab bench`: one renderer, one scene, a
// list of settings, each measured over many frames in several interleaved
// rounds (A B C A B C ...) so that slow spells of a shared machine fall on
// every setting alike rather than on whichever ran at the time.
#include <functional>
#include <string>
#include <vector>

#include "core/scene.h"
#include "core/shading.h"
#include "passes/renderer.h"

namespace shadelab {

struct BenchPoint {
  ShadingModel model = ShadingModel::Phong;
  float tessellation = 1.0f;  // Scene::retessellate factor
  uint32_t msaaSamples = 1;
};

struct BenchOptions {
  uint32_t width = 1280;
  uint32_t height = 720;
  uint32_t frames = 120;  // per round and point; the first tenth is warm-up
  uint32_t rounds = 3;
};

struct BenchResult {
  BenchPoint point;
  uint64_t triangles = 0;
  size_t frames = 0;  // steady frames measured, over all rounds
  double deviceMedianMs = 0.0, deviceP95Ms = 0.0;  // GPU timestamps around each frame
  double wallMedianMs = 0.0, wallP95Ms = 0.0;      // between successive frame completions
};

// `progress` receives one line per measured run. Throws InputError for
// impossible settings (as renderToImage does).
std::vector<BenchResult> runBenchmark(Renderer& renderer, const Scene& scene,
                                      const std::vector<BenchPoint>& points,
                                      const BenchOptions& options,
                                      const std::function<void(const std::string&)>& progress);

// One header line and one line per result; columns documented in the header.
std::string benchCsv(const std::vector<BenchResult>& results, const BenchOptions& options,
                     const std::string& sceneName);

}  // namespace shadelab
