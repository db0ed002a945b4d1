#pragma once
// Single-channel float images and separable convolution, for the image
// metrics (SSIM's Gaussian window, FLIP's contrast sensitivity and feature
// filters).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace shadelab {

struct Plane {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> values;  // row-major

  Plane() = default;
  Plane(uint32_t w, uint32_t h) : width(w), height(h), values(size_t(w) * h, 0.0f) {}
  float& operator()(uint32_t x, uint32_t y) { return values[size_t(y) * width + x]; }
  float operator()(uint32_t x, uint32_t y) const { return values[size_t(y) * width + x]; }
};

// Convolves rows with `horizontal` then columns with `vertical` (odd-sized
// kernels, centred); outside the image the edge pixel repeats.
Plane convolveSeparable(const Plane& image, const std::vector<float>& horizontal,
                        const std::vector<float>& vertical);

// exp(-x^2 / (2 sigma^2)) for x = -radius..radius, scaled to sum to 1.
std::vector<float> gaussianKernel(float sigma, int radius);

}  // namespace shadelab
