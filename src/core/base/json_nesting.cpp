#include "core/base/json_nesting.h"

#include <algorithm>

#include "core/base/errors.h"

namespace shadelab {

void checkJsonNesting(std::string_view text, const std::string& source, size_t limit) {
  size_t depth = 0;
  bool inString = false;
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (inString) {
      if (c == '\\')
        ++i;  // the escaped character, whatever it is
      else if (c == '"')
        inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) {
        size_t line = 1 + size_t(std::count(text.begin(), text.begin() + long(i), '\n'));
        throw InputError(source + ": JSON nests deeper than " + std::to_string(limit) +
                         " levels of arrays and objects (at line " + std::to_string(line) + ")");
      }
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
}

}  // namespace shadelab
