#pragma once
// Error between two images of the same size (alpha is ignored): RMSE and
// PSNR in 8-bit sRGB units over the RGB channels, SSIM, and FLIP.
#include <cstdint>
#include <vector>

#include "core/base/image.h"

namespace shadelab {

struct ImageDifference {
  double rmse = 0.0;                 // root mean square error, 0..255
  double psnr = 0.0;                 // 20 log10(255 / rmse) dB; +infinity when identical
  int maxDifference = 0;             // largest channel difference, 0..255
  uint64_t pixelsOverThreshold = 0;  // pixels with any channel differing by more than the threshold
  double fractionOverThreshold = 0.0;
};

// Throws std::invalid_argument when the sizes differ.
ImageDifference compareImages(const ImageU8& a, const ImageU8& b, int threshold = 0);

// A tolerance an image test states and checks.
struct ImageTolerance {
  double minPsnr = 40.0;           // dB
  int pixelThreshold = 4;          // channel difference that counts a pixel as different
  double maxFractionOver = 0.005;  // of all pixels
};
bool withinTolerance(const ImageDifference& difference, const ImageTolerance& tolerance);

// |a - b| per pixel, scaled by `gain` and shown on a black-to-red-to-yellow-to-white ramp.
ImageU8 differenceHeatmap(const ImageU8& a, const ImageU8& b, float gain = 8.0f);

// A per-pixel metric and its mean over the image.
struct MetricMap {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> values;  // row-major, row 0 at the top
  double mean = 0.0;
  float at(uint32_t x, uint32_t y) const { return values[size_t(y) * width + x]; }
};

// SSIM (Wang, Bovik, Sheikh, Simoncelli 2004) on the luma of the stored
// sRGB values (Rec. 709 weights, 0..1, the grey image SSIM is usually run
// on): local means, variances and covariance under an 11x11 Gaussian window
// of sigma 1.5, C1 = (0.01)^2, C2 = (0.03)^2. Borders repeat the edge
// pixels. 1 where identical, lower the more the structure differs.
// Throws std::invalid_argument when the sizes differ.
MetricMap structuralSimilarity(const ImageU8& a, const ImageU8& b);

// LDR FLIP (Andersson et al. 2020, "FLIP: A Difference Evaluator for
// Alternating Images"): the perceived difference, 0 (none) to 1, of `test`
// from `reference` for a viewer seeing `pixelsPerDegree` pixels per degree
// of visual angle (67: a 0.7 m viewing distance from a 24" 4K monitor).
// Colour differences (contrast sensitivity filtered, Hunt-adjusted HyAB in
// L*a*b*) raised to the power 1 - the feature (edge and point) difference.
// Throws std::invalid_argument when the sizes differ.
MetricMap flipError(const ImageU8& reference, const ImageU8& test, double pixelsPerDegree = 67.0);

// A map of values in [0, 1] on the perceptually uniform "magma" ramp (black,
// purple, orange, pale yellow), as FLIP's authors show their error maps.
ImageU8 magmaHeatmap(const MetricMap& map);

}  // namespace shadelab
