// Study `shadow-near`: a small tilted card hung ever closer under a point
// light until it crosses the near plane of the light's cube faces
// (kPointShadowNear). A depth pass clips what lies before its near plane:
// that part of the caster vanishes from the map and its shadow leaks light
// onto the floor. The shadow pass flattens such casters onto the plane
// instead (depth clamp, "pancaking"); the study measures the truly shadowed
// floor drawn lit with the clamp and without it, against the tracer's exact
// shadow rays, and keeps the two renders of one crossing distance.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/base/files.h"
#include "core/metrics/chart.h"
#include "core/metrics/sheet.h"
#include "core/scene/scene_json.h"
#include "measure/shadow_study.h"
#include "measure/study.h"

namespace shadelab {
namespace {

constexpr float kLightHeight = 2.5f;
constexpr float kCardSize = 0.06f;      // side of the square card
constexpr float kCardTiltDegrees = 40;  // about x: its far edge reaches up towards the light

// The card's centre `distance` below the light.
Scene nearPlaneScene(float distance) {
  char text[1400];
  std::snprintf(text, sizeof text, R"({
  "camera": {"eye": [0, 4.5, 5.5], "at": [0, 0.2, 0], "fovy": 45},
  "ambient": 0.2,
  "lights": [{"type": "point", "position": [0, %g, 0], "intensity": 1}],
  "objects": [
    {"name": "floor", "shape": "plane", "size": 8, "material": {"kd": 0.7, "ks": 0}},
    {"name": "card", "shape": "plane", "size": %g,
     "transform": [{"translate": [0, %g, 0]}, {"rotate": {"axis": "x", "degrees": %g}}],
     "material": {"kd": [0.8, 0.3, 0.2], "ks": 0}}
  ]})",
                double(kLightHeight), double(kCardSize), double(kLightHeight - distance),
                double(kCardTiltDegrees));
  return parseSceneJson(text, "study shadow-near");
}

}  // namespace

StudyResult runShadowNearStudy(const StudyOptions& options, const StudyServices& services) {
  // Card centre below the light; its nearest edge is kCardSize / 2 *
  // sin(tilt) closer, so from 0.069 down part of the card is before the
  // near plane (0.05) and from 0.03 nearly all of it.
  const float distances[] = {0.3f, 0.15f, 0.1f, 0.08f, 0.065f, 0.05f, 0.04f, 0.03f};
  const float shown = 0.04f;  // the distance whose renders are kept
  float reach = 0.5f * kCardSize * std::sin(glm::radians(kCardTiltDegrees));

  StudyResult result;
  std::ostringstream csv;
  csv << "card_distance,nearest_edge_distance,near_plane,depth_clamp,shadowed_pixels,"
         "leaked_pixels,leak_percent\n";
  result.report = "card distance  nearest edge  depth clamp  shadowed px  leaked %\n";
  Chart chart;
  chart.title = "A caster crossing the light's near plane";
  chart.subtitle = "% of truly shadowed pixels drawn lit (point light, hard, default bias)";
  chart.x = {"distance of the card's centre below the light", AxisScale::Log};
  chart.y = {"percent", AxisScale::Linear};
  std::vector<SheetCell> cells;
  for (bool clamp : {true, false}) {
    ChartSeries series{clamp ? "depth clamp" : "clipped",
                       chartColor(clamp ? 0 : 1), {}, true, Marker::Dot};
    for (float distance : distances) {
      Scene scene = nearPlaneScene(distance);
      ShadowTruth truth = traceShadowTruth(scene, 0, options.width, options.height);
      ShadowErrors errors =
          measureShadowErrors(services.renderer(), scene, 0, truth, ShadowMethod::Hard,
                              ShadowBias{}, kDefaultShadowMapSize, clamp);
      char line[160];
      std::snprintf(line, sizeof line, "%13g  %12.4f  %-11s  %11llu  %8.3f", distance,
                    distance - reach, clamp ? "on" : "off",
                    static_cast<unsigned long long>(errors.shadowed),
                    100.0 * errors.leakFraction());
      services.progress(line);
      result.report += std::string(line) + "\n";
      csv << distance << ',' << distance - reach << ',' << kPointShadowNear << ','
          << (clamp ? "on" : "off") << ',' << errors.shadowed << ',' << errors.leaked << ','
          << 100.0 * errors.leakFraction() << '\n';
      series.points.push_back({distance, 100.0 * errors.leakFraction(), ""});
      if (distance == shown) {
        RenderSettings settings{options.width, options.height, ShadingModel::Phong};
        settings.environment = false;
        settings.shadows = ShadowMethod::Hard;
        settings.shadowDepthClamp = clamp;
        char lines[2][96];
        std::snprintf(lines[0], sizeof lines[0], "card %g below the light", distance);
        std::snprintf(lines[1], sizeof lines[1], "shadowed drawn lit: %.1f%%",
                      100.0 * errors.leakFraction());
        cells.push_back({encodeSrgb8(services.renderer().renderToImage(scene, settings).image),
                         clamp ? "depth clamp" : "clipped", {lines[0], lines[1]}});
      }
    }
    chart.series.push_back(series);
  }
  writeTextFile(options.output / "shadow_near.csv", csv.str());
  writeImage(drawChartRow({chart}, 560, 360), options.output / "shadow_near.png");
  writeImage(composeSheet({cells}), options.output / "shadow_near_renders.png");
  result.files = {"shadow_near.csv", "shadow_near.png", "shadow_near_renders.png"};
  return result;
}

}  // namespace shadelab
