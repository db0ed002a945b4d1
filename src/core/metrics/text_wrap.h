#pragma once
// Labels that fit: text broken at spaces into lines no wider than a width,
// measured with the font the charts and sheets draw it in.
#include <string>
#include <vector>

namespace shadelab {

// `text` in lines at most `width` pixels wide at `size` in `font`, broken
// at spaces and after hyphens between letters; a word wider than that is broken where it reaches
// the width (a line holds at least one character). Empty text: no lines. Loads the OpenImageIO
// module (it measures with FreeType).
std::vector<std::string> wrapText(const std::string& text, int size, const std::string& font,
                                  int width);

}  // namespace shadelab
