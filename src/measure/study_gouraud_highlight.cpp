// Study `gouraud-highlight`: the seed's Gouraud failure, a highlight inside
// a large triangle lost, measured as the Gouraud peak over the Phong peak
// against how finely the plane is subdivided.
#include <cstdio>

#include "core/base/files.h"
#include "core/metrics/chart.h"
#include "measure/highlight.h"
#include "measure/study.h"

namespace shadelab {

StudyResult runGouraudHighlightStudy(const StudyOptions& options, const StudyServices& services) {
  Renderer& renderer = services.renderer();
  StudyResult result;
  std::string csv = "quads_per_side,triangles,width,height,gouraud_peak,phong_peak,ratio\n";
  result.report = "quads      triangles  Gouraud peak  Phong peak  Gouraud / Phong\n";
  Chart chart;
  chart.title = "Gouraud's highlight against subdivision";
  chart.subtitle = "highlight scene: peak luminance of Gouraud over Phong's";
  chart.x = {"triangles in the plane (log)", AxisScale::Log};
  chart.y = {"Gouraud peak / Phong peak (%)", AxisScale::Linear, 0.0, 110.0};
  ChartSeries series{"Gouraud / Phong", chartColor(0), {}, true, Marker::Dot};
  for (uint32_t quads : {1u, 2u, 4u, 8u, 16u, 32u, 64u, 128u}) {
    HighlightMeasurement m = measureHighlight(renderer, quads, options.width, options.height);
    char line[160];
    std::snprintf(line, sizeof line, "%3ux%-3u %12llu %13.3f %11.3f %15.1f%%", quads, quads,
                  (unsigned long long)m.triangles, m.gouraudPeak, m.phongPeak, 100.0 * m.ratio());
    services.progress(line);
    result.report += std::string(line) + "\n";
    std::snprintf(line, sizeof line, "%u,%llu,%u,%u,%.6f,%.6f,%.6f\n", quads,
                  (unsigned long long)m.triangles, options.width, options.height, m.gouraudPeak,
                  m.phongPeak, m.ratio());
    csv += line;
    series.points.push_back({double(m.triangles), 100.0 * m.ratio(), ""});
    if (quads == 1 || quads == 8 || quads == 32) {
      std::snprintf(line, sizeof line, "gouraud_%ux%u.png", quads, quads);
      writeImage(m.gouraud, options.output / line);
      result.files.push_back(line);
    }
  }
  chart.series = {series};
  writeTextFile(options.output / "gouraud-highlight.csv", csv);
  writeImage(drawChart(chart, 640, 380), options.output / "gouraud-highlight.png");
  result.files.insert(result.files.begin(), {"gouraud-highlight.csv", "gouraud-highlight.png"});
  return result;
}

}  // namespace shadelab
