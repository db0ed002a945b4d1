#pragma once
#include <string_view>

#include "core/base/names.h"
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
inline constexpr NameTable<ShadingModel, 5> kShadingModelNames = {
    {{ShadingModel::Flat, "flat"},
     {ShadingModel::Gouraud, "gouraud"},
     {ShadingModel::Phong, "phong"},
     {ShadingModel::BlinnPhong, "blinn-phong"},
     {ShadingModel::Unlit, "unlit"}}};
constexpr int kShadingModelCount = int(kShadingModelNames.size());

inline std::string_view shadingModelName(ShadingModel model) {
  return nameOf(kShadingModelNames, model);
}

}  // namespace shadelab
