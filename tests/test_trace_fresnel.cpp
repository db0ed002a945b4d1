// Issue 16's check of the traced glass against the formula: the committed
// scene tests/data/glass_sphere.json (a clear ball, kt 1, ior 1.5, before a
// red emitter only refracted rays reach) traced with and without the Fresnel
// term. Through a sphere a ray enters and leaves at the same angle, so each
// glass pixel must be dimmed by (1 - F_in)(1 - F_out), Schlick's F written
// out here, not taken from the tracer. And shadows through glass: k_shadow
// measured on a floor under a clear ball.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/scene/scene_loader.h"
#include "core/trace/raytracer.h"

namespace shadelab {
namespace {

constexpr float kIor = 1.5f;

// Schlick: F = F0 + (1 - F0) (1 - cos)^5, F0 = ((1 - n) / (1 + n))^2, cos on
// the air side.
double schlick(double cosAir) {
  const double f0 = std::pow((1.0 - kIor) / (1.0 + kIor), 2.0);
  return f0 + (1.0 - f0) * std::pow(1.0 - cosAir, 5.0);
}

struct GlassRenders {
  Scene scene;
  ImageRgba fresnel, plain;  // with and without the Fresnel term
};

GlassRenders renderGlass(uint32_t size) {
  GlassRenders renders{loadScene(SHADELAB_TEST_DATA_DIR "/glass_sphere.json"), {}, {}};
  RayTracer tracer(renders.scene);
  TraceSettings settings;
  settings.width = settings.height = size;
  settings.samplesPerPixel = 1;  // the pixel centre, whose angle the test computes
  renders.fresnel = tracer.render(settings).image;
  settings.fresnel = false;
  renders.plain = tracer.render(settings).image;
  return renders;
}

// The incidence angle (degrees) at each pixel's centre ray on the ball, or
// -1 where the ray misses it.
std::vector<double> incidenceAngles(const Scene& scene, uint32_t size) {
  RayTracer tracer(scene);
  CameraRays camera(scene.camera, size, size);
  std::vector<double> angles(size_t(size) * size, -1.0);
  for (uint32_t y = 0; y < size; ++y)
    for (uint32_t x = 0; x < size; ++x) {
      Ray ray = camera.through(float(x) + 0.5f, float(y) + 0.5f);
      std::optional<SurfaceHit> hit = tracer.intersect(ray, 0.0f, 1.0f);
      if (!hit || scene.objects[hit->object].name != "glass") continue;
      double cosine = std::abs(glm::dot(glm::normalize(ray.direction), hit->shadingNormal));
      angles[size_t(y) * size + x] = glm::degrees(std::acos(std::min(1.0, cosine)));
    }
  return angles;
}

// Per 15-degree bin of incidence up to 75 (past that the refracted rays
// miss the emitter): the traced ratio sum(with) / sum(without) of the red
// channel (only the emitter behind gives red) and the formula's mean.
struct BinRatio {
  int pixels = 0;
  double traced = 0.0;
  double formula = 0.0;
};

std::vector<BinRatio> ratiosByAngle(const ImageRgba& with, const ImageRgba& without,
                                    const std::vector<double>& angles) {
  constexpr int kBins = 5;
  std::vector<BinRatio> bins(kBins);
  std::vector<double> withSum(kBins), withoutSum(kBins);
  for (size_t p = 0; p < angles.size(); ++p) {
    if (angles[p] < 0.0) continue;
    const float plain = without.pixels[p * 4];
    if (plain < 0.5f) continue;  // the refracted path missed the emitter
    const int bin = int(angles[p] / 15.0);
    if (bin >= kBins) continue;
    // Leaving the ball the ray meets the surface at the refraction angle
    // inside, which is the entry angle again on the air side.
    const double cosIn = std::cos(glm::radians(angles[p]));
    const double fIn = schlick(cosIn), fOut = schlick(cosIn);
    withSum[bin] += with.pixels[p * 4];
    withoutSum[bin] += plain;
    bins[bin].formula += (1.0 - fIn) * (1.0 - fOut);
    ++bins[bin].pixels;
  }
  for (int bin = 0; bin < kBins; ++bin) {
    bins[bin].traced = withSum[bin] / withoutSum[bin];
    bins[bin].formula /= std::max(1, bins[bin].pixels);
  }
  return bins;
}

TEST(TraceFresnel, GlassDimsByOneMinusFresnelInAndOut) {
  constexpr uint32_t kSize = 200;
  GlassRenders renders = renderGlass(kSize);
  std::vector<BinRatio> bins =
      ratiosByAngle(renders.fresnel, renders.plain, incidenceAngles(renders.scene, kSize));
  for (size_t bin = 0; bin < bins.size(); ++bin) {
    std::printf("incidence %2zu-%2zu deg: %5d pixels, traced ratio %.4f, (1-F_in)(1-F_out) %.4f\n",
                15 * bin, 15 * bin + 15, bins[bin].pixels, bins[bin].traced, bins[bin].formula);
    ASSERT_GT(bins[bin].pixels, 50) << "bin " << bin;
    EXPECT_NEAR(bins[bin].traced / bins[bin].formula, 1.0, 0.02) << "bin " << bin;
  }
}

// The twin: glass traced without Fresnel (ratio 1) is off by more than the
// 2% in every bin, so the check above can fail.
TEST(TraceFresnel, CheckRejectsGlassWithoutFresnel) {
  constexpr uint32_t kSize = 200;
  GlassRenders renders = renderGlass(kSize);
  std::vector<BinRatio> bins =
      ratiosByAngle(renders.plain, renders.plain, incidenceAngles(renders.scene, kSize));
  for (size_t bin = 0; bin < bins.size(); ++bin)
    EXPECT_GT(std::abs(bins[bin].traced / bins[bin].formula - 1.0), 0.02) << "bin " << bin;
}

// At grazing incidence Fresnel reflects most light: the ball's rim mirrors
// the blue emitter behind it, which without Fresnel (kr 0) it cannot.
TEST(TraceFresnel, RimReflectsAtGrazingIncidence) {
  constexpr uint32_t kSize = 200;
  GlassRenders renders = renderGlass(kSize);
  std::vector<double> angles = incidenceAngles(renders.scene, kSize);
  double fresnelBlue = 0.0, plainBlue = 0.0, formula = 0.0;
  int count = 0;
  for (size_t p = 0; p < angles.size(); ++p) {
    if (angles[p] < 80.0) continue;
    fresnelBlue += renders.fresnel.pixels[p * 4 + 2];
    plainBlue += renders.plain.pixels[p * 4 + 2];
    formula += schlick(std::cos(glm::radians(angles[p])));
    ++count;
  }
  ASSERT_GT(count, 100);
  const double emitter = renders.scene.objects[2].material.emissive.b;
  std::printf(
      "rim (incidence >= 80 deg, %d pixels): blue %.4f with Fresnel, %.4f without; "
      "F x emitter %.4f\n",
      count, fresnelBlue / count, plainBlue / count, formula / count * emitter);
  // F times the emitter, to 10%: some refracted paths at the rim reach it too.
  EXPECT_NEAR(fresnelBlue / count, formula / count * emitter, 0.1 * formula / count * emitter);
  EXPECT_LT(plainBlue / count, 0.01);
}

// k_shadow measured on a traced floor: a clear ball (kt 1, ior 1.5, radius 1)
// 1.5 above a diffuse floor, lit straight down. Seen from the side, below the
// ball, each floor point gets the light the straight shadow ray passes:
// (1 - F)^2 with F at the angle the ray meets the ball, so 0.9216 under the
// centre and darker towards the shadow's edge. Without Fresnel a kt 1 ball
// casts no shadow at all (ratio 1).
TEST(TraceFresnel, ClearGlassCastsAShadowOfOneMinusFresnelSquared) {
  Scene scene;
  scene.ambient = glm::vec3(0.0f);
  scene.lights.push_back({LightType::Directional, {}, {0.0f, -1.0f, 0.0f}, glm::vec3(1.0f)});
  ShapeDesc floorShape{ShapeKind::Plane};
  floorShape.size = 20.0f;
  Material floor{glm::vec3(0.0f), glm::vec3(0.8f), glm::vec3(0.0f), 1.0f};
  scene.objects.push_back({"floor", scene.addShape(floorShape), glm::mat4(1.0f), floor});
  Scene unshadowed = scene;
  ShapeDesc ball{ShapeKind::UvSphere};
  ball.radius = 1.0f;
  Material glass{glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f), 1.0f};
  glass.transparency = 1.0f;
  glass.ior = kIor;
  glm::mat4 lifted = glm::mat4(1.0f);
  lifted[3] = glm::vec4(0.0f, 1.5f, 0.0f, 1.0f);
  scene.objects.push_back({"glass", scene.addShape(ball), lifted, glass});
  RayTracer tracer(scene), open(unshadowed);
  TraceSettings settings;
  for (float x : {0.0f, 0.5f, 0.9f}) {
    // A grazing ray from the side that passes under the ball to the floor at (x, 0, 0).
    const Ray ray{{x, 0.2f, 4.0f}, glm::vec3(0.0f, -0.2f, -4.0f)};
    TraceStats stats;
    const float lit = open.traceRay(ray, 2.0f, ray.origin, 0, 1.0f, settings, stats).g;
    const float shadowed = tracer.traceRay(ray, 2.0f, ray.origin, 0, 1.0f, settings, stats).g;
    settings.fresnel = false;
    const float plain = tracer.traceRay(ray, 2.0f, ray.origin, 0, 1.0f, settings, stats).g;
    settings.fresnel = true;
    const double cosine = std::sqrt(1.0 - double(x) * x);  // the light meets the ball at asin(x)
    const double formula = std::pow(1.0 - schlick(cosine), 2.0);
    std::printf(
        "floor at %.1f from the centre line: k_shadow %.4f ((1-F)^2 = %.4f), "
        "without Fresnel %.4f\n",
        x, shadowed / lit, formula, plain / lit);
    EXPECT_NEAR(shadowed / lit, formula, 0.002) << x;
    EXPECT_FLOAT_EQ(plain / lit, 1.0f) << x;
  }
}

}  // namespace
}  // namespace shadelab
