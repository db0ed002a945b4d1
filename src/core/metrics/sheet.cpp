#include "core/metrics/sheet.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

namespace shadelab {
namespace {

constexpr const char* kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";
constexpr int kMargin = 8;
constexpr int kTitleHeight = 26;
constexpr int kLineHeight = 18;
constexpr int kTitleSize = 18;
constexpr int kLineSize = 14;

void drawText(OIIO::ImageBuf& sheet, int x, int baseline, const std::string& text, int size) {
  if (text.empty()) return;
  if (!OIIO::ImageBufAlgo::render_text(sheet, x, baseline, text, size, kFont,
                                       {0.92f, 0.92f, 0.92f, 1.0f}))
    throw std::runtime_error("cannot draw sheet labels with " + std::string(kFont) + ": " +
                             sheet.geterror() + " (install Debian package fonts-dejavu-core)");
}

}  // namespace

ImageU8 composeSheet(const std::vector<std::vector<SheetCell>>& rows) {
  uint32_t cellWidth = 0, cellHeight = 0;
  size_t columns = 0, maxLines = 0;
  for (const auto& row : rows) {
    columns = std::max(columns, row.size());
    for (const SheetCell& cell : row) {
      cellWidth = std::max(cellWidth, cell.image.width);
      cellHeight = std::max(cellHeight, cell.image.height);
      maxLines = std::max(maxLines, cell.lines.size());
    }
  }
  int blockWidth = int(cellWidth) + kMargin;
  int blockHeight = kTitleHeight + int(cellHeight) + int(maxLines) * kLineHeight + kMargin;
  int width = kMargin + int(columns) * blockWidth;
  int height = kMargin + int(rows.size()) * blockHeight;
  OIIO::ImageBuf sheet(OIIO::ImageSpec(width, height, 4, OIIO::TypeDesc::UINT8));
  OIIO::ImageBufAlgo::fill(sheet, {0.08f, 0.08f, 0.09f, 1.0f});
  for (size_t r = 0; r < rows.size(); ++r) {
    for (size_t c = 0; c < rows[r].size(); ++c) {
      const SheetCell& cell = rows[r][c];
      int x = kMargin + int(c) * blockWidth;
      int y = kMargin + int(r) * blockHeight;
      drawText(sheet, x, y + kTitleHeight - 8, cell.title, kTitleSize);
      if (cell.image.width > 0) {
        OIIO::ImageSpec spec(int(cell.image.width), int(cell.image.height), 4,
                             OIIO::TypeDesc::UINT8);
        OIIO::ImageBuf image(spec, const_cast<uint8_t*>(cell.image.pixels.data()));
        OIIO::ImageBufAlgo::paste(sheet, x, y + kTitleHeight, 0, 0, image);
      }
      for (size_t l = 0; l < cell.lines.size(); ++l)
        drawText(sheet, x, y + kTitleHeight + int(cellHeight) + int(l + 1) * kLineHeight - 4,
                 cell.lines[l], kLineSize);
    }
  }
  ImageU8 result{uint32_t(width), uint32_t(height)};
  sheet.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 4), OIIO::TypeDesc::UINT8,
                   result.pixels.data());
  return result;
}

}  // namespace shadelab
