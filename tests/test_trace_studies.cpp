// The headline numbers of the tracer's studies (`shadelab study acne`,
// `study tir`), asserted with the measurement code the studies run.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/trace/raytracer.h"
#include "measure/acne.h"
#include "measure/tir.h"

namespace shadelab {
namespace {

// Without the offset 85% of the floor's and sphere's lit pixels are shadowed
// by their own surface; at the default 1e-4 none, and no shadow leaks.
TEST(AcneStudy, ShadowAcneWithoutEpsilonAndNoneWithIt) {
  const Scene scene = acneScene();
  const AcneMeasurement without = measureAcne(scene, 0.0f, 160, 90);
  const AcneMeasurement with = measureAcne(scene, TraceSettings{}.epsilon, 160, 90);
  std::printf("shadow acne: %.1f%% of %llu lit pixels with epsilon 0, %.2f%% with %g\n",
              100.0 * without.acneFraction(), (unsigned long long)without.litPixels,
              100.0 * with.acneFraction(), TraceSettings{}.epsilon);
  EXPECT_GT(without.litPixels, 160u * 90u / 4) << "the test must look at many lit pixels";
  EXPECT_GT(without.acneFraction(), 0.10);
  EXPECT_LT(with.acneFraction(), 0.001);
  EXPECT_GT(with.shadowedPixels, 100u);
  EXPECT_LT(with.leakFraction(), 0.001);
}

// Too large an offset starts shadow rays past the sphere: its shadow leaks.
TEST(AcneStudy, TooLargeAnEpsilonLeaksLightIntoShadow) {
  const AcneMeasurement large = measureAcne(acneScene(), 0.5f, 160, 90);
  std::printf("epsilon 0.5: %.1f%% of %llu shadowed pixels lit\n", 100.0 * large.leakFraction(),
              (unsigned long long)large.shadowedPixels);
  EXPECT_GT(large.leakFraction(), 0.2);
}

// The traced critical angle is asin(1 / ior) to 1e-4 degrees, past it no
// light leaves, and reflected plus transmitted light is all of it.
TEST(TirStudy, CriticalAngleAndEnergyMatchTheFormulas) {
  for (float ior : {1.2f, 1.33f, 1.5f, 2.0f, 2.42f}) {
    const double traced = tracedCriticalAngle(ior);
    const double formula = glm::degrees(std::asin(1.0 / double(ior)));
    std::printf("ior %g: critical angle traced %.5f, asin(1/ior) %.5f\n", ior, traced, formula);
    EXPECT_NEAR(traced, formula, 1e-4) << ior;
    for (double angle : {0.0, 0.5 * formula, formula - 0.5, formula + 0.5, 89.0}) {
      const TirSample sample = measureInterface(ior, angle);
      EXPECT_NEAR(sample.transmitted + sample.reflected, 1.0, 1e-5) << ior << " " << angle;
      EXPECT_EQ(sample.totalInternalReflection, angle > formula) << ior << " " << angle;
      EXPECT_NEAR(sample.transmitted, 1.0 - schlickReflectance(ior, angle), 1e-5)
          << ior << " " << angle;
    }
  }
}

// The exact Fresnel reflectance at normal incidence is F0, where Schlick is
// exact too; the twin: at 0.9 of the critical angle they differ by 0.018
// for ior 1.5, far beyond the 1e-5 above, so it would notice the other formula.
TEST(TirStudy, SchlickAndExactFresnelAgreeHeadOnOnly) {
  EXPECT_NEAR(exactReflectance(1.5, 0.0), 0.04, 1e-12);
  EXPECT_NEAR(schlickReflectance(1.5, 0.0), 0.04, 1e-12);
  const double angle = 0.9 * glm::degrees(std::asin(1.0 / 1.5));
  EXPECT_GT(std::abs(exactReflectance(1.5, angle) - schlickReflectance(1.5, angle)), 0.01);
}

}  // namespace
}  // namespace shadelab
