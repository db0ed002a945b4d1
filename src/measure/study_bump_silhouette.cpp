// Study `bump-silhouette`: the seed's test for telling bump mapping from real
// geometry ("check whether the silhouette is flat"), measured: the bump
// scene's dimpled sphere bump-mapped beside the same height field as real
// displacement, at increasing tessellation until the geometry's own error is
// below a pixel; pixels whose coverage differs (the silhouette) and mean
// FLIP where both cover (the interior).
#include <cstdio>

#include "core/base/files.h"
#include "core/metrics/chart.h"
#include "measure/bump_silhouette.h"
#include "measure/study.h"

namespace shadelab {

StudyResult runBumpSilhouetteStudy(const StudyOptions& options, const StudyServices& services) {
  Renderer& renderer = services.renderer();
  StudyResult result;
  char line[240];
  std::snprintf(line, sizeof line,
                "displacement amplitude %.4f (bump_scale x one texel at the equator)\n"
                "slices  triangles  sphere px (bump/displaced)  outline differs px   "
                "bump vs plain px  interior mean FLIP\n",
                bumpDisplacementAmplitude(bumpSphereScene()));
  result.report = line;
  std::string csv =
      "slices,triangles,width,height,covered_bump,covered_displaced,covered_plain,"
      "silhouette_difference,bump_vs_plain,interior_flip\n";
  Chart chart;
  chart.title = "Bump mapping against displaced geometry";
  chart.subtitle = "bump sphere: dimples height map; displaced: the same heights as geometry";
  chart.x = {"slices of the displaced sphere (log)", AxisScale::Log};
  chart.y = {"pixels whose coverage differs", AxisScale::Linear};
  ChartSeries outline{"bump vs displaced", chartColor(0), {}, true, Marker::Dot};
  ChartSeries plain{"bump vs plain", chartColor(1), {}, true, Marker::Dot};
  for (uint32_t slices : {64u, 128u, 256u, 512u, 1024u}) {
    BumpSilhouetteMeasurement m =
        measureBumpSilhouette(renderer, slices, options.width, options.height);
    std::snprintf(line, sizeof line, "%6u %10llu %13llu/%-13llu %17llu %18llu %19.4f", slices,
                  (unsigned long long)m.triangles, (unsigned long long)m.coveredBump,
                  (unsigned long long)m.coveredDisplaced,
                  (unsigned long long)m.silhouetteDifference, (unsigned long long)m.bumpVersusPlain,
                  m.interiorFlip);
    services.progress(line);
    result.report += std::string(line) + "\n";
    std::snprintf(line, sizeof line, "%u,%llu,%u,%u,%llu,%llu,%llu,%llu,%llu,%.6f\n", slices,
                  (unsigned long long)m.triangles, options.width, options.height,
                  (unsigned long long)m.coveredBump, (unsigned long long)m.coveredDisplaced,
                  (unsigned long long)m.coveredPlain, (unsigned long long)m.silhouetteDifference,
                  (unsigned long long)m.bumpVersusPlain, m.interiorFlip);
    csv += line;
    outline.points.push_back({double(slices), double(m.silhouetteDifference), ""});
    plain.points.push_back({double(slices), double(m.bumpVersusPlain), ""});
    if (slices == 1024u) {
      writeImage(m.bump, options.output / "bump.png");
      writeImage(m.displaced, options.output / "displaced_1024.png");
      result.files = {"bump.png", "displaced_1024.png"};
    }
  }
  chart.series = {outline, plain};
  writeTextFile(options.output / "bump-silhouette.csv", csv);
  writeImage(drawChart(chart, 720, 380), options.output / "bump-silhouette.png");
  result.files.insert(result.files.begin(), {"bump-silhouette.csv", "bump-silhouette.png"});
  return result;
}

}  // namespace shadelab
