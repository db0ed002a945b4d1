#include "core/metrics/metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "core/metrics/image_filter.h"

namespace shadelab {

ImageDifference compareImages(const ImageU8& a, const ImageU8& b, int threshold) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("compareImages: sizes differ (" + std::to_string(a.width) + "x" +
                                std::to_string(a.height) + " vs " + std::to_string(b.width) + "x" +
                                std::to_string(b.height) + ")");
  ImageDifference result;
  double sumSquares = 0.0;
  size_t pixelCount = size_t(a.width) * a.height;
  for (size_t p = 0; p < pixelCount; ++p) {
    int pixelMax = 0;
    for (int c = 0; c < 3; ++c) {
      int d = std::abs(int(a.pixels[p * 4 + c]) - int(b.pixels[p * 4 + c]));
      sumSquares += double(d) * d;
      pixelMax = std::max(pixelMax, d);
    }
    result.maxDifference = std::max(result.maxDifference, pixelMax);
    if (pixelMax > threshold) ++result.pixelsOverThreshold;
  }
  result.rmse = pixelCount ? std::sqrt(sumSquares / double(pixelCount * 3)) : 0.0;
  result.psnr = result.rmse > 0.0 ? 20.0 * std::log10(255.0 / result.rmse)
                                  : std::numeric_limits<double>::infinity();
  result.fractionOverThreshold = pixelCount ? double(result.pixelsOverThreshold) / pixelCount : 0.0;
  return result;
}

bool withinTolerance(const ImageDifference& difference, const ImageTolerance& tolerance) {
  return difference.psnr >= tolerance.minPsnr &&
         difference.fractionOverThreshold <= tolerance.maxFractionOver;
}

namespace {

Plane lumaOf(const ImageU8& image) {
  Plane luma(image.width, image.height);
  for (size_t p = 0; p < luma.values.size(); ++p) {
    const uint8_t* rgb = &image.pixels[p * 4];
    luma.values[p] = (0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2]) / 255.0f;
  }
  return luma;
}

Plane product(const Plane& a, const Plane& b) {
  Plane result(a.width, a.height);
  for (size_t i = 0; i < a.values.size(); ++i) result.values[i] = a.values[i] * b.values[i];
  return result;
}

}  // namespace

MetricMap structuralSimilarity(const ImageU8& a, const ImageU8& b) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("structuralSimilarity: sizes differ");
  constexpr float c1 = 0.01f * 0.01f, c2 = 0.03f * 0.03f;  // (K L)^2 with L = 1
  const std::vector<float> window = gaussianKernel(1.5f, 5);
  const Plane x = lumaOf(a), y = lumaOf(b);
  const Plane meanX = convolveSeparable(x, window, window);
  const Plane meanY = convolveSeparable(y, window, window);
  const Plane meanXX = convolveSeparable(product(x, x), window, window);
  const Plane meanYY = convolveSeparable(product(y, y), window, window);
  const Plane meanXY = convolveSeparable(product(x, y), window, window);
  MetricMap map{a.width, a.height, std::vector<float>(x.values.size()), 0.0};
  double sum = 0.0;
  for (size_t i = 0; i < map.values.size(); ++i) {
    const float mx = meanX.values[i], my = meanY.values[i];
    const float varianceX = meanXX.values[i] - mx * mx;
    const float varianceY = meanYY.values[i] - my * my;
    const float covariance = meanXY.values[i] - mx * my;
    map.values[i] = ((2.0f * mx * my + c1) * (2.0f * covariance + c2)) /
                    ((mx * mx + my * my + c1) * (varianceX + varianceY + c2));
    sum += map.values[i];
  }
  map.mean = map.values.empty() ? 1.0 : sum / double(map.values.size());
  return map;
}

ImageU8 differenceHeatmap(const ImageU8& a, const ImageU8& b, float gain) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("differenceHeatmap: sizes differ");
  ImageU8 heat(a.width, a.height);
  for (size_t p = 0; p < size_t(a.width) * a.height; ++p) {
    int d = 0;
    for (int c = 0; c < 3; ++c)
      d = std::max(d, std::abs(int(a.pixels[p * 4 + c]) - int(b.pixels[p * 4 + c])));
    float t = std::clamp(d * gain / 255.0f, 0.0f, 1.0f);
    // Black -> red -> yellow -> white, thirds of the range each.
    heat.pixels[p * 4 + 0] = uint8_t(std::lround(255 * std::clamp(3.0f * t, 0.0f, 1.0f)));
    heat.pixels[p * 4 + 1] = uint8_t(std::lround(255 * std::clamp(3.0f * t - 1.0f, 0.0f, 1.0f)));
    heat.pixels[p * 4 + 2] = uint8_t(std::lround(255 * std::clamp(3.0f * t - 2.0f, 0.0f, 1.0f)));
    heat.pixels[p * 4 + 3] = 255;
  }
  return heat;
}

}  // namespace shadelab
