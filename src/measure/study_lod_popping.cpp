// Study `lod-popping`: --lod auto chooses each object's level every frame;
// a switch is a pop, a jump between consecutive frames. Measured on a dolly
// away from six shapes and on a small oscillation about one sphere's
// switching distance, with the default hysteresis (0.75) and without (1):
// how many switches, how much larger the frame-to-frame change is where a
// level switched than the camera's motion alone makes it (the same step with
// lod off), and each frame's error against its lod-off twin.
#include <cstdio>
#include <sstream>

#include "core/base/files.h"
#include "core/metrics/chart.h"
#include "core/metrics/metrics.h"
#include "core/metrics/sheet.h"
#include "measure/lod_popping.h"
#include "measure/study.h"

namespace shadelab {
namespace {

constexpr uint32_t kDollyFrames = 241;       // 1% farther each frame
constexpr uint32_t kOscillationFrames = 96;  // 8 periods
// The dolly again at a coarse bound, where a switch is a visible jump.
constexpr float kCoarseBound = 4.0f;

std::string runName(const LodPoppingRun& run) {
  char text[48];
  std::snprintf(text, sizeof text, "%g px, hysteresis %.2f", double(run.bound),
                double(run.hysteresis));
  return text;
}

// Dolly: popped pixels per frame, a line per hysteresis, switch frames
// ringed. Oscillation: switches so far per frame.
ImageU8 popChart(const LodCameraPath& dolly, const std::vector<LodPoppingRun>& dollyRuns,
                 const std::vector<LodPoppingRun>& oscillationRuns) {
  Chart pops;
  pops.title = "Dolly away: popped pixels";
  pops.subtitle = "changed against lod off since the last frame; rings: a switch";
  pops.x = {"eye z (log)", AxisScale::Log};
  pops.y = {"pixels", AxisScale::Linear, 0.0};
  for (size_t r = 0; r < dollyRuns.size(); ++r) {
    ChartSeries line{runName(dollyRuns[r]), chartColor(r), {}, true, Marker::None};
    ChartSeries rings{"", chartColor(r), {}, false, Marker::Ring, 5.0};
    for (size_t i = 1; i < dollyRuns[r].frames.size(); ++i) {
      const LodPoppingFrame& frame = dollyRuns[r].frames[i];
      line.points.push_back({dolly.eyeZ[i], double(frame.poppedPixels), ""});
      if (frame.switches > 0) rings.points.push_back({dolly.eyeZ[i], double(frame.poppedPixels)});
    }
    pops.series.push_back(line);
    pops.series.push_back(rings);
  }

  Chart counts;
  counts.title = "Oscillating about a switching distance";
  counts.subtitle = "switches so far; swing 3% of the distance";
  counts.x = {"frame", AxisScale::Linear};
  counts.y = {"level switches", AxisScale::Linear, 0.0};
  for (size_t r = 0; r < oscillationRuns.size(); ++r) {
    ChartSeries series{"hysteresis " + std::to_string(oscillationRuns[r].hysteresis).substr(0, 4),
                       chartColor(r),
                       {},
                       true,
                       Marker::None};
    uint32_t total = 0;
    for (size_t i = 0; i < oscillationRuns[r].frames.size(); ++i) {
      total += oscillationRuns[r].frames[i].switches;
      series.points.push_back({double(i), double(total), ""});
    }
    counts.series.push_back(series);
  }
  return drawChartRow({pops, counts}, 480, 320);
}

}  // namespace

StudyResult runLodPoppingStudy(const StudyOptions& options, const StudyServices& services) {
  Renderer& renderer = services.renderer();
  Scene scene = lodPoppingScene();
  const float hysteresis[] = {kLodHysteresis, 1.0f};
  LodCameraPath dolly = dollyPath(kDollyFrames);
  LodCameraPath oscillation = oscillationPath(scene, renderer, kOscillationFrames, options.height);
  services.progress("dolly, " + std::to_string(kDollyFrames) + " frames");
  std::vector<LodPoppingRun> dollyRuns =
      measureLodPopping(renderer, scene, dolly, hysteresis, options.width, options.height);
  for (LodPoppingRun& run : measureLodPopping(renderer, scene, dolly, hysteresis, options.width,
                                              options.height, kCoarseBound))
    dollyRuns.push_back(std::move(run));
  services.progress("oscillation, " + std::to_string(kOscillationFrames) + " frames");
  std::vector<LodPoppingRun> oscillationRuns =
      measureLodPopping(renderer, scene, oscillation, hysteresis, options.width, options.height);

  StudyResult result;
  std::ostringstream csv;
  csv << "path,bound_pixels,hysteresis,frame,eye_z,triangles,switches,step_flip_lod,step_flip_off,"
         "popped_pixels,flip_against_off\n";
  result.report =
      "path       bound px  hysteresis  frames  switches  step FLIP lod/off: at switch  elsewhere  "
      "popped px: at switch  elsewhere  FLIP vs off: mean  max     model\n";
  for (const auto* runs : {&dollyRuns, &oscillationRuns}) {
    const LodCameraPath& path = runs == &dollyRuns ? dolly : oscillation;
    for (const LodPoppingRun& run : *runs) {
      char line[240];
      std::snprintf(
          line, sizeof line,
          "%-10s %8.1f  %10.2f  %6zu  %8u  %27.3f  %9.3f  %20.1f  %9.1f  %17.4f  %.4f  %s",
          run.path.c_str(), double(run.bound), double(run.hysteresis), run.frames.size(),
          run.switches(), run.stepRatio(true), run.stepRatio(false), run.meanPopped(true),
          run.meanPopped(false), run.meanErrorAgainstOff(), run.maxErrorAgainstOff(),
          run.modelAgrees ? "agrees" : "DIFFERS");
      result.report += std::string(line) + "\n";
      for (size_t i = 0; i < run.frames.size(); ++i) {
        const LodPoppingFrame& frame = run.frames[i];
        csv << run.path << ',' << run.bound << ',' << run.hysteresis << ',' << i << ','
            << path.eyeZ[i] << ',' << frame.triangles << ',' << frame.switches << ','
            << frame.stepLod << ',' << frame.stepOff << ',' << frame.poppedPixels << ','
            << frame.errorAgainstOff << '\n';
      }
    }
  }
  // The dolly's switch with the most popped pixels at the coarse bound and
  // the default hysteresis, beside the same two cameras with lod off.
  const LodPoppingRun& shown = dollyRuns[2];
  if (!shown.shownAfter.pixels.empty()) {
    const LodPoppingFrame& frame = shown.frames[shown.shownFrame];
    char lines[3][96];
    std::snprintf(lines[0], sizeof lines[0], "%g px bound, frame %u, eye z %.2f",
                  double(shown.bound), shown.shownFrame, double(dolly.eyeZ[shown.shownFrame]));
    std::snprintf(lines[1], sizeof lines[1], "%llu pixels popped",
                  static_cast<unsigned long long>(frame.poppedPixels));
    std::snprintf(lines[2], sizeof lines[2], "step FLIP %.4f, lod off %.4f", frame.stepLod,
                  frame.stepOff);
    std::vector<SheetCell> lodRow = {
        {shown.shownBefore, "lod, frame before", {}},
        {shown.shownAfter, "lod, a level switched", {lines[0]}},
        {popMap(shown.shownBefore, shown.offBefore, shown.shownAfter, shown.offAfter),
         "popped (red)",
         {lines[1]}}};
    std::vector<SheetCell> offRow = {{shown.offBefore, "lod off, frame before", {}},
                                     {shown.offAfter, "lod off", {}},
                                     {magmaHeatmap(flipError(shown.shownBefore, shown.shownAfter)),
                                      "FLIP between lod frames",
                                      {lines[2]}}};
    writeImage(composeSheet({lodRow, offRow}), options.output / "lod_popping_switch.png");
    result.files.push_back("lod_popping_switch.png");
  }
  writeTextFile(options.output / "lod_popping.csv", csv.str());
  writeImage(popChart(dolly, dollyRuns, oscillationRuns), options.output / "lod_popping.png");
  result.files.insert(result.files.begin(), {"lod_popping.csv", "lod_popping.png"});
  return result;
}

}  // namespace shadelab
