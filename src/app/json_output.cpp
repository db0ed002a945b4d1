#include "app/json_output.h"

#include <cmath>

#include "core/base/stats.h"
#include "core/scene/texture.h"
#include "core/vulkan/depth.h"

namespace shadelab {

void JsonOutput::add(CLI::App* command) {
  command->add_flag("--json", enabled_,
                    "Print one JSON object with settings, timings, triangles, metrics and output "
                    "paths on stdout; the human lines go to stderr");
}

void JsonOutput::emit(const std::string& command, const nlohmann::json& fields) const {
  if (!enabled_) return;
  nlohmann::json object = {{"schema_version", kJsonSchemaVersion}, {"command", command}};
  object.update(fields);
  // Every human line went to stderr before this: flush it so a terminal shows it first.
  std::fflush(stderr);
  std::printf("%s\n", object.dump().c_str());
  std::fflush(stdout);
}

std::string jsonPath(const std::filesystem::path& path) {
  std::error_code error;
  std::filesystem::path absolute = std::filesystem::absolute(path, error);
  return (error ? path : absolute.lexically_normal()).string();
}

FrameTimings frameTimings(const RenderStats& stats) {
  FrameTimings timings;
  if (stats.wallMs.empty()) return timings;
  timings.firstWallMs = stats.wallMs.front();
  timings.firstDeviceMs = stats.deviceMs.front();
  // The first frames include lavapipe's lazy pipeline compile: the steady
  // statistics are over the rest.
  timings.warmup = warmupFrames(stats.deviceMs.size());
  std::vector<double> device(stats.deviceMs.begin() + long(timings.warmup), stats.deviceMs.end());
  std::vector<double> wall(stats.wallMs.begin() + long(timings.warmup), stats.wallMs.end());
  std::vector<double> shadow(stats.shadowMs.begin() + long(timings.warmup), stats.shadowMs.end());
  timings.steadyFrames = device.size();
  timings.deviceMedianMs = median(device);
  timings.deviceP95Ms = percentile(device, 95.0);
  timings.wallMedianMs = median(wall);
  timings.wallMeanMs = mean(wall);
  timings.wallP95Ms = percentile(wall, 95.0);
  timings.shadowMedianMs = median(shadow);
  return timings;
}

nlohmann::json toJson(const FrameTimings& timings) {
  return {{"first_frame_wall_ms", timings.firstWallMs},
          {"first_frame_device_ms", timings.firstDeviceMs},
          {"warmup_frames", timings.warmup},
          {"steady_frames", timings.steadyFrames},
          {"device_median_ms", timings.deviceMedianMs},
          {"device_p95_ms", timings.deviceP95Ms},
          {"wall_median_ms", timings.wallMedianMs},
          {"wall_mean_ms", timings.wallMeanMs},
          {"wall_p95_ms", timings.wallP95Ms},
          {"shadow_median_ms", timings.shadowMedianMs}};
}

nlohmann::json toJson(const FrameSettings& settings) {
  nlohmann::json json = {
      {"width", settings.width},
      {"height", settings.height},
      {"msaa", settings.msaaSamples},
      {"depth", std::string(depthModeName(settings.depth))},
      {"environment", settings.environment},
      {"filter", settings.textures.filterOverride
                     ? nlohmann::json(textureFilterName(*settings.textures.filterOverride))
                     : nlohmann::json("material")},
      {"bump", settings.textures.bump},
      {"shadows", std::string(nameOf(kShadowMethodNames, settings.shadows))},
      {"shadow_map_size", settings.shadowMapSize},
      {"shadow_cache", settings.keepShadowMaps},
      {"lod", settings.lod ? nlohmann::json(settings.lodErrorPixels) : nlohmann::json("off")},
      {"impostor_cells", settings.impostorCells},
      {"billboard_outline", settings.trimBillboards ? "trimmed" : "quad"},
      {"draw_order", settings.frontToBack ? "sorted" : "scene"},
      {"shadow_bias",
       {{"constant", settings.shadowBias.constant},
        {"slope", settings.shadowBias.slope},
        {"normal_offset", settings.shadowBias.normalOffset}}}};
  if (settings.splitModels.empty()) {
    json["mode"] = std::string(shadingModelName(settings.shadingModel));
  } else {
    json["modes"] = nlohmann::json::array();
    for (ShadingModel model : settings.splitModels)
      json["modes"].push_back(std::string(shadingModelName(model)));
  }
  return json;
}

nlohmann::json toJson(const BenchPoint& point) {
  return {{"mode", std::string(shadingModelName(point.model))},
          {"tess", point.tessellation},
          {"msaa", point.msaaSamples},
          {"filter", benchFilterName(point.filter)},
          {"shadows", std::string(nameOf(kShadowMethodNames, point.shadows))},
          {"shadow_map_size", point.shadows == ShadowMethod::Off ? 0u : point.shadowMapSize},
          {"width", point.width},
          {"height", point.height},
          {"lights", point.lights},
          {"lod_error_px", point.lodError}};
}

nlohmann::json toJson(const BenchResult& result, const std::vector<ErrorMetric>& metrics) {
  nlohmann::json errors = nlohmann::json::object();
  for (size_t i = 0; i < metrics.size() && i < result.errors.size(); ++i)
    errors[metrics[i].name] = result.errors[i];
  return {{"setting", toJson(result.point)},
          {"triangles", result.triangles},
          {"lights", result.lights},
          {"steady_frames", result.frames},
          {"device_median_ms", result.deviceMedianMs},
          {"device_p95_ms", result.deviceP95Ms},
          {"wall_median_ms", result.wallMedianMs},
          {"wall_p95_ms", result.wallP95Ms},
          {"device_memory_bytes", result.deviceMemoryBytes},
          {"peak_resident_bytes", result.peakResidentBytes},
          {"metrics", errors},
          {"coarser_draws", result.coarserDraws},
          {"flip_vs_lod_off", result.flipAgainstFull >= 0.0 ? nlohmann::json(result.flipAgainstFull)
                                                            : nlohmann::json(nullptr)}};
}

}  // namespace shadelab
