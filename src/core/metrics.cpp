#include "core/metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace shadelab {

ImageDifference compareImages(const ImageU8& a, const ImageU8& b, int threshold) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("compareImages: sizes differ (" + std::to_string(a.width) + "x" +
                                std::to_string(a.height) + " vs " + std::to_string(b.width) +
                                "x" + std::to_string(b.height) + ")");
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
