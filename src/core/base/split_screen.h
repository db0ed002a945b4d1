#pragma once
// Split screen: a frame cut into equal columns side by side, one view each
// (the renderer's viewports, the viewer's labels and error crops, compare's
// cells all use these).
#include <cstdint>
#include <vector>

namespace shadelab {

struct ScreenColumn {
  uint32_t left = 0;   // first pixel column
  uint32_t width = 0;  // pixels
};

// Column i spans [floor(i * width / count), floor((i + 1) * width / count)):
// every pixel belongs to exactly one column and widths differ by at most one
// (the first is the narrowest). `count` is at least 1 and at most `width`.
std::vector<ScreenColumn> splitColumns(uint32_t width, uint32_t count);

}  // namespace shadelab
