#include "core/scene/shading.h"

namespace shadelab {
namespace {
constexpr std::string_view kNames[kShadingModelCount] = {"flat", "gouraud", "phong", "blinn-phong",
                                                         "unlit"};
}

std::string_view shadingModelName(ShadingModel model) { return kNames[int(model)]; }

std::optional<ShadingModel> parseShadingModel(std::string_view name) {
  for (int i = 0; i < kShadingModelCount; ++i)
    if (kNames[i] == name) return ShadingModel(i);
  return std::nullopt;
}

std::vector<std::string> shadingModelNames() { return {std::begin(kNames), std::end(kNames)}; }

}  // namespace shadelab
