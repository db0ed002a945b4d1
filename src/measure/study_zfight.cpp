// Study `zfight`: the seed's claim that z-fighting "is more serious for
// polygons further away in a perspective projection; unaffected by distance
// in orthographic", measured two ways on the zfight scene's planes 0.05
// apart: against the near plane at a fixed distance, and against the planes'
// distance at a fixed near plane (1, as the classic D16 setting).
#include <cstdio>

#include "core/base/files.h"
#include "measure/study.h"
#include "measure/zfight.h"

namespace shadelab {
namespace {

constexpr float kNearPlanes[] = {0.001f, 0.01f, 0.1f, 1.0f, 10.0f};
constexpr float kDistanceNear = 1.0f;
constexpr float kDistanceScales[] = {0.25f, 0.5f, 1.0f, 2.0f, 4.0f};

// One row per projection and swept value, one column per depth mode (% wrong).
std::string table(const std::vector<ZFightMeasurement>& results, ZFightAxis axis) {
  std::string text;
  char cell[64];
  std::snprintf(cell, sizeof cell, "%-13s %9s", "projection",
                axis == ZFightAxis::Near ? "near" : "distance");
  text += cell;
  for (DepthMode depth : valuesOf(kDepthModeNames)) {
    std::snprintf(cell, sizeof cell, " %9s", std::string(depthModeName(depth)).c_str());
    text += cell;
  }
  text += '\n';
  for (const ZFightMeasurement& row : results) {
    if (row.depth != DepthMode::D16) continue;  // one line per (projection, value)
    double value = axis == ZFightAxis::Near ? row.near : zfightDistance(row.distanceScale);
    std::snprintf(cell, sizeof cell, axis == ZFightAxis::Near ? "%-13s %9g" : "%-13s %9.1f",
                  nameOf(kProjectionNames, row.projection).data(), value);
    text += cell;
    for (DepthMode depth : valuesOf(kDepthModeNames))
      for (const ZFightMeasurement& m : results)
        if (m.projection == row.projection && m.depth == depth && m.near == row.near &&
            m.distanceScale == row.distanceScale) {
          std::snprintf(cell, sizeof cell, " %9.2f", 100.0 * m.wrongFraction());
          text += cell;
        }
    text += '\n';
  }
  return text;
}

}  // namespace

StudyResult runZFightStudy(const StudyOptions& options, const StudyServices& services) {
  Renderer& renderer = services.renderer();
  std::vector<ZFightSetting> nearSweep, distanceSweep;
  for (float near : kNearPlanes) nearSweep.push_back({near, 1.0f});
  for (float scale : kDistanceScales) distanceSweep.push_back({kDistanceNear, scale});
  services.progress("near-plane sweep, then distance sweep at near 1");
  std::vector<ZFightMeasurement> nearResults =
      runZFightSweep(renderer, nearSweep, options.width, options.height, services.progress);
  std::vector<ZFightMeasurement> distanceResults =
      runZFightSweep(renderer, distanceSweep, options.width, options.height, services.progress);

  StudyResult result;
  auto write = [&](const std::string& name, const auto& content) {
    if constexpr (std::is_same_v<std::decay_t<decltype(content)>, std::string>)
      writeTextFile(options.output / name, content);
    else
      writeImage(content, options.output / name);
    result.files.push_back(name);
  };
  write("zfight_near.csv", zfightCsv(nearResults, options.width, options.height));
  write("zfight_near.png", zfightChart(nearResults, ZFightAxis::Near));
  write("zfight_distance.csv", zfightCsv(distanceResults, options.width, options.height));
  write("zfight_distance.png", zfightChart(distanceResults, ZFightAxis::Distance));
  // What D16 at near 1 looks like nearest and farthest (farther plane drawn first).
  RenderSettings settings{options.width, options.height, ShadingModel::Unlit};
  settings.depth = DepthMode::D16;
  settings.frontToBack = false;  // sorted, the nearer plane would be drawn first and win every tie
  for (Projection projection : {Projection::Perspective, Projection::Orthographic})
    for (float scale : {kDistanceScales[0], kDistanceScales[std::size(kDistanceScales) - 1]}) {
      char name[96];
      std::snprintf(name, sizeof name, "d16_%s_distance%.0f.png",
                    nameOf(kProjectionNames, projection).data(), zfightDistance(scale));
      write(
          name,
          renderer.renderToImage(zfightSceneAt(projection, kDistanceNear, scale), settings).image);
    }
  char heading[160];
  std::snprintf(heading, sizeof heading,
                "pixels where the farther plane wins (%%), planes %g apart\n", kZFightGap);
  char distanceHeading[96];
  std::snprintf(distanceHeading, sizeof distanceHeading,
                "at near %g, by distance from the eye to the planes' centre:\n", kDistanceNear);
  result.report = heading + table(nearResults, ZFightAxis::Near) + distanceHeading +
                  table(distanceResults, ZFightAxis::Distance);
  return result;
}

}  // namespace shadelab
