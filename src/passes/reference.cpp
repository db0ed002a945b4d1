#include "passes/reference.h"

#include "core/errors.h"

namespace shadelab {
namespace {

const std::vector<Reference>& references() {
  static const std::vector<Reference> table = {
      {"raster", "Phong, 4x tessellation, 4x MSAA",
       [](Renderer& renderer, const Scene& scene, uint32_t width, uint32_t height) {
         Scene fine = scene;
         fine.retessellate(4.0f);
         RenderSettings settings{width, height, ShadingModel::Phong};
         settings.msaaSamples = 4;
         return renderer.renderToImage(fine, settings).image;
       }},
  };
  return table;
}

}  // namespace

const Reference& findReference(const std::string& name, const std::string& option) {
  for (const Reference& reference : references())
    if (reference.name == name) return reference;
  std::string names;
  for (const Reference& reference : references())
    names += (names.empty() ? "" : ", ") + reference.name;
  throw InputError(option + " '" + name + "': expected " + names);
}

}  // namespace shadelab
