// Study `acne`: the tracer's epsilon (how far new rays start off the
// surface) against the two ways it fails. Too small, shadow rays hit the
// surface they leave and lit points come out shadowed (acne); too large, they
// start past a nearby occluder and shadowed points come out lit (leaks).
#include <cstdio>

#include "core/base/files.h"
#include "core/metrics/chart.h"
#include "measure/acne.h"
#include "measure/study.h"

namespace shadelab {

StudyResult runAcneStudy(const StudyOptions& options, const StudyServices& services) {
  const Scene scene = acneScene();
  const float epsilons[] = {0.0f, 1e-7f, 1e-6f, 1e-5f, 1e-4f, 1e-3f, 1e-2f, 1e-1f, 0.5f};
  std::vector<AcneMeasurement> results;
  StudyResult result;
  std::string csv =
      "epsilon,width,height,lit_pixels,acne_pixels,acne_fraction,shadowed_pixels,"
      "leaking_pixels,leak_fraction\n";
  result.report = "epsilon   lit px shadowed wrongly (acne)   shadow px lit wrongly (leak)\n";
  for (float epsilon : epsilons) {
    results.push_back(measureAcne(scene, epsilon, options.width, options.height));
    const AcneMeasurement& m = results.back();
    char line[200];
    std::snprintf(line, sizeof line, "%-8g %10llu %8.2f%% of %-8llu %10llu %6.2f%% of %llu",
                  epsilon, (unsigned long long)m.acnePixels, 100.0 * m.acneFraction(),
                  (unsigned long long)m.litPixels, (unsigned long long)m.leakingPixels,
                  100.0 * m.leakFraction(), (unsigned long long)m.shadowedPixels);
    services.progress(line);
    result.report += std::string(line) + "\n";
    std::snprintf(line, sizeof line, "%g,%u,%u,%llu,%llu,%.6f,%llu,%llu,%.6f\n", epsilon,
                  options.width, options.height, (unsigned long long)m.litPixels,
                  (unsigned long long)m.acnePixels, m.acneFraction(),
                  (unsigned long long)m.shadowedPixels, (unsigned long long)m.leakingPixels,
                  m.leakFraction());
    csv += line;
  }
  Chart chart;
  chart.title = "Shadow rays against the tracer's epsilon";
  char subtitle[160];
  std::snprintf(subtitle, sizeof subtitle,
                "acne: lit points drawn shadowed; leak: shadowed points drawn lit; epsilon 0 "
                "(off the log axis): %.1f%% acne",
                100.0 * results.front().acneFraction());
  chart.subtitle = subtitle;
  chart.x = {"epsilon (world units, log)", AxisScale::Log};
  chart.y = {"wrong pixels (%)", AxisScale::Linear, 0.0, 100.0};
  ChartSeries acne{"acne", chartColor(0), {}, true, Marker::Dot};
  ChartSeries leak{"leak", chartColor(1), {}, true, Marker::Dot};
  for (const AcneMeasurement& m : results) {
    if (m.epsilon <= 0.0f) continue;
    acne.points.push_back({m.epsilon, 100.0 * m.acneFraction(), ""});
    leak.points.push_back({m.epsilon, 100.0 * m.leakFraction(), ""});
  }
  chart.series = {acne, leak};
  writeTextFile(options.output / "acne.csv", csv);
  writeImage(drawChart(chart, 720, 400), options.output / "acne.png");
  result.files = {"acne.csv", "acne.png"};
  for (const AcneMeasurement& m : results) {
    char name[64];
    std::snprintf(name, sizeof name, "trace_epsilon_%g.png", m.epsilon);
    if (m.epsilon == 0.0f || m.epsilon == 1e-4f || m.epsilon == 0.5f) {
      writeImage(m.image, options.output / name);
      result.files.push_back(name);
    }
  }
  return result;
}

}  // namespace shadelab
