// Image metrics, sRGB transfer functions and statistics against hand-worked numbers.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <glm/gtc/packing.hpp>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/base/stats.h"
#include "core/metrics/metrics.h"

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

// A deterministic textured image: a smooth colour gradient with a sharp-edged
// checker and fine stripes, so blur and shifts change its structure.
ImageU8 pattern(uint32_t w = 96, uint32_t h = 64) {
  ImageU8 image(w, h);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const bool checker = ((x / 8) + (y / 8)) % 2 == 0;
      const bool stripe = (x % 3) == 0;
      image.set(
          x, y,
          {uint8_t(checker ? 200 : 40), uint8_t(stripe ? 180 : 60 + y), uint8_t(30 + 2 * x), 255});
    }
  return image;
}

ImageU8 offset(const ImageU8& image, int delta) {
  ImageU8 result = image;
  for (size_t i = 0; i < result.pixels.size(); ++i)
    if (i % 4 != 3) result.pixels[i] = uint8_t(std::clamp(int(result.pixels[i]) + delta, 0, 255));
  return result;
}

// A box blur of the given radius (edge pixels repeat).
ImageU8 blurred(const ImageU8& image, int radius) {
  ImageU8 result = image;
  const int w = int(image.width), h = int(image.height);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        int sum = 0, count = 0;
        for (int dy = -radius; dy <= radius; ++dy)
          for (int dx = -radius; dx <= radius; ++dx, ++count)
            sum += image.at(uint32_t(std::clamp(x + dx, 0, w - 1)),
                            uint32_t(std::clamp(y + dy, 0, h - 1)))[c];
        result.pixels[(size_t(y) * w + x) * 4 + c] = uint8_t((sum + count / 2) / count);
      }
  return result;
}

ImageU8 shiftedRight(const ImageU8& image) {
  ImageU8 result = image;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 1; x < image.width; ++x) result.set(x, y, image.at(x - 1, y));
  return result;
}

void expectInUnitInterval(const MetricMap& map) {
  for (float v : map.values) {
    ASSERT_TRUE(std::isfinite(v));
    ASSERT_GE(v, 0.0f);
    ASSERT_LE(v, 1.0f);
  }
}

TEST(Ssim, IdenticalImagesScoreOne) {
  const ImageU8 a = pattern();
  const MetricMap map = structuralSimilarity(a, a);
  EXPECT_EQ(map.mean, 1.0);
  for (float v : map.values) EXPECT_EQ(v, 1.0f);
}

TEST(Ssim, ConstantOffsetLowersOnlyTheLuminanceTerm) {
  const ImageU8 a = pattern();
  const double small = structuralSimilarity(a, offset(a, 10)).mean;
  const double large = structuralSimilarity(a, offset(a, 40)).mean;
  EXPECT_LT(small, 1.0);
  EXPECT_GT(small, 0.95);  // structure and contrast are kept (but for clipping)
  EXPECT_LT(large, small);
}

TEST(Ssim, BlurAndShiftLowerItMonotonically) {
  const ImageU8 a = pattern();
  const double blur1 = structuralSimilarity(a, blurred(a, 1)).mean;
  const double blur2 = structuralSimilarity(a, blurred(a, 2)).mean;
  const double shift = structuralSimilarity(a, shiftedRight(a)).mean;
  std::printf("SSIM: blur r1 %.4f, blur r2 %.4f, one-pixel shift %.4f\n", blur1, blur2, shift);
  EXPECT_LT(blur1, 0.9);
  EXPECT_LT(blur2, blur1);
  EXPECT_LT(shift, 0.9);
  EXPECT_THROW(structuralSimilarity(ImageU8(4, 4), ImageU8(4, 5)), std::invalid_argument);
}

TEST(Flip, IdenticalImagesScoreZero) {
  const ImageU8 a = pattern();
  const MetricMap map = flipError(a, a);
  EXPECT_EQ(map.mean, 0.0);
  for (float v : map.values) EXPECT_EQ(v, 0.0f);
}

TEST(Flip, ConstantOffsetGrowsWithTheOffset) {
  const ImageU8 a = pattern();
  double previous = 0.0;
  for (int delta : {2, 8, 24, 64}) {
    const MetricMap map = flipError(a, offset(a, delta));
    expectInUnitInterval(map);
    EXPECT_GT(map.mean, previous) << delta;
    previous = map.mean;
  }
}

TEST(Flip, BlurAndShiftAreSeenWhereTheEdgesAre) {
  const ImageU8 a = pattern();
  const MetricMap blur1 = flipError(a, blurred(a, 1));
  const MetricMap blur2 = flipError(a, blurred(a, 2));
  const MetricMap shift = flipError(a, shiftedRight(a));
  std::printf("FLIP: blur r1 %.4f, blur r2 %.4f, one-pixel shift %.4f\n", blur1.mean, blur2.mean,
              shift.mean);
  expectInUnitInterval(blur2);
  expectInUnitInterval(shift);
  EXPECT_GT(blur1.mean, 0.01);
  EXPECT_GT(blur2.mean, blur1.mean);
  EXPECT_GT(shift.mean, 0.01);
  // A shift changes the checker's vertical edges (x = 8, 16, ...), not the
  // inside of its squares, where only the stripes move.
  EXPECT_GT(shift.at(8, 4), shift.at(4, 4) + 0.05f);
}

TEST(Flip, OppositesScoreNearOneAndStayInRange) {
  const MetricMap map =
      flipError(filled(32, 32, {0, 0, 0, 255}), filled(32, 32, {255, 255, 255, 255}));
  expectInUnitInterval(map);
  EXPECT_GT(map.mean, 0.9);
  // Green against blue is the metric's largest colour difference: 1.
  EXPECT_NEAR(flipError(filled(32, 32, {0, 255, 0, 255}), filled(32, 32, {0, 0, 255, 255})).mean,
              1.0, 1e-3);
  EXPECT_THROW(flipError(ImageU8(4, 4), ImageU8(5, 4)), std::invalid_argument);
}

TEST(Flip, ViewingDistanceMatters) {
  // Seen from further away (more pixels per degree) a one-pixel shift of
  // fine detail is harder to see.
  const ImageU8 a = pattern(), b = shiftedRight(pattern());
  EXPECT_LT(flipError(a, b, 200.0).mean, flipError(a, b, 67.0).mean);
}

TEST(Flip, MagmaHeatmapRunsFromBlackToPaleYellow) {
  MetricMap map{5, 1, {0.0f, 0.25f, 0.5f, 0.75f, 1.0f}, 0.5};
  const ImageU8 heat = magmaHeatmap(map);
  EXPECT_EQ(heat.at(0, 0), glm::u8vec4(0, 0, 4, 255));
  EXPECT_EQ(heat.at(4, 0), glm::u8vec4(252, 253, 191, 255));
  float previous = -1.0f;
  for (uint32_t x = 0; x < 5; ++x) {  // lightness rises along the ramp
    const glm::u8vec4 c = heat.at(x, 0);
    const float luma = 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
    EXPECT_GT(luma, previous) << x;
    previous = luma;
  }
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

// linearToSrgb8 is a table built from the transfer function; it must give
// the same code as quantising linearToSrgb for every float. Checked here: a
// window of bit patterns around each of the 255 steps, a stride through all
// of [0, 1], and the values outside it.
TEST(Srgb, TableEncodingEqualsTheTransferFunction) {
  auto reference = [](float linear) {
    return uint8_t(std::lround(std::clamp(linearToSrgb(linear), 0.0f, 1.0f) * 255.0f));
  };
  uint32_t one = std::bit_cast<uint32_t>(1.0f);
  size_t checked = 0, mismatches = 0;
  auto check = [&](uint32_t bits) {
    float linear = std::bit_cast<float>(bits);
    ++checked;
    if (linearToSrgb8(linear) != reference(linear) && ++mismatches <= 5)
      ADD_FAILURE() << "bits " << bits << " (" << linear << "): table "
                    << int(linearToSrgb8(linear)) << ", function " << int(reference(linear));
  };
  for (uint32_t bits = 0; bits <= one; bits += 97) check(bits);
  // The steps: where the code first reaches each value, found by bisection
  // on the function, then 4096 patterns either side.
  for (int code = 1; code <= 255; ++code) {
    uint32_t lower = 0, upper = one;  // reference(lower) < code <= reference(upper)
    while (upper - lower > 1) {
      uint32_t middle = lower + (upper - lower) / 2;
      (reference(std::bit_cast<float>(middle)) >= code ? upper : lower) = middle;
    }
    for (uint32_t bits = upper - std::min(upper, 4096u); bits <= std::min(one, upper + 4096);
         ++bits)
      check(bits);
  }
  EXPECT_EQ(mismatches, 0u) << "of " << checked;
  EXPECT_GT(checked, 10'000'000u);
  for (float linear : {-0.0f, -1.0f, 1.5f, 1e30f, std::numeric_limits<float>::infinity(),
                       -std::numeric_limits<float>::infinity(), std::nanf(""),
                       std::numeric_limits<float>::denorm_min()})
    EXPECT_EQ(linearToSrgb8(linear), reference(linear)) << linear;
  EXPECT_EQ(linearToSrgb8(0.5f), 188);  // 0.7354 * 255 = 187.5
}

TEST(Srgb, EncodeRoundsAndClamps) {
  ImageRgba linear(3, 1);
  linear.set(0, 0, {0.5f, -1.0f, 7.0f, 0.5f});
  ImageU8 encoded = encodeSrgb8(linear);
  EXPECT_EQ(encoded.at(0, 0), glm::u8vec4(188, 0, 255, 128));  // 0.735357 * 255 = 187.5 -> 188
}

// Every half float, as each of the four channels: the half path gives the
// codes the float path gives (the render command writes PNGs through it).
TEST(Srgb, HalfEncodingEqualsTheFloatEncodingForEveryHalf) {
  const uint32_t width = 256, height = 256;  // 65,536 pixels, one half each
  std::vector<uint16_t> halves(size_t(width) * height * 4);
  ImageRgba floats(width, height);
  for (uint32_t bits = 0; bits < 65536; ++bits) {
    // Channel c of pixel p holds half (bits + c * 16,411) mod 2^16: every
    // channel meets every half once.
    for (uint32_t channel = 0; channel < 4; ++channel) {
      uint16_t half = uint16_t(bits + channel * 16411u);
      halves[size_t(bits) * 4 + channel] = half;
      floats.pixels[size_t(bits) * 4 + channel] = glm::unpackHalf1x16(half);
    }
  }
  ImageU8 fromHalves = encodeSrgb8FromHalf(halves.data(), width, height);
  ImageU8 fromFloats = encodeSrgb8(floats);
  size_t mismatches = 0;
  for (size_t i = 0; i < fromFloats.pixels.size(); ++i)
    if (fromHalves.pixels[i] != fromFloats.pixels[i] && ++mismatches <= 5)
      ADD_FAILURE() << "half " << halves[i] << " channel " << i % 4 << ": "
                    << int(fromHalves.pixels[i]) << " against " << int(fromFloats.pixels[i]);
  EXPECT_EQ(mismatches, 0u);
  // A wrong image is caught: one code off in one pixel.
  ++fromHalves.pixels[4 * 1234 + 1];
  EXPECT_NE(fromHalves.pixels, fromFloats.pixels);
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

TEST(Stats, MeanCountsTheTailTheMedianIgnores) {
  // glmark2's FPS is frames over elapsed time: a mean, which slow frames raise.
  std::vector<double> samples{1.0, 1.0, 1.0, 9.0};
  EXPECT_DOUBLE_EQ(median(samples), 1.0);
  EXPECT_DOUBLE_EQ(mean(samples), 3.0);
  EXPECT_DOUBLE_EQ(mean({}), 0.0);
}

}  // namespace
}  // namespace shadelab
