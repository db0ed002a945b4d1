// Split-screen columns: the one place their pixel edges are computed
// (renderer viewports, viewer crops and labels, compare cells).
#include <gtest/gtest.h>

#include "core/base/image.h"
#include "core/base/split_screen.h"

namespace shadelab {
namespace {

TEST(SplitScreen, EqualColumnsWhenTheWidthDivides) {
  std::vector<ScreenColumn> columns = splitColumns(320, 4);
  ASSERT_EQ(columns.size(), 4u);
  for (uint32_t i = 0; i < 4; ++i) {
    EXPECT_EQ(columns[i].left, 80 * i);
    EXPECT_EQ(columns[i].width, 80u);
  }
}

// floor(i * width / count) in exact arithmetic: every pixel in one column,
// widths within one pixel of each other, the first the narrowest.
TEST(SplitScreen, ColumnsTileEveryWidth) {
  for (uint32_t width = 1; width <= 600; ++width)
    for (uint32_t count = 1; count <= std::min(width, 12u); ++count) {
      std::vector<ScreenColumn> columns = splitColumns(width, count);
      ASSERT_EQ(columns.size(), count);
      uint32_t next = 0;
      for (const ScreenColumn& column : columns) {
        ASSERT_EQ(column.left, next) << width << " / " << count;
        ASSERT_GE(column.width, width / count);
        ASSERT_LE(column.width, (width + count - 1) / count);
        next += column.width;
      }
      ASSERT_EQ(next, width) << width << " / " << count;
      ASSERT_EQ(columns[0].width, width / count);
    }
}

// The float form the columns used to be computed with,
// floor(i * float(width / count)), ends the last column at pixel 12 of 13.
TEST(SplitScreen, LastColumnReachesTheRightEdgeWhereFloatsFellShort) {
  std::vector<ScreenColumn> columns = splitColumns(13, 11);
  EXPECT_EQ(columns.back().left + columns.back().width, 13u);
  float columnWidth = 13.0f / 11.0f;
  EXPECT_EQ(uint32_t(std::floor(columnWidth * 11.0f)), 12u);  // the old edge, one short
}

TEST(SplitScreen, CropColumnsCopiesThoseColumnsOfEveryRow) {
  ImageU8 image(5, 3);
  for (uint32_t y = 0; y < 3; ++y)
    for (uint32_t x = 0; x < 5; ++x) image.set(x, y, {uint8_t(x), uint8_t(y), 7, 255});
  ImageU8 part = cropColumns(image, 2, 2);
  ASSERT_EQ(part.width, 2u);
  ASSERT_EQ(part.height, 3u);
  for (uint32_t y = 0; y < 3; ++y)
    for (uint32_t x = 0; x < 2; ++x) EXPECT_EQ(part.at(x, y), image.at(x + 2, y));
}

}  // namespace
}  // namespace shadelab
