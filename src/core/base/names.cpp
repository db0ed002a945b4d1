#include "core/base/names.h"

namespace shadelab {

std::string joinNames(const std::vector<std::string_view>& names, std::string_view separator) {
  std::string joined;
  for (std::string_view name : names) {
    if (!joined.empty()) joined += separator;
    joined += name;
  }
  return joined;
}

}  // namespace shadelab
