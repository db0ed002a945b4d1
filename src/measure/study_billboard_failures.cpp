// Study `billboard-failures`: the billboard pass's two known failures as
// numbers. A cylindrical billboard seen from above goes edge-on (its pixels
// against the eye's elevation, beside a spherical one and the exact
// orthographic areas); and billboards have real depth, so the ground cuts a
// sunk one along a straight line at the row where the quad's plane meets
// the ground, and a spherical one, leaning back to face a rising eye, sinks
// out of sight.
#include <cstdio>
#include <sstream>

#include "core/base/files.h"
#include "core/metrics/chart.h"
#include "core/metrics/sheet.h"
#include "measure/billboard_failures.h"
#include "measure/study.h"

namespace shadelab {
namespace {

constexpr float kSink = 0.3f;  // the ground-cut quad's centre below the ground (its height: 2)

const char* kindName(BillboardKind kind) {
  return nameOf(kBillboardKindNames, kind).data();
}

}  // namespace

StudyResult runBillboardFailuresStudy(const StudyOptions& options, const StudyServices& services) {
  Renderer& renderer = services.renderer();
  const BillboardKind kinds[] = {BillboardKind::Cylindrical, BillboardKind::Spherical};
  StudyResult result;

  std::ostringstream coverageCsv;
  coverageCsv << "kind,elevation_degrees,covered_pixels,expected_pixels,face_on_pixels,"
                 "covered_percent_of_face_on\n";
  result.report =
      "coverage (orthographic, 2 x 3 quad)\n"
      "kind         elevation  covered px  expected px  % of face-on\n";
  Chart coverage;
  coverage.title = "Billboard coverage as the eye rises";
  coverage.subtitle = "orthographic; lines: the exact area, dots: pixels drawn";
  coverage.x = {"eye elevation (degrees)", AxisScale::Linear, 0.0, 90.0};
  coverage.y = {"pixels, % of the quad seen face-on", AxisScale::Linear, 0.0, 110.0};
  std::vector<SheetCell> coverageCells;
  for (size_t k = 0; k < 2; ++k) {
    ChartSeries drawn{std::string(kindName(kinds[k])), chartColor(k), {}, false, Marker::Dot};
    ChartSeries exact{"", chartColor(k), {}, true, Marker::None};
    for (float elevation = 0.0f; elevation <= 90.0f; elevation += 7.5f) {
      BillboardCoverage c =
          measureBillboardCoverage(renderer, kinds[k], elevation, options.width, options.height);
      char line[160];
      std::snprintf(line, sizeof line, "%-11s  %9.1f  %10llu  %11.1f  %12.1f", kindName(kinds[k]),
                    double(elevation), static_cast<unsigned long long>(c.covered), c.expected,
                    100.0 * double(c.covered) / c.fullArea);
      services.progress(line);
      result.report += std::string(line) + "\n";
      coverageCsv << kindName(kinds[k]) << ',' << elevation << ',' << c.covered << ',' << c.expected
                  << ',' << c.fullArea << ',' << 100.0 * double(c.covered) / c.fullArea << '\n';
      drawn.points.push_back({elevation, 100.0 * double(c.covered) / c.fullArea, ""});
      exact.points.push_back({elevation, 100.0 * c.expected / c.fullArea, ""});
    }
    coverage.series.push_back(exact);
    coverage.series.push_back(drawn);
  }

  std::ostringstream cutCsv;
  cutCsv << "kind,elevation_degrees,sink,cut_height,columns,mean_row_error,max_row_error,"
            "max_line_residual,bottom_edge_gap_rows,visible_pixels,unhidden_pixels,"
            "visible_percent\n";
  result.report +=
      "\nground cut (perspective, 2 x 2 quad, centre 0.3 below the ground)\n"
      "kind         elevation  cut height  columns  row error mean  max   "
      "line residual  bottom-edge gap  visible %\n";
  Chart visible;
  visible.title = "A billboard sunk 0.3 into the ground";
  visible.subtitle = "pixels above the ground, % of the whole quad's";
  visible.x = {"eye elevation (degrees)", AxisScale::Linear, 0.0, 90.0};
  visible.y = {"visible %", AxisScale::Linear, 0.0, 100.0};
  std::vector<std::vector<SheetCell>> cutRows;
  for (size_t k = 0; k < 2; ++k) {
    ChartSeries series{std::string(kindName(kinds[k])), chartColor(k), {}, true, Marker::Dot};
    std::vector<SheetCell> row;
    for (float elevation = 10.0f; elevation <= 80.0f; elevation += 10.0f) {
      BillboardGroundCut cut =
          measureGroundCut(renderer, kinds[k], elevation, kSink, options.width, options.height);
      char line[200];
      std::snprintf(
          line, sizeof line, "%-11s  %9.1f  %10.3f  %7u  %14.2f  %4.2f  %13.2f  %15.1f  %9.1f",
          kindName(kinds[k]), double(elevation), cut.cutHeight, cut.columns, cut.meanRowError,
          cut.maxRowError, cut.maxLineResidual, cut.bottomEdgeGap, 100.0 * cut.visibleShare());
      services.progress(line);
      result.report += std::string(line) + "\n";
      cutCsv << kindName(kinds[k]) << ',' << elevation << ',' << kSink << ',' << cut.cutHeight
             << ',' << cut.columns << ',' << cut.meanRowError << ',' << cut.maxRowError << ','
             << cut.maxLineResidual << ',' << cut.bottomEdgeGap << ',' << cut.visible << ','
             << cut.unhidden << ',' << 100.0 * cut.visibleShare() << '\n';
      series.points.push_back({elevation, 100.0 * cut.visibleShare(), ""});
      if (elevation == 20.0f || elevation == 50.0f || elevation == 70.0f) {
        char title[64], error[64];
        std::snprintf(title, sizeof title, "%s, %g degrees", kindName(kinds[k]), double(elevation));
        if (cut.columns > 0)
          std::snprintf(error, sizeof error, "cut to the red line: max %.2f px", cut.maxRowError);
        else
          std::snprintf(error, sizeof error, "buried: the ground meets it above its top");
        row.push_back({cut.image, title, {error}});
      }
    }
    visible.series.push_back(series);
    cutRows.push_back(row);
  }

  writeTextFile(options.output / "billboard_coverage.csv", coverageCsv.str());
  writeTextFile(options.output / "billboard_ground_cut.csv", cutCsv.str());
  writeImage(drawChartRow({coverage, visible}, 460, 320),
             options.output / "billboard_failures.png");
  writeImage(composeSheet(cutRows), options.output / "billboard_ground_cut.png");
  result.files = {"billboard_coverage.csv", "billboard_ground_cut.csv", "billboard_failures.png",
                  "billboard_ground_cut.png"};
  return result;
}

}  // namespace shadelab
