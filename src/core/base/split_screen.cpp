#include "core/base/split_screen.h"

#include <cassert>

namespace shadelab {

std::vector<ScreenColumn> splitColumns(uint32_t width, uint32_t count) {
  assert(count >= 1 && count <= width);
  // In integers: the float form floor(i * (width / count)) leaves the last
  // pixel uncovered for some widths and odd counts (13 pixels in 11 columns).
  auto edge = [&](uint32_t i) { return uint32_t(uint64_t(i) * width / count); };
  std::vector<ScreenColumn> columns;
  for (uint32_t i = 0; i < count; ++i) columns.push_back({edge(i), edge(i + 1) - edge(i)});
  return columns;
}

}  // namespace shadelab
