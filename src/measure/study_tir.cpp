// Study `tir`: total internal reflection in the tracer against the formulas.
// A ray inside glass meets the surface at each angle, for several indices of
// refraction: the light refracted out and reflected back (their sum is the
// energy kept), and the critical angle where refraction stops, against
// asin(1 / ior); Schlick's reflectance (the tracer's) and the exact Fresnel
// one beside it.
#include <cmath>
#include <cstdio>

#include "core/base/files.h"
#include "core/metrics/chart.h"
#include "measure/study.h"
#include "measure/tir.h"

namespace shadelab {

StudyResult runTirStudy(const StudyOptions& options, const StudyServices& services) {
  const float iors[] = {1.2f, 1.33f, 1.5f, 2.0f, 2.42f};
  StudyResult result;
  std::string csv =
      "ior,angle_deg,transmitted,reflected,energy,total_internal_reflection,"
      "schlick_transmitted,exact_transmitted\n";
  result.report =
      "ior    critical angle traced  asin(1/ior)   difference   max |energy - 1|   "
      "max |T - T_schlick|   max |T - T_exact|\n";
  Chart chart;
  chart.title = "Light refracted out of glass against the angle inside";
  chart.subtitle = "dots: traced; lines: exact Fresnel (the tracer uses Schlick's approximation)";
  chart.x = {"angle from the normal inside the glass (degrees)", AxisScale::Linear, 0.0, 90.0};
  chart.y = {"transmitted share", AxisScale::Linear, 0.0, 1.0};
  for (size_t i = 0; i < std::size(iors); ++i) {
    const float ior = iors[i];
    double energyError = 0.0, schlickError = 0.0, exactError = 0.0;
    char name[32];
    std::snprintf(name, sizeof name, "ior %g", ior);
    ChartSeries traced{name, chartColor(i), {}, false, Marker::Dot, 2.5};
    ChartSeries exact{"", chartColor(i), {}, true, Marker::None};
    for (double angle = 0.0; angle <= 89.75; angle += 0.5) {
      const TirSample sample = measureInterface(ior, angle);
      const double schlickT = 1.0 - schlickReflectance(ior, angle);
      const double exactT = 1.0 - exactReflectance(ior, angle);
      energyError = std::max(energyError, std::abs(sample.transmitted + sample.reflected - 1.0));
      schlickError = std::max(schlickError, std::abs(sample.transmitted - schlickT));
      exactError = std::max(exactError, std::abs(sample.transmitted - exactT));
      traced.points.push_back({angle, sample.transmitted, ""});
      exact.points.push_back({angle, exactT, ""});
      char line[160];
      std::snprintf(line, sizeof line, "%g,%g,%.6f,%.6f,%.6f,%d,%.6f,%.6f\n", ior, angle,
                    sample.transmitted, sample.reflected, sample.transmitted + sample.reflected,
                    sample.totalInternalReflection ? 1 : 0, schlickT, exactT);
      csv += line;
    }
    const double critical = tracedCriticalAngle(ior);
    const double formula = glm::degrees(std::asin(1.0 / double(ior)));
    char line[200];
    std::snprintf(line, sizeof line, "%-6g %21.5f %12.5f %12.2e %18.2e %21.4f %19.4f", ior,
                  critical, formula, critical - formula, energyError, schlickError, exactError);
    services.progress(line);
    result.report += std::string(line) + "\n";
    chart.series.push_back(std::move(traced));
    chart.series.push_back(std::move(exact));
  }
  writeTextFile(options.output / "tir.csv", csv);
  writeImage(drawChart(chart, 720, 420), options.output / "tir.png");
  result.files = {"tir.csv", "tir.png"};
  for (float ior : {1.33f, 1.5f}) {
    char name[64];
    std::snprintf(name, sizeof name, "snells_window_ior%g.png", ior);
    writeImage(snellsWindow(ior, options.width, options.height), options.output / name);
    result.files.push_back(name);
  }
  return result;
}

}  // namespace shadelab
