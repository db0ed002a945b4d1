#include "core/metrics/text_wrap.h"

#include <cctype>

#include "core/base/oiio_module.h"

namespace shadelab {

std::vector<std::string> wrapText(const std::string& text, int size, const std::string& font,
                                  int width) {
  oiio::Module& module = oiio::oiioModule("lay out labels");
  auto fits = [&](const std::string& line) {
    oiio::TextBox box = module.textSize(line, size, font);
    return box.xEnd - box.xBegin <= width;
  };
  std::vector<std::string> lines;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.size();
    if (!fits(text.substr(start))) {
      // The last break that fits: before a space (dropped) or after a
      // hyphen (kept). A first word too wide on its own is cut after as many
      // characters as fit (at least one).
      end = start;
      auto letter = [&](size_t i) {
        return i < text.size() && std::isalpha((unsigned char)text[i]);
      };
      for (size_t at = text.find_first_of(" -", start); at != std::string::npos;
           at = text.find_first_of(" -", at + 1)) {
        // A hyphen between letters ("blinn-phong"), not a minus sign.
        if (text[at] == '-' && !(at > 0 && letter(at - 1) && letter(at + 1))) continue;
        size_t lineEnd = text[at] == '-' ? at + 1 : at;
        if (lineEnd == start || !fits(text.substr(start, lineEnd - start))) break;
        end = lineEnd;
      }
      if (end == start) {
        end = start + 1;
        while (end < text.size() && text[end] != ' ' && fits(text.substr(start, end + 1 - start)))
          ++end;
      }
    }
    lines.push_back(text.substr(start, end - start));
    start = end;
    while (start < text.size() && text[start] == ' ') ++start;
  }
  return lines;
}

}  // namespace shadelab
