// Depth precision measured: the zfight scene's two planes 0.05 apart, the
// fraction of their pixels where the farther one wins, per depth mode,
// projection and near plane. Figures are printed so a failing run shows how
// far off it was (figures below measured at 320x180 on lavapipe).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/vulkan/depth.h"
#include "gpu_test_support.h"
#include "measure/zfight.h"

namespace shadelab::test {
namespace {

constexpr uint32_t kWidth = 320, kHeight = 180;

using DepthPrecision = GpuTest;

ZFightMeasurement measure(Renderer& renderer, DepthMode depth, Projection projection, float near) {
  ZFightMeasurement m = measureZFight(renderer, depth, projection, near, kWidth, kHeight);
  std::printf("%s %s near %g: %.2f%% wrong of %llu pixels\n",
              projection == Projection::Orthographic ? "orthographic" : "perspective",
              std::string(depthModeName(depth)).c_str(), near, 100.0 * m.wrongFraction(),
              static_cast<unsigned long long>(m.coveredPixels));
  return m;
}

// Perspective at near 0.1: D16 cannot separate the planes (95.9% wrong),
// reversed-Z D32F separates every pixel (0%).
TEST_F(DepthPrecision, ReversedZFixesWhatD16CannotResolve) {
  ZFightMeasurement d16 = measure(renderer(), DepthMode::D16, Projection::Perspective, 0.1f);
  ZFightMeasurement reversed =
      measure(renderer(), DepthMode::ReversedZ, Projection::Perspective, 0.1f);
  // The planes cover most of the frame either way.
  EXPECT_GT(d16.coveredPixels, uint64_t(kWidth * kHeight / 2));
  EXPECT_EQ(reversed.coveredPixels, d16.coveredPixels);
  EXPECT_GT(d16.wrongFraction(), 0.8);
  EXPECT_LT(reversed.wrongFraction(), 0.001);
}

// Near 0.001 defeats 24-bit precision too: D24 and standard D32F lose 92.3%
// (float has 24 bits of mantissa, and standard depth crowds near 1), while
// reversed-Z puts float's dense range near 0 at the far end: 0%.
TEST_F(DepthPrecision, ReversedZHoldsWhereStandardFloatDepthFails) {
  ZFightMeasurement d24 = measure(renderer(), DepthMode::D24, Projection::Perspective, 0.001f);
  ZFightMeasurement d32 = measure(renderer(), DepthMode::D32F, Projection::Perspective, 0.001f);
  ZFightMeasurement reversed =
      measure(renderer(), DepthMode::ReversedZ, Projection::Perspective, 0.001f);
  EXPECT_GT(d24.wrongFraction(), 0.5);
  EXPECT_GT(d32.wrongFraction(), 0.5);
  EXPECT_LT(reversed.wrongFraction(), 0.001);
}

// Pushing the near plane out is the classic fix: D16 loses 95.9%, 51.8%, 0%
// at near 0.1, 1, 10.
TEST_F(DepthPrecision, D16RecoversAsTheNearPlaneMovesOut) {
  double previous = 1.1;
  for (float near : {0.1f, 1.0f, 10.0f}) {
    double fraction =
        measure(renderer(), DepthMode::D16, Projection::Perspective, near).wrongFraction();
    EXPECT_LT(fraction, previous) << "near " << near;
    previous = fraction;
  }
  EXPECT_LT(previous, 0.001);
}

// Orthographic depth is linear in distance, so its precision is (far - near)
// spread evenly: the near plane hardly matters (D16 loses 35.0% at near
// 0.001 and 35.6% at 10) and 24 bits or float are enough everywhere.
TEST_F(DepthPrecision, OrthographicPrecisionIgnoresTheNearPlane) {
  double atSmallNear =
      measure(renderer(), DepthMode::D16, Projection::Orthographic, 0.001f).wrongFraction();
  double atLargeNear =
      measure(renderer(), DepthMode::D16, Projection::Orthographic, 10.0f).wrongFraction();
  EXPECT_GT(atSmallNear, 0.2);
  EXPECT_LT(std::abs(atSmallNear - atLargeNear), 0.1);
  for (DepthMode depth : {DepthMode::D24, DepthMode::D32F, DepthMode::ReversedZ})
    EXPECT_LT(measure(renderer(), depth, Projection::Orthographic, 0.001f).wrongFraction(), 0.001);
}

// The seed's claim, measured by moving the planes away (study zfight's
// distance sweep, near plane 1): in perspective D16 loses more of the planes
// the farther they are, since depth steps grow with z^2 / near; in
// orthographic the steps are (far - near) / 2^16 at any distance, so the
// loss stays in a band.
TEST_F(DepthPrecision, PerspectiveZFightingGrowsWithDistanceOrthographicDoesNot) {
  std::vector<double> perspective, orthographic;
  for (float scale : {0.25f, 0.5f, 1.0f, 2.0f, 4.0f}) {
    perspective.push_back(measureZFight(renderer(), DepthMode::D16, Projection::Perspective, 1.0f,
                                        kWidth, kHeight, scale)
                              .wrongFraction());
    orthographic.push_back(measureZFight(renderer(), DepthMode::D16, Projection::Orthographic, 1.0f,
                                         kWidth, kHeight, scale)
                               .wrongFraction());
    std::printf("distance %.1f: perspective %.2f%%, orthographic %.2f%%\n", zfightDistance(scale),
                100.0 * perspective.back(), 100.0 * orthographic.back());
  }
  for (size_t i = 1; i < perspective.size(); ++i)
    EXPECT_GE(perspective[i], perspective[i - 1]) << "step " << i;
  EXPECT_GT(perspective.back() - perspective.front(), 0.5);
  auto [low, high] = std::minmax_element(orthographic.begin(), orthographic.end());
  EXPECT_GT(*low, 0.2) << "D16 in orthographic fights at every distance";
  EXPECT_LT(*high - *low, 0.1);
}

// depthResolution, the prediction behind render's warning, against the
// measurement: on the zfight scene the planes' depths differ by the gap over
// the sine of the line of sight's elevation. Where the predicted resolution
// is 4x that difference the planes fight over most pixels; where it is a
// quarter of it they do not fight at all. (Settings in between are not
// asserted: D16 at near 1 predicts 2.1x and loses 51.8%.)
TEST_F(DepthPrecision, PredictedResolutionAgreesWithMeasuredZFighting) {
  const Camera camera = builtinScene("zfight").camera;
  const double distance = zfightDistance(1.0f);
  const double depthGap = kZFightGap * distance / double(camera.eye.y - camera.at.y);
  struct Setting {
    DepthMode depth;
    float near;
  };
  int asserted = 0;
  for (Setting s : {Setting{DepthMode::D16, 0.1f}, Setting{DepthMode::D16, 10.0f},
                    Setting{DepthMode::D24, 0.001f}, Setting{DepthMode::D32F, 0.001f},
                    Setting{DepthMode::D32F, 0.1f}, Setting{DepthMode::ReversedZ, 0.001f}}) {
    Camera withNear = camera;
    withNear.near = s.near;
    double predicted = depthResolution(withNear, s.depth, distance);
    double wrong = measure(renderer(), s.depth, Projection::Perspective, s.near).wrongFraction();
    std::printf("  predicted resolution %.4g against a depth gap of %.4g\n", predicted, depthGap);
    if (predicted > 4.0 * depthGap) {
      EXPECT_GT(wrong, 0.5) << depthModeName(s.depth) << " near " << s.near;
      ++asserted;
    } else if (predicted < 0.25 * depthGap) {
      EXPECT_LT(wrong, 0.001) << depthModeName(s.depth) << " near " << s.near;
      ++asserted;
    }
  }
  EXPECT_EQ(asserted, 6) << "every setting above is clearly on one side";
}

// Where the prediction is infinite (the depth value rounds to the clear
// value) nothing is drawn: the image is the background alone. With
// reversed-Z the same camera draws the scene.
TEST_F(DepthPrecision, DepthRoundingToTheClearValueDrawsNothing) {
  Scene scene = builtinScene("default");
  scene.camera.near = 1e-5f;
  double distance = glm::length(scene.camera.at - scene.camera.eye);
  EXPECT_TRUE(std::isinf(depthResolution(scene.camera, DepthMode::D16, distance)));
  EXPECT_TRUE(std::isfinite(depthResolution(scene.camera, DepthMode::ReversedZ, distance)));
  RenderSettings settings{kWidth, kHeight};
  settings.depth = DepthMode::D16;
  ImageU8 blank = render(scene, settings);
  Scene empty = scene;
  empty.objects.clear();
  EXPECT_TRUE(matchesImage(render(empty, settings), blank));
  settings.depth = DepthMode::ReversedZ;
  EXPECT_FALSE(matchesImage(render(empty, settings), render(scene, settings)));
}

// Where precision is ample every depth mode draws the same image.
TEST_F(DepthPrecision, EveryDepthModeDrawsTheDefaultSceneAlike) {
  Scene scene = builtinScene("default");
  RenderSettings settings{kWidth, kHeight};
  ImageU8 standard = render(scene, settings);
  for (DepthMode depth : {DepthMode::D16, DepthMode::D24, DepthMode::ReversedZ}) {
    settings.depth = depth;
    EXPECT_TRUE(matchesImage(standard, render(scene, settings))) << depthModeName(depth);
  }
}

// The twin: where D16 z-fights, its image is rejected by the same comparison.
TEST_F(DepthPrecision, ComparisonRejectsZFighting) {
  Scene scene = zfightScene(Projection::Perspective, 0.1f);
  RenderSettings settings{kWidth, kHeight, ShadingModel::Unlit};
  settings.frontToBack = false;  // the farther plane first: sorted, ties would go to the nearer
  settings.depth = DepthMode::ReversedZ;
  ImageU8 correct = render(scene, settings);
  settings.depth = DepthMode::D16;
  EXPECT_FALSE(matchesImage(correct, render(scene, settings)));
}

}  // namespace
}  // namespace shadelab::test
