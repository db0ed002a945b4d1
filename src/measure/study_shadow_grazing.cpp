// Study `shadow-grazing`: the sun of the `shadows` scene lowered towards
// the horizon. At a grazing angle a map texel stretches over a long strip
// of the floor, so the floor's own depth varies across one texel by far
// more than at a steep angle: without the slope-scaled and normal-offset
// terms that is acne; with them, the bias that grows with tan(theta) may
// detach shadows from their casters (peter-panning). Measured with the
// default bias and map size against the tracer's exact shadow rays.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/base/files.h"
#include "core/metrics/chart.h"
#include "measure/shadow_study.h"
#include "measure/study.h"

namespace shadelab {

StudyResult runShadowGrazingStudy(const StudyOptions& options, const StudyServices& services) {
  Scene scene = builtinScene("shadows");
  uint32_t sun = 0;
  while (sun < scene.lights.size() && scene.lights[sun].type != LightType::Directional) ++sun;
  const float elevations[] = {3.0f, 5.0f, 10.0f, 20.0f, 40.0f, 70.0f};  // degrees above the floor
  const ShadowMethod methods[] = {ShadowMethod::Hard, ShadowMethod::Pcf3};
  const ShadowBias none{0.0f, 0.0f, 0.0f};
  const ShadowBias standard;
  glm::vec3 across = scene.lights[sun].direction;
  across.y = 0.0f;
  across = glm::normalize(across);

  StudyResult result;
  std::ostringstream csv;
  csv << "elevation_degrees,method,bias,lit_pixels,acne_percent,contact_pixels,"
         "peter_panning_percent\n";
  result.report = "elevation  method  bias      acne %   peter-panning %\n";
  Chart acneChart, panningChart;
  acneChart.title = "Acne as the sun sinks";
  acneChart.subtitle = "% of truly lit pixels drawn shadowed (default map size)";
  panningChart.title = "Peter-panning as the sun sinks";
  panningChart.subtitle = "% of truly shadowed pixels near contact drawn lit";
  for (Chart* chart : {&acneChart, &panningChart}) {
    chart->x = {"sun elevation (degrees above the floor)", AxisScale::Linear};
    chart->y = {"percent", AxisScale::Linear};
  }
  size_t series = 0;
  for (ShadowMethod method : methods)
    for (bool biased : {false, true}) {
      std::string name = std::string(nameOf(kShadowMethodNames, method)) +
                         (biased ? ", default bias" : ", no bias");
      ChartSeries acne{name, chartColor(series), {}, true, Marker::Dot};
      ChartSeries panning{name, chartColor(series), {}, true, Marker::Dot};
      ++series;
      for (float elevation : elevations) {
        float e = glm::radians(elevation);
        scene.lights[sun].direction = across * std::cos(e) + glm::vec3(0.0f, -std::sin(e), 0.0f);
        ShadowTruth truth = traceShadowTruth(scene, sun, options.width, options.height);
        ShadowErrors errors = measureShadowErrors(services.renderer(), scene, sun, truth, method,
                                                  biased ? standard : none, kDefaultShadowMapSize);
        char line[160];
        std::snprintf(line, sizeof line, "%9g  %-6s  %-7s %8.3f %17.3f", elevation,
                      std::string(nameOf(kShadowMethodNames, method)).c_str(),
                      biased ? "default" : "none", 100.0 * errors.acneFraction(),
                      100.0 * errors.peterPanningFraction());
        services.progress(line);
        result.report += std::string(line) + "\n";
        csv << elevation << ',' << nameOf(kShadowMethodNames, method) << ','
            << (biased ? "default" : "none") << ',' << errors.lit << ','
            << 100.0 * errors.acneFraction() << ',' << errors.contact << ','
            << 100.0 * errors.peterPanningFraction() << '\n';
        acne.points.push_back({elevation, 100.0 * errors.acneFraction(), ""});
        panning.points.push_back({elevation, 100.0 * errors.peterPanningFraction(), ""});
      }
      acneChart.series.push_back(acne);
      panningChart.series.push_back(panning);
    }
  writeTextFile(options.output / "shadow_grazing.csv", csv.str());
  writeImage(drawChartRow({acneChart, panningChart}, 520, 360),
             options.output / "shadow_grazing.png");
  result.files = {"shadow_grazing.csv", "shadow_grazing.png"};
  return result;
}

}  // namespace shadelab
