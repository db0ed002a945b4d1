// Study `shadow-edges`: how a shadow map's resolution and filter show at
// shadow edges. Each method and map size draws the `shadows` scene (Phong);
// its mean FLIP against the traced reference with exact shadow rays, and
// against the same frame without shadows, says how much of the shadows'
// error is left. The device time of the frame is charted with it.
#include <cstdio>
#include <sstream>

#include "core/base/files.h"
#include "core/base/stats.h"
#include "core/metrics/chart.h"
#include "core/metrics/error_metric.h"
#include "measure/reference.h"
#include "measure/study.h"

namespace shadelab {

StudyResult runShadowEdgesStudy(const StudyOptions& options, const StudyServices& services) {
  Renderer& renderer = services.renderer();
  const Scene scene = builtinScene("shadows");
  const ErrorMetric& flip = findErrorMetric("flip", "study");
  services.progress("tracing the reference (4 spp, shadow rays)");
  ImageU8 reference =
      encodeSrgb8(traceReference(4, true).render(renderer, scene, options.width, options.height));
  const uint32_t sizes[] = {128, 256, 512, 1024, 2048};
  const ShadowMethod methods[] = {ShadowMethod::Hard, ShadowMethod::Pcf3, ShadowMethod::Pcf5};

  RenderSettings settings{options.width, options.height, ShadingModel::Phong};
  settings.frames = 12;
  auto measure = [&](ShadowMethod method, uint32_t size, double& ms) {
    settings.shadows = method;
    settings.shadowMapSize = size;
    RenderResult run = renderer.renderToImage(scene, settings);
    std::vector<double> device(run.stats.deviceMs.begin() + 2, run.stats.deviceMs.end());
    ms = median(device);
    return flip.measure(reference, encodeSrgb8(run.image));
  };
  double offMs = 0.0;
  double off = measure(ShadowMethod::Off, kDefaultShadowMapSize, offMs);

  StudyResult result;
  std::ostringstream csv;
  csv << "method,map_size,width,height,flip,device_median_ms\n";
  csv << "off,0," << options.width << ',' << options.height << ',' << off << ',' << offMs << '\n';
  char line[160];
  std::snprintf(line, sizeof line, "no shadows: mean FLIP %.4f, %.2f ms", off, offMs);
  result.report = std::string(line) + "\nmethod  map size   mean FLIP   device ms\n";
  Chart chart;
  chart.title = "Shadow maps on the shadows scene against traced shadow rays";
  std::snprintf(line, sizeof line, "Phong at %ux%u; without shadows the mean FLIP is %.4f",
                options.width, options.height, off);
  chart.subtitle = line;
  chart.x = {"shadow map size (texels, log)", AxisScale::Log};
  chart.y = {"mean FLIP against the traced reference", AxisScale::Linear};
  for (size_t m = 0; m < std::size(methods); ++m) {
    ChartSeries series{
        std::string(nameOf(kShadowMethodNames, methods[m])), chartColor(m), {}, true, Marker::Dot};
    for (uint32_t size : sizes) {
      double ms = 0.0;
      double error = measure(methods[m], size, ms);
      std::snprintf(line, sizeof line, "%-7s %8u %11.4f %11.2f",
                    std::string(nameOf(kShadowMethodNames, methods[m])).c_str(), size, error, ms);
      services.progress(line);
      result.report += std::string(line) + "\n";
      csv << nameOf(kShadowMethodNames, methods[m]) << ',' << size << ',' << options.width << ','
          << options.height << ',' << error << ',' << ms << '\n';
      series.points.push_back({double(size), error, ""});
    }
    chart.series.push_back(series);
  }
  writeTextFile(options.output / "shadow_edges.csv", csv.str());
  writeImage(drawChart(chart, 720, 400), options.output / "shadow_edges.png");
  result.files = {"shadow_edges.csv", "shadow_edges.png"};
  return result;
}

}  // namespace shadelab
