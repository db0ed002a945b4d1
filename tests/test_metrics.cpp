// Image metrics, sRGB transfer functions and statistics against hand-worked numbers.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/metrics.h"
#include "core/stats.h"

namespace shadelab {
namespace {

ImageU8 filled(uint32_t w, uint32_t h, glm::u8vec4 color) {
  ImageU8 image(w, h);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) image.set(x, y, color);
  return image;
}

TEST(Metrics, IdenticalImagesHaveZeroError) {
  ImageU8 a = filled(8, 4, {10, 20, 30, 255});
  ImageDifference d = compareImages(a, a);
  EXPECT_EQ(d.rmse, 0.0);
  EXPECT_TRUE(std::isinf(d.psnr));
  EXPECT_EQ(d.maxDifference, 0);
  EXPECT_EQ(d.pixelsOverThreshold, 0u);
}

TEST(Metrics, ConstantOffsetGivesThatRmse) {
  ImageDifference d = compareImages(filled(8, 4, {10, 20, 30, 255}), filled(8, 4, {20, 30, 40, 0}));
  EXPECT_DOUBLE_EQ(d.rmse, 10.0);  // alpha is ignored
  EXPECT_NEAR(d.psnr, 20.0 * std::log10(25.5), 1e-9);
  EXPECT_EQ(d.maxDifference, 10);
  EXPECT_EQ(d.pixelsOverThreshold, 32u);
}

TEST(Metrics, OnePixelChangedCountsOnce) {
  ImageU8 a = filled(10, 10, {0, 0, 0, 255});
  ImageU8 b = a;
  b.set(3, 7, {0, 30, 0, 255});
  ImageDifference d = compareImages(a, b, 4);
  EXPECT_EQ(d.pixelsOverThreshold, 1u);
  EXPECT_DOUBLE_EQ(d.fractionOverThreshold, 0.01);
  EXPECT_NEAR(d.rmse, std::sqrt(900.0 / 300.0), 1e-12);
}

TEST(Metrics, ToleranceChecksBothPsnrAndFraction) {
  ImageDifference d;
  d.psnr = 45.0, d.fractionOverThreshold = 0.001;
  EXPECT_TRUE(withinTolerance(d, {40.0, 4, 0.005}));
  d.psnr = 39.0;
  EXPECT_FALSE(withinTolerance(d, {40.0, 4, 0.005}));
  d.psnr = 45.0, d.fractionOverThreshold = 0.01;
  EXPECT_FALSE(withinTolerance(d, {40.0, 4, 0.005}));
}

TEST(Metrics, SizeMismatchThrows) {
  EXPECT_THROW(compareImages(ImageU8(2, 2), ImageU8(2, 3)), std::invalid_argument);
}

TEST(Metrics, HeatmapIsBlackWhereEqualAndBrightWhereDifferent) {
  ImageU8 a = filled(4, 1, {100, 100, 100, 255});
  ImageU8 b = a;
  b.set(2, 0, {200, 100, 100, 255});
  ImageU8 heat = differenceHeatmap(a, b, 8.0f);
  EXPECT_EQ(heat.at(0, 0), glm::u8vec4(0, 0, 0, 255));
  EXPECT_EQ(heat.at(2, 0), glm::u8vec4(255, 255, 255, 255));  // 100 * 8 saturates
}

TEST(Srgb, TransferFunctionMatchesTheStandard) {
  EXPECT_FLOAT_EQ(linearToSrgb(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(linearToSrgb(1.0f), 1.0f);
  EXPECT_NEAR(linearToSrgb(0.0031308f), 0.04045f, 1e-5f);  // the two pieces meet
  EXPECT_NEAR(linearToSrgb(0.5f), 0.735357f, 1e-5f);
  EXPECT_NEAR(linearToSrgb(0.18f), 0.461356f, 1e-5f);
  EXPECT_EQ(linearToSrgb(std::nanf("")), 0.0f);
  for (int i = 0; i <= 255; ++i) {
    float encoded = i / 255.0f;
    EXPECT_NEAR(linearToSrgb(srgbToLinear(encoded)), encoded, 1e-5f) << i;
  }
}

TEST(Srgb, EncodeRoundsAndClamps) {
  ImageRgba linear(3, 1);
  linear.set(0, 0, {0.5f, -1.0f, 7.0f, 0.5f});
  ImageU8 encoded = encodeSrgb8(linear);
  EXPECT_EQ(encoded.at(0, 0), glm::u8vec4(188, 0, 255, 128));  // 0.735357 * 255 = 187.5 -> 188
}

TEST(Stats, PercentilesInterpolateBetweenRanks) {
  std::vector<double> samples{5, 1, 4, 2, 3};
  EXPECT_DOUBLE_EQ(median(samples), 3.0);
  EXPECT_DOUBLE_EQ(percentile(samples, 0), 1.0);
  EXPECT_DOUBLE_EQ(percentile(samples, 100), 5.0);
  EXPECT_DOUBLE_EQ(percentile(samples, 95), 4.8);
  EXPECT_DOUBLE_EQ(median({1.0, 2.0}), 1.5);
  EXPECT_DOUBLE_EQ(median({}), 0.0);
}

}  // namespace
}  // namespace shadelab
