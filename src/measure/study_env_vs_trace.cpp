// Study `env-vs-trace`: environment mapping against the traced reflection on
// the `env` scene, its error split by where the traced specular path goes
// (core/trace/reflection_regions.h): paths that hit an object (inter- and
// self-reflection, which no environment map holds) against paths that
// escape (only distortion and parallax), per shading model; and the same
// split against a reference traced without Fresnel, the tracer before issue 16.
#include <cstdio>

#include "core/base/files.h"
#include "core/metrics/chart.h"
#include "core/metrics/metrics.h"
#include "core/scene/shading.h"
#include "core/scene/shadows.h"
#include "core/trace/raytracer.h"
#include "core/trace/reflection_regions.h"
#include "measure/study.h"

namespace shadelab {

StudyResult runEnvVsTraceStudy(const StudyOptions& options, const StudyServices& services) {
  Renderer& renderer = services.renderer();
  const Scene scene = builtinScene("env");
  TraceSettings trace;
  trace.width = options.width, trace.height = options.height, trace.samplesPerPixel = 4;
  RayTracer tracer(scene);
  const ImageRgba reference = tracer.render(trace).image;
  trace.fresnel = false;
  const ImageU8 referenceWithoutFresnel = encodeSrgb8(tracer.render(trace).image);
  const ImageU8 referenceU8 = encodeSrgb8(reference);
  const ReflectionRegions regions = classifyReflections(scene, options.width, options.height);
  StudyResult result;
  char line[240];
  std::snprintf(line, sizeof line,
                "mean FLIP against the trace (4 spp) where the reflection hits an object (%llu px) "
                "and where it escapes (%llu px); without Fresnel in the trace in brackets\n",
                (unsigned long long)regions.count(ReflectionRegion::HitsObject),
                (unsigned long long)regions.count(ReflectionRegion::Escapes));
  result.report = line;
  std::string csv =
      "mode,width,height,flip,flip_hits_object,flip_escapes,flip_no_fresnel,"
      "flip_hits_object_no_fresnel,flip_escapes_no_fresnel\n";
  Chart chart;
  chart.title = "Env mapping against traced reflection (env)";
  chart.subtitle = "mean FLIP per region of the traced specular path; rings: trace without Fresnel";
  chart.x = {"shading model (flat, Gouraud, Phong, Blinn-Phong)", AxisScale::Linear, 0.5, 4.5};
  chart.y = {"mean FLIP", AxisScale::Linear, 0.0, 0.7};
  ChartSeries hits{"path hits an object", chartColor(1), {}, true, Marker::Dot};
  ChartSeries escapes{"path escapes", chartColor(0), {}, true, Marker::Dot};
  ChartSeries hitsBefore{"", chartColor(1), {}, false, Marker::Ring};
  ChartSeries escapesBefore{"", chartColor(0), {}, false, Marker::Ring};
  double position = 1.0;
  for (ShadingModel model :
       {ShadingModel::Flat, ShadingModel::Gouraud, ShadingModel::Phong, ShadingModel::BlinnPhong}) {
    // Shadowed as the trace is, and as `compare env`'s columns are by default.
    RenderSettings settings{options.width, options.height, model};
    settings.shadows = kDefaultShadowMethod;
    const ImageRgba raster = renderer.renderToImage(scene, settings).image;
    const ImageU8 rasterU8 = encodeSrgb8(raster);
    const MetricMap flip = flipError(referenceU8, rasterU8);
    const MetricMap before = flipError(referenceWithoutFresnel, rasterU8);
    const double hit = meanOver(flip, regions, ReflectionRegion::HitsObject);
    const double escape = meanOver(flip, regions, ReflectionRegion::Escapes);
    const double hitBefore = meanOver(before, regions, ReflectionRegion::HitsObject);
    const double escapeBefore = meanOver(before, regions, ReflectionRegion::Escapes);
    const std::string name(shadingModelName(model));
    std::snprintf(line, sizeof line,
                  "%-12s FLIP %.4f (%.4f)  hits an object %.4f (%.4f)  escapes %.4f (%.4f)",
                  name.c_str(), flip.mean, before.mean, hit, hitBefore, escape, escapeBefore);
    services.progress(line);
    result.report += std::string(line) + "\n";
    std::snprintf(line, sizeof line, "%s,%u,%u,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f\n", name.c_str(),
                  options.width, options.height, flip.mean, hit, escape, before.mean, hitBefore,
                  escapeBefore);
    csv += line;
    hits.points.push_back({position, hit, ""});
    escapes.points.push_back({position, escape, ""});
    hitsBefore.points.push_back({position, hitBefore, ""});
    escapesBefore.points.push_back({position, escapeBefore, ""});
    if (model == ShadingModel::Phong) {
      writeImage(raster, options.output / "phong.png");
      result.files.push_back("phong.png");
    }
    position += 1.0;
  }
  chart.series = {hits, escapes, hitsBefore, escapesBefore};
  writeTextFile(options.output / "env-vs-trace.csv", csv);
  writeImage(drawChart(chart, 720, 380), options.output / "env-vs-trace.png");
  writeImage(reference, options.output / "trace.png");
  writeImage(regionImage(regions), options.output / "regions.png");
  result.files.insert(result.files.begin(),
                      {"env-vs-trace.csv", "env-vs-trace.png", "trace.png", "regions.png"});
  return result;
}

}  // namespace shadelab
