#include "core/metrics/image_filter.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace shadelab {

Plane convolveSeparable(const Plane& image, const std::vector<float>& horizontal,
                        const std::vector<float>& vertical) {
  assert(horizontal.size() % 2 == 1 && vertical.size() % 2 == 1);
  const int w = int(image.width), h = int(image.height);
  const int rx = int(horizontal.size() / 2), ry = int(vertical.size() / 2);
  Plane rows(image.width, image.height), result(image.width, image.height);
  for (int y = 0; y < h; ++y) {
    const float* row = &image.values[size_t(y) * size_t(w)];
    for (int x = 0; x < w; ++x) {
      float sum = 0.0f;
      for (int k = -rx; k <= rx; ++k)
        sum += horizontal[size_t(k + rx)] * row[std::clamp(x + k, 0, w - 1)];
      rows.values[size_t(y) * size_t(w) + size_t(x)] = sum;
    }
  }
  for (int y = 0; y < h; ++y) {
    float* out = &result.values[size_t(y) * size_t(w)];
    for (int k = -ry; k <= ry; ++k) {
      const float weight = vertical[size_t(k + ry)];
      const float* in = &rows.values[size_t(std::clamp(y + k, 0, h - 1)) * size_t(w)];
      for (int x = 0; x < w; ++x) out[x] += weight * in[x];
    }
  }
  return result;
}

std::vector<float> gaussianKernel(float sigma, int radius) {
  std::vector<float> kernel(size_t(2 * radius + 1));
  float sum = 0.0f;
  for (int x = -radius; x <= radius; ++x) {
    kernel[size_t(x + radius)] = std::exp(-float(x * x) / (2.0f * sigma * sigma));
    sum += kernel[size_t(x + radius)];
  }
  for (float& value : kernel) value /= sum;
  return kernel;
}

}  // namespace shadelab
