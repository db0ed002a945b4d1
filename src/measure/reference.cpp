#include "measure/reference.h"

#include "core/base/errors.h"
#include "core/trace/raytracer.h"

namespace shadelab {
namespace {

const std::vector<Reference>& references() {
  static const std::vector<Reference> table = {
      traceReference(4, true),
      rasterReference(true),
  };
  return table;
}

}  // namespace

Reference rasterReference(bool shadows) {
  return {"raster",
          std::string("Phong, 4x tessellation, 4x MSAA") +
              (shadows ? ", hard shadows" : ", no shadows"),
          [shadows](Renderer& renderer, const Scene& scene, uint32_t width, uint32_t height) {
            Scene fine = scene;
            fine.retessellate(4.0f);
            RenderSettings settings{width, height, ShadingModel::Phong};
            settings.msaaSamples = 4;
            // The shadows render draws, as the traced reference has its own:
            // against a shadowless reference a setting's error would be mostly
            // its shadows.
            if (shadows) settings.shadows = kDefaultShadowMethod;
            return renderer.renderToImage(fine, settings).image;
          }};
}

Reference traceReference(uint32_t samplesPerPixel, bool shadows) {
  return {
      "trace",
      "Whitted ray tracer, " + std::to_string(samplesPerPixel) + " spp" +
          (shadows ? "" : ", no shadows"),
      [samplesPerPixel, shadows](Renderer&, const Scene& scene, uint32_t width, uint32_t height) {
        TraceSettings settings;
        settings.width = width;
        settings.height = height;
        settings.samplesPerPixel = samplesPerPixel;
        settings.shadows = shadows;
        return RayTracer(scene).render(settings).image;
      }};
}

const Reference& findReference(const std::string& name, const std::string& option,
                               const std::string& alsoAccepted) {
  for (const Reference& reference : references())
    if (reference.name == name) return reference;
  std::string names = alsoAccepted;
  for (const Reference& reference : references())
    names += (names.empty() ? "" : ", ") + reference.name;
  throw InputError(option + " '" + name + "': expected " + names);
}

}  // namespace shadelab
