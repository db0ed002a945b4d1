#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "interface.h"

namespace shadelab {

// The shading models the forward pass offers, as its specialization constant.
enum class ShadingModel : int {
  Flat = SHADING_FLAT,
  Gouraud = SHADING_GOURAUD,
  Phong = SHADING_PHONG,
  BlinnPhong = SHADING_BLINN_PHONG,
  Unlit = SHADING_UNLIT,
};
constexpr int kShadingModelCount = 5;

std::string_view shadingModelName(ShadingModel model);  // "flat", "gouraud", ...
std::optional<ShadingModel> parseShadingModel(std::string_view name);
std::vector<std::string> shadingModelNames();

}  // namespace shadelab
