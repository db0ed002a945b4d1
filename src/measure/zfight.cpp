#include "measure/zfight.h"

#include <algorithm>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <sstream>

#include "core/metrics/chart.h"

namespace shadelab {
namespace {

const char* projectionName(Projection projection) {
  return nameOf(kProjectionNames, projection).data();  // the table's names are literals
}

}  // namespace

Scene zfightSceneAt(Projection projection, float near, float distanceScale) {
  Scene scene = zfightScene(projection, near);
  Camera& camera = scene.camera;
  camera.eye = camera.at + (camera.eye - camera.at) * distanceScale;
  camera.left *= distanceScale;
  camera.right *= distanceScale;
  camera.bottom *= distanceScale;
  camera.top *= distanceScale;
  // The planes lie in y = 0 and y = -gap: scaling x and z keeps the gap.
  glm::mat4 grow = glm::scale(glm::mat4(1.0f), {distanceScale, 1.0f, distanceScale});
  for (Object& object : scene.objects) object.transform = grow * object.transform;
  return scene;
}

double zfightDistance(float distanceScale) {
  const Camera& camera = builtinScene("zfight").camera;
  return glm::length(camera.eye - camera.at) * double(distanceScale);
}

ZFightPixel classifyZFightPixel(const ImageRgba& image, size_t p) {
  // Unlit, the planes are pure red (near) and pure blue (far) on black; edge
  // pixels blend with the background, so compare the two channels.
  float nearChannel = image.pixels[p * 4 + 0], farChannel = image.pixels[p * 4 + 2];
  if (nearChannel + farChannel < 0.5f) return ZFightPixel::Background;
  return farChannel > nearChannel ? ZFightPixel::FarPlane : ZFightPixel::NearPlane;
}

ZFightMeasurement measureZFight(Renderer& renderer, DepthMode depth, Projection projection,
                                float near, uint32_t width, uint32_t height, float distanceScale) {
  Scene farFirst = zfightSceneAt(projection, near, distanceScale);
  Scene farLast = farFirst;
  std::reverse(farLast.objects.begin(), farLast.objects.end());
  RenderSettings settings{width, height, ShadingModel::Unlit};
  settings.depth = depth;
  settings.frontToBack = false;  // each order as given: sorted, the near plane would come first
  ImageRgba a = renderer.renderToImage(farFirst, settings).image;
  ImageRgba b = renderer.renderToImage(farLast, settings).image;
  ZFightMeasurement result{depth, projection, near, distanceScale};
  for (size_t p = 0; p < size_t(width) * height; ++p) {
    ZFightPixel first = classifyZFightPixel(a, p), last = classifyZFightPixel(b, p);
    if (first == ZFightPixel::Background && last == ZFightPixel::Background) continue;
    ++result.coveredPixels;
    if (first == ZFightPixel::FarPlane || last == ZFightPixel::FarPlane) ++result.wrongPixels;
  }
  return result;
}

std::vector<ZFightMeasurement> runZFightSweep(
    Renderer& renderer, const std::vector<ZFightSetting>& settings, uint32_t width, uint32_t height,
    const std::function<void(const std::string&)>& progress) {
  std::vector<ZFightMeasurement> results;
  for (Projection projection : {Projection::Perspective, Projection::Orthographic})
    for (DepthMode depth : valuesOf(kDepthModeNames))
      for (const ZFightSetting& setting : settings) {
        results.push_back(measureZFight(renderer, depth, projection, setting.near, width, height,
                                        setting.distanceScale));
        char line[160];
        std::snprintf(
            line, sizeof line, "%-12s %-8s near %-7g distance %-6.1f wrong %6.2f%% of %llu pixels",
            projectionName(projection), std::string(depthModeName(depth)).c_str(), setting.near,
            zfightDistance(setting.distanceScale), 100.0 * results.back().wrongFraction(),
            static_cast<unsigned long long>(results.back().coveredPixels));
        progress(line);
      }
  return results;
}

std::string zfightCsv(const std::vector<ZFightMeasurement>& measurements, uint32_t width,
                      uint32_t height) {
  std::ostringstream csv;
  csv << "projection,depth,format,near,far,distance,gap,width,height,covered_pixels,"
         "wrong_pixels,wrong_fraction\n";
  for (const ZFightMeasurement& m : measurements) {
    Scene scene = zfightScene(m.projection, m.near);
    csv << projectionName(m.projection) << ',' << depthModeName(m.depth) << ','
        << depthFormatName(m.depth) << ',' << m.near << ',' << scene.camera.far << ','
        << zfightDistance(m.distanceScale) << ',' << kZFightGap << ',' << width << ',' << height
        << ',' << m.coveredPixels << ',' << m.wrongPixels << ',' << m.wrongFraction() << '\n';
  }
  return csv.str();
}

ImageU8 zfightChart(const std::vector<ZFightMeasurement>& measurements, ZFightAxis axis) {
  std::vector<Chart> panels;
  for (Projection projection : {Projection::Perspective, Projection::Orthographic}) {
    Chart chart;
    chart.title = std::string("Z-fighting, ") + projectionName(projection);
    char subtitle[96];
    if (axis == ZFightAxis::Near) {
      std::snprintf(subtitle, sizeof subtitle, "planes %g apart, 80-230 units away; far %g",
                    kZFightGap, zfightScene(projection, 1.0f).camera.far);
      chart.x = {"near plane distance (log)", AxisScale::Log};
    } else {
      std::snprintf(subtitle, sizeof subtitle, "planes %g apart; near %g, far %g", kZFightGap,
                    measurements.empty() ? 0.0f : measurements.front().near,
                    zfightScene(projection, 1.0f).camera.far);
      chart.x = {"distance to the planes' centre (log)", AxisScale::Log};
    }
    chart.subtitle = subtitle;
    chart.y = {"farther plane wins (% of pixels)", AxisScale::Linear, 0.0, 100.0};
    for (DepthMode depth : valuesOf(kDepthModeNames)) {
      ChartSeries series{
          depth == DepthMode::ReversedZ ? "reversed-Z d32f" : std::string(depthModeName(depth)),
          chartColor(size_t(depth)),
          {},
          true,
          Marker::Dot};
      for (const ZFightMeasurement& m : measurements)
        if (m.projection == projection && m.depth == depth)
          series.points.push_back(
              {axis == ZFightAxis::Near ? double(m.near) : zfightDistance(m.distanceScale),
               100.0 * m.wrongFraction(), ""});
      chart.series.push_back(std::move(series));
    }
    panels.push_back(std::move(chart));
  }
  return drawChartRow(panels, 560, 360);
}

}  // namespace shadelab
