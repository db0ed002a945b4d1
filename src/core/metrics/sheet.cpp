#include "core/metrics/sheet.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "core/base/oiio_module.h"

namespace shadelab {
namespace {

constexpr const char* kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";
constexpr int kMargin = 8;
constexpr int kTitleHeight = 26;
constexpr int kLineHeight = 18;
constexpr int kTitleSize = 18;
constexpr int kLineSize = 14;

// Text through the OpenImageIO module (FreeType): a sheet loads it.
void drawText(oiio::Canvas& sheet, int x, int baseline, const std::string& text, int size) {
  if (text.empty()) return;
  static const float kLabel[4] = {0.92f, 0.92f, 0.92f, 1.0f};
  std::string error;
  if (!sheet.text(x, baseline, text, size, kFont, kLabel, oiio::AlignX::Left,
                  oiio::AlignY::Baseline, error))
    throw std::runtime_error("cannot draw sheet labels with " + std::string(kFont) + ": " + error +
                             " (install Debian package fonts-dejavu-core)");
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
  std::unique_ptr<oiio::Canvas> sheet =
      oiio::oiioModule("compose a sheet").createCanvas(width, height, oiio::PixelType::UInt8);
  static const float kBackground[4] = {0.08f, 0.08f, 0.09f, 1.0f};
  sheet->fill(kBackground);
  for (size_t r = 0; r < rows.size(); ++r) {
    for (size_t c = 0; c < rows[r].size(); ++c) {
      const SheetCell& cell = rows[r][c];
      int x = kMargin + int(c) * blockWidth;
      int y = kMargin + int(r) * blockHeight;
      drawText(*sheet, x, y + kTitleHeight - 8, cell.title, kTitleSize);
      if (cell.image.width > 0)
        sheet->pasteRgba8(x, y + kTitleHeight, int(cell.image.width), int(cell.image.height),
                          cell.image.pixels.data());
      for (size_t l = 0; l < cell.lines.size(); ++l)
        drawText(*sheet, x, y + kTitleHeight + int(cellHeight) + int(l + 1) * kLineHeight - 4,
                 cell.lines[l], kLineSize);
    }
  }
  ImageU8 result{uint32_t(width), uint32_t(height)};
  sheet->getRgba8(result.pixels.data());
  return result;
}

}  // namespace shadelab
