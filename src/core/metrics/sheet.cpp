#include "core/metrics/sheet.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "core/base/oiio_module.h"
#include "core/metrics/text_wrap.h"

namespace shadelab {
namespace {

constexpr const char* kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";
constexpr int kMargin = 8;
constexpr int kTitleHeight = 26;
constexpr int kLineHeight = 18;
constexpr int kTitleSize = 18;
constexpr int kTitleLineHeight = 22;
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
  size_t columns = 0;
  for (const auto& row : rows) {
    columns = std::max(columns, row.size());
    for (const SheetCell& cell : row) {
      cellWidth = std::max(cellWidth, cell.image.width);
      cellHeight = std::max(cellHeight, cell.image.height);
    }
  }
  // Titles and lines wrap to the cell's width (a narrow image would let them
  // run into the next column). A row's title band is as tall as its longest
  // title; every row keeps room for the most lines any cell has, so the
  // images of all rows sit on one grid.
  // Two pixels spare: antialiased ink can reach a pixel past the measured box.
  const int textWidth = std::max(int(cellWidth) - 2, 1);
  struct Laid {
    std::vector<std::string> title, lines;
  };
  std::vector<std::vector<Laid>> laid(rows.size());
  std::vector<size_t> titleLines(rows.size(), 1);
  size_t mostLines = 0;
  for (size_t r = 0; r < rows.size(); ++r)
    for (const SheetCell& cell : rows[r]) {
      Laid cellText{wrapText(cell.title, kTitleSize, kFont, textWidth), {}};
      for (const std::string& line : cell.lines)
        for (std::string& part : wrapText(line, kLineSize, kFont, textWidth))
          cellText.lines.push_back(std::move(part));
      titleLines[r] = std::max(titleLines[r], cellText.title.size());
      mostLines = std::max(mostLines, cellText.lines.size());
      laid[r].push_back(std::move(cellText));
    }
  int blockWidth = int(cellWidth) + kMargin;
  int width = kMargin + int(columns) * blockWidth;
  std::vector<int> rowTop(rows.size() + 1, kMargin);
  for (size_t r = 0; r < rows.size(); ++r)
    rowTop[r + 1] = rowTop[r] + kTitleHeight + int(titleLines[r] - 1) * kTitleLineHeight +
                    int(cellHeight) + int(mostLines) * kLineHeight + kMargin;
  int height = rowTop.back();
  std::unique_ptr<oiio::Canvas> sheet =
      oiio::oiioModule("compose a sheet").createCanvas(width, height, oiio::PixelType::UInt8);
  static const float kBackground[4] = {0.08f, 0.08f, 0.09f, 1.0f};
  sheet->fill(kBackground);
  for (size_t r = 0; r < rows.size(); ++r) {
    const int titleHeight = kTitleHeight + int(titleLines[r] - 1) * kTitleLineHeight;
    for (size_t c = 0; c < rows[r].size(); ++c) {
      const SheetCell& cell = rows[r][c];
      const Laid& text = laid[r][c];
      int x = kMargin + int(c) * blockWidth;
      int y = rowTop[r];
      for (size_t l = 0; l < text.title.size(); ++l)
        drawText(*sheet, x, y + kTitleHeight - 8 + int(l) * kTitleLineHeight, text.title[l],
                 kTitleSize);
      if (cell.image.width > 0)
        sheet->pasteRgba8(x, y + titleHeight, int(cell.image.width), int(cell.image.height),
                          cell.image.pixels.data());
      for (size_t l = 0; l < text.lines.size(); ++l)
        drawText(*sheet, x, y + titleHeight + int(cellHeight) + int(l + 1) * kLineHeight - 4,
                 text.lines[l], kLineSize);
    }
  }
  ImageU8 result{uint32_t(width), uint32_t(height)};
  sheet->getRgba8(result.pixels.data());
  return result;
}

}  // namespace shadelab
