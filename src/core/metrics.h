#pragma once
// Error between two images of the same size, in 8-bit sRGB units over the
// RGB channels (alpha is ignored).
#include <cstdint>

#include "core/image.h"

namespace shadelab {

struct ImageDifference {
  double rmse = 0.0;       // root mean square error, 0..255
  double psnr = 0.0;       // 20 log10(255 / rmse) dB; +infinity when identical
  int maxDifference = 0;   // largest channel difference, 0..255
  uint64_t pixelsOverThreshold = 0;  // pixels with any channel differing by more than the threshold
  double fractionOverThreshold = 0.0;
};

// Throws std::invalid_argument when the sizes differ.
ImageDifference compareImages(const ImageU8& a, const ImageU8& b, int threshold = 0);

// A tolerance an image test states and checks.
struct ImageTolerance {
  double minPsnr = 40.0;              // dB
  int pixelThreshold = 4;             // channel difference that counts a pixel as different
  double maxFractionOver = 0.005;     // of all pixels
};
bool withinTolerance(const ImageDifference& difference, const ImageTolerance& tolerance);

// |a - b| per pixel, scaled by `gain` and shown on a black-to-red-to-yellow-to-white ramp.
ImageU8 differenceHeatmap(const ImageU8& a, const ImageU8& b, float gain = 8.0f);

}  // namespace shadelab
