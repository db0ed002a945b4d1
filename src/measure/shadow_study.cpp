#include "measure/shadow_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/metrics/chart.h"
#include "core/trace/raytracer.h"

namespace shadelab {
namespace {

using Pixel = ShadowTruth::Pixel;

float luminance(const ImageRgba& image, size_t p) {
  return 0.2126f * image.pixels[p * 4] + 0.7152f * image.pixels[p * 4 + 1] +
         0.0722f * image.pixels[p * 4 + 2];
}

Scene withOneLight(const Scene& scene, uint32_t light) {
  Scene reduced = scene;
  reduced.lights = {scene.lights[light]};
  reduced.ambient = glm::vec3(0.0f);
  return reduced;
}

}  // namespace

ShadowTruth traceShadowTruth(const Scene& scene, uint32_t lightIndex, uint32_t width,
                             uint32_t height) {
  const Light& light = scene.lights[lightIndex];
  RayTracer tracer(scene);
  CameraRays camera(scene.camera, width, height);
  size_t count = size_t(width) * height;
  std::vector<int32_t> object(count, -1);
  std::vector<Pixel> classes(count, Pixel::Ignored);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      size_t p = size_t(y) * width + x;
      std::optional<SurfaceHit> hit =
          tracer.intersect(camera.through(float(x) + 0.5f, float(y) + 0.5f), 0.0f, 1.0f, true);
      if (!hit) continue;
      object[p] = int32_t(hit->object);
      bool point = light.type == LightType::Point;
      glm::vec3 toLight = point ? light.position - hit->position : -light.direction;
      glm::vec3 L = glm::normalize(toLight);
      glm::vec3 N = hit->geometricNormal;
      if (glm::dot(N, L) <= 0.05f) continue;
      // The tracer's shadow ray: off the surface by an epsilon, to the light.
      Ray shadow{hit->position + N * 1e-3f, point ? toLight : L};
      const float tMax = point ? 1.0f : 1e30f;
      std::optional<SurfaceHit> blocker = tracer.intersect(shadow, 0.0f, tMax);
      // What casts no shadow (billboards, objects with "casts_shadows": false) is looked past.
      while (blocker && (blocker->object >= scene.objects.size() ||
                         !scene.objects[blocker->object].castsShadows))
        blocker = tracer.intersect(shadow, std::nextafter(blocker->t, 1e30f), tMax);
      if (!blocker) {
        classes[p] = Pixel::Lit;
        continue;
      }
      float distance = blocker->t * glm::length(shadow.direction);
      classes[p] = distance < kContactDistance ? Pixel::ShadowedNearContact : Pixel::Shadowed;
    }
  ShadowTruth truth{width, height, classes};
  // Silhouettes and true shadow edges are left to the edge-aliasing study.
  auto lit = [](Pixel pixel) { return pixel == Pixel::Lit; };
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      size_t p = size_t(y) * width + x;
      if (classes[p] == Pixel::Ignored) continue;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          int nx = int(x) + dx, ny = int(y) + dy;
          if (nx < 0 || ny < 0 || nx >= int(width) || ny >= int(height)) continue;
          size_t q = size_t(ny) * width + size_t(nx);
          if (object[q] != object[p] || classes[q] == Pixel::Ignored ||
              lit(classes[q]) != lit(classes[p]))
            truth.pixels[p] = Pixel::Ignored;
        }
    }
  return truth;
}

ShadowErrors measureShadowErrors(Renderer& renderer, const Scene& scene, uint32_t light,
                                 const ShadowTruth& truth, ShadowMethod method,
                                 const ShadowBias& bias, uint32_t mapSize, bool depthClamp) {
  Scene reduced = withOneLight(scene, light);
  RenderSettings settings{truth.width, truth.height, ShadingModel::Phong};
  settings.environment = false;
  ImageRgba unshadowed = renderer.renderToImage(reduced, settings).image;
  settings.shadows = method;
  settings.shadowBias = bias;
  settings.shadowMapSize = mapSize;
  settings.shadowDepthClamp = depthClamp;
  ImageRgba shadowed = renderer.renderToImage(reduced, settings).image;
  ShadowErrors errors;
  for (size_t p = 0; p < truth.pixels.size(); ++p) {
    Pixel pixel = truth.pixels[p];
    float direct = luminance(unshadowed, p);
    if (pixel == Pixel::Ignored || direct <= 1e-4f) continue;
    float drawn = luminance(shadowed, p);
    bool drawnShadowed = drawn < 0.5f * direct;
    if (pixel != Pixel::Lit) {
      ++errors.shadowed;
      errors.leaked += drawnShadowed ? 0 : 1;
    }
    if (pixel == Pixel::Shadowed) continue;
    if (pixel == Pixel::Lit) {
      ++errors.lit;
      errors.acne += drawnShadowed ? 1 : 0;
      errors.dimmed += drawn < 0.98f * direct ? 1 : 0;
    } else {
      ++errors.contact;
      errors.peterPanning += drawnShadowed ? 0 : 1;
    }
  }
  return errors;
}

std::vector<BiasStudyRow> runBiasStudy(Renderer& renderer, const Scene& scene,
                                       const std::vector<float>& values, ShadowMethod method,
                                       uint32_t mapSize, uint32_t width, uint32_t height) {
  std::vector<BiasStudyRow> rows;
  for (uint32_t light = 0; light < scene.lights.size(); ++light) {
    if (!scene.lights[light].shadows) continue;
    ShadowTruth truth = traceShadowTruth(scene, light, width, height);
    std::string lightKind(nameOf(kLightTypeNames, scene.lights[light].type));
    for (const char* kind : {"constant", "slope", "normal-offset", "default-scaled"})
      for (float value : values) {
        ShadowBias bias{0.0f, 0.0f, 0.0f};
        std::string name = kind;
        if (name == "constant") bias.constant = value;
        if (name == "slope") bias.slope = value;
        if (name == "normal-offset") bias.normalOffset = value;
        if (name == "default-scaled") {
          ShadowBias standard;
          bias = {standard.constant * value, standard.slope * value, standard.normalOffset * value};
        }
        rows.push_back({lightKind, name, value,
                        measureShadowErrors(renderer, scene, light, truth, method, bias, mapSize)});
      }
  }
  return rows;
}

std::string biasStudyCsv(const std::vector<BiasStudyRow>& rows) {
  std::ostringstream csv;
  csv << "light,bias_kind,value_texels,lit_pixels,acne_pixels,acne_percent,contact_pixels,"
         "peter_panning_pixels,peter_panning_percent\n";
  for (const BiasStudyRow& row : rows)
    csv << row.lightKind << ',' << row.biasKind << ',' << row.value << ',' << row.errors.lit << ','
        << row.errors.acne << ',' << 100.0 * row.errors.acneFraction() << ',' << row.errors.contact
        << ',' << row.errors.peterPanning << ',' << 100.0 * row.errors.peterPanningFraction()
        << '\n';
  return csv.str();
}

ImageU8 biasStudyChart(const std::vector<BiasStudyRow>& rows) {
  std::vector<Chart> charts;
  std::vector<std::string> lightKinds;
  for (const BiasStudyRow& row : rows)
    if (std::find(lightKinds.begin(), lightKinds.end(), row.lightKind) == lightKinds.end())
      lightKinds.push_back(row.lightKind);
  for (const std::string& lightKind : lightKinds)
    for (bool acne : {true, false}) {
      Chart chart;
      chart.title = lightKind + " light: " + (acne ? "acne" : "peter-panning");
      chart.subtitle = acne ? "% of truly lit pixels drawn shadowed"
                            : "% of truly shadowed pixels near contact drawn lit";
      chart.x.label = "bias in texels (default-scaled: x default)";
      chart.y.label = "percent";
      // The sweep doubles the bias from 0.25 (and starts at 0): its values
      // evenly spaced by their rank, labelled with the value, so the steps
      // below one texel, where acne goes, get as much room as the rest.
      std::vector<float> values;
      for (const BiasStudyRow& row : rows)
        if (row.lightKind == lightKind &&
            std::find(values.begin(), values.end(), row.value) == values.end())
          values.push_back(row.value);
      std::sort(values.begin(), values.end());
      auto rank = [&](float value) {
        return double(std::lower_bound(values.begin(), values.end(), value) - values.begin());
      };
      for (float value : values) {
        char label[16];
        std::snprintf(label, sizeof label, "%g", double(value));
        chart.x.ticks.push_back({rank(value), label});
      }
      std::vector<std::string> kinds;
      for (const BiasStudyRow& row : rows)
        if (row.lightKind == lightKind &&
            std::find(kinds.begin(), kinds.end(), row.biasKind) == kinds.end())
          kinds.push_back(row.biasKind);
      for (size_t k = 0; k < kinds.size(); ++k) {
        ChartSeries series{kinds[k], chartColor(k), {}, true};
        for (const BiasStudyRow& row : rows)
          if (row.lightKind == lightKind && row.biasKind == kinds[k])
            series.points.push_back(
                {rank(row.value),
                 100.0 * (acne ? row.errors.acneFraction() : row.errors.peterPanningFraction()),
                 ""});
        chart.series.push_back(series);
      }
      charts.push_back(chart);
    }
  return drawChartRow(charts, 560, 340);
}

}  // namespace shadelab
