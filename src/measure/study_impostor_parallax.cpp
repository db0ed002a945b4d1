// Study `impostor-parallax`: an octahedral impostor against the mesh it
// stands for, as a function of its atlas's cells per side (the angle a view
// may be from the direction it was captured from). The bound the level-of-
// detail chain ranks the impostor by (core/scene/impostor.h, impostorError)
// beside the measured outline distance and FLIP.
#include <cstdio>
#include <sstream>

#include "core/base/files.h"
#include "core/metrics/chart.h"
#include "core/metrics/sheet.h"
#include "measure/impostor_parallax.h"
#include "measure/study.h"

namespace shadelab {

StudyResult runImpostorParallaxStudy(const StudyOptions& options, const StudyServices& services) {
  const std::vector<uint32_t> cellCounts = {4, 6, 8, 12, 16, 24, 32};
  constexpr uint32_t kViews = 24;
  std::vector<ImpostorParallax> results;
  for (bool blend : {false, true})
    for (uint32_t cells : cellCounts) {
      services.progress(std::string(blend ? "blended, " : "nearest cell, ") + "cells " +
                        std::to_string(cells));
      std::vector<ImpostorParallax> one = measureImpostorParallax(
          services.renderer(), {cells}, kViews, options.width, options.height, blend);
      results.push_back(std::move(one.front()));
    }
  StudyResult result;
  result.report =
      "one teapot, 24 views; outline distance = pixels covered by one image only / the full\n"
      "mesh's outline pixels; bound = impostorError at the teapot's centre (parallax part:\n"
      "radius sin(angle), the angle the nearest cell's or the blend's)\n"
      "cells  cells drawn  angle deg  bound px  parallax px  outline px mean  max    FLIP mean  "
      "impostor drawn\n";
  std::ostringstream csv;
  csv << "cells,drawn_from,parallax_angle_degrees,bound_pixels,parallax_bound_pixels,outline_"
         "pixels_mean,"
         "outline_pixels_max,flip_mean,views,impostor_drawn\n";
  Chart chart;
  chart.title = "Impostor against the full mesh";
  chart.subtitle = "one teapot, 24 views; bound: impostorError, what the LOD chain uses";
  chart.x = {"atlas cells per side", AxisScale::Log, 4.0, 32.0};
  chart.y = {"pixels", AxisScale::Log, 0.1, 100.0};
  ChartSeries bound{"bound", chartColor(0), {}, true, Marker::None};
  ChartSeries mean{"nearest cell, mean", chartColor(1), {}, true, Marker::Dot};
  ChartSeries worst{"nearest cell, worst", chartColor(2), {}, true, Marker::Dot};
  ChartSeries blendMean{"blended, mean", chartColor(3), {}, true, Marker::Dot};
  ChartSeries blendWorst{"blended, worst", chartColor(4), {}, true, Marker::Dot};
  std::vector<SheetCell> pairs;
  for (const ImpostorParallax& r : results) {
    char line[200];
    const char* drawn = r.blend ? "blend" : "nearest";
    std::snprintf(line, sizeof line, "%5u  %11s  %9.2f  %8.2f  %11.2f  %15.2f  %5.2f  %9.4f  %s",
                  r.cells, drawn, r.angleDegrees, r.boundPixels, r.parallaxBoundPixels,
                  r.meanOutlinePixels, r.maxOutlinePixels, r.meanFlip,
                  r.allImpostors ? "yes" : "NO");
    result.report += std::string(line) + "\n";
    csv << r.cells << ',' << drawn << ',' << r.angleDegrees << ',' << r.boundPixels << ','
        << r.parallaxBoundPixels << ',' << r.meanOutlinePixels << ',' << r.maxOutlinePixels << ','
        << r.meanFlip << ',' << r.views << ',' << (r.allImpostors ? 1 : 0) << '\n';
    if (r.blend) {
      blendMean.points.push_back({double(r.cells), std::max(0.1, r.meanOutlinePixels), ""});
      blendWorst.points.push_back({double(r.cells), std::max(0.1, r.maxOutlinePixels), ""});
      continue;
    }
    bound.points.push_back({double(r.cells), r.boundPixels, ""});
    mean.points.push_back({double(r.cells), std::max(0.1, r.meanOutlinePixels), ""});
    worst.points.push_back({double(r.cells), std::max(0.1, r.maxOutlinePixels), ""});
    if (r.cells == 4 || r.cells == 16) {
      char title[64], caption[80];
      std::snprintf(title, sizeof title, "%u cells: full | impostor", r.cells);
      std::snprintf(caption, sizeof caption, "worst view: outline %.2f px", r.maxOutlinePixels);
      pairs.push_back({r.worstPair, title, {caption}});
    }
  }
  chart.series = {bound, mean, worst, blendMean, blendWorst};
  writeTextFile(options.output / "impostor_parallax.csv", csv.str());
  writeImage(drawChartRow({chart}, 560, 340), options.output / "impostor_parallax.png");
  writeImage(composeSheet({pairs}), options.output / "impostor_views.png");
  result.files = {"impostor_parallax.csv", "impostor_parallax.png", "impostor_views.png"};
  return result;
}

}  // namespace shadelab
