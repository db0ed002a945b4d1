#pragma once
// A comparison sheet: a grid of labelled images (renders, heatmaps) with a
// few lines of numbers under each, composed on the CPU once per run.
#include <string>
#include <vector>

#include "core/base/image.h"

namespace shadelab {

struct SheetCell {
  ImageU8 image;                   // empty (0x0) leaves the cell blank
  std::string title;               // drawn above the image
  std::vector<std::string> lines;  // drawn below it
};

// Rows of cells, every image the same size. Throws std::runtime_error if the
// label font (Debian fonts-dejavu-core) is missing.
ImageU8 composeSheet(const std::vector<std::vector<SheetCell>>& rows);

}  // namespace shadelab
