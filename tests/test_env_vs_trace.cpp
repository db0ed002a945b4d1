// Environment mapping against traced reflection on the `env` scene: where
// the traced specular path meets an object (inter- and self-reflection,
// which no environment map holds) the rasterised image is measurably
// further from the reference than where the path escapes (distortion and
// parallax only).
#include <cstdio>

#include "core/metrics/metrics.h"
#include "core/trace/raytracer.h"
#include "core/trace/reflection_regions.h"
#include "gpu_test_support.h"

namespace shadelab::test {
namespace {

using EnvironmentAgainstTrace = GpuTest;

TEST_F(EnvironmentAgainstTrace, ReflectionsThatHitObjectsErrMoreThanEscapingOnes) {
  const Scene scene = builtinScene("env");
  TraceSettings trace;
  trace.width = 240, trace.height = 135, trace.samplesPerPixel = 1;
  const ImageU8 traced = encodeSrgb8(RayTracer(scene).render(trace).image);
  const ImageU8 raster = encodeSrgb8(
      renderer().renderToImage(scene, {trace.width, trace.height, ShadingModel::Phong}).image);
  const ReflectionRegions regions = classifyReflections(scene, trace.width, trace.height);
  const MetricMap flip = flipError(traced, raster);
  const uint64_t hits = regions.count(ReflectionRegion::HitsObject);
  const uint64_t escapes = regions.count(ReflectionRegion::Escapes);
  const double hitting = meanOver(flip, regions, ReflectionRegion::HitsObject);
  const double escaping = meanOver(flip, regions, ReflectionRegion::Escapes);
  std::printf(
      "env, Phong vs trace: mean FLIP %.4f where the reflection hits an object (%llu px), "
      "%.4f where it escapes (%llu px)\n",
      hitting, (unsigned long long)hits, escaping, (unsigned long long)escapes);
  // The three reflective objects cover ~8% of the frame, split about evenly.
  EXPECT_GT(hits, 500u);
  EXPECT_GT(escapes, 500u);
  EXPECT_GT(hitting, 2.0 * escaping);
}

}  // namespace
}  // namespace shadelab::test
