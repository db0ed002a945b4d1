#pragma once
// Shadow maps measured against the tracer's exact shadow rays: per pixel of
// a view, whether each light truly reaches the surface the camera sees, and
// how often a shadow-mapped render disagrees.
//   acne: truly lit pixels drawn shadowed (self-shadowing; too little bias),
//   peter-panning: truly shadowed pixels near the caster (the shadow ray
//   hits it within kContactDistance) drawn lit (too much bias).
// Pixels at a silhouette or a true shadow edge (a 3x3 neighbour differs in
// object or visibility) are left out: there the map's resolution decides
// (edge aliasing), not the bias. Like the z-fighting study, a measurement
// that drives the renderer, not a pass.
#include <cstdint>
#include <string>
#include <vector>

#include "core/base/image.h"
#include "core/scene/scene.h"
#include "core/scene/shadows.h"
#include "passes/renderer.h"

namespace shadelab {

inline constexpr float kContactDistance = 0.5f;  // world units from receiver to caster

// The truth for one light of a scene, at width x height.
struct ShadowTruth {
  uint32_t width = 0, height = 0;
  enum class Pixel : uint8_t { Ignored, Lit, Shadowed, ShadowedNearContact };
  std::vector<Pixel> pixels;
};
// `light` indexes scene.lights. Traced with the same camera rays as the
// rasteriser's pixel centres; surfaces turned away from the light (N.L <=
// 0.05) are ignored: the equation gives them no direct light anyway.
ShadowTruth traceShadowTruth(const Scene& scene, uint32_t light, uint32_t width, uint32_t height);

struct ShadowErrors {
  uint64_t lit = 0, acne = 0;  // truly lit pixels; of them drawn shadowed
  uint64_t dimmed = 0;  // truly lit pixels drawn below 0.98 of their light (one PCF5 tap of 25)
  uint64_t contact = 0, peterPanning = 0;  // truly shadowed near contact; of them drawn lit
  uint64_t shadowed = 0, leaked = 0;       // truly shadowed (any distance); of them drawn lit
  double acneFraction() const { return lit ? double(acne) / double(lit) : 0.0; }
  double dimmedFraction() const { return lit ? double(dimmed) / double(lit) : 0.0; }
  double peterPanningFraction() const {
    return contact ? double(peterPanning) / double(contact) : 0.0;
  }
  double leakFraction() const { return shadowed ? double(leaked) / double(shadowed) : 0.0; }
};

// `scene` reduced to its light `light` with no ambient light, rendered
// (Phong) with and without shadows: k_shadow per pixel is their ratio, and a
// pixel counts as drawn shadowed where it is below 0.5. `depthClamp` off
// clips casters nearer than a map's near plane (study shadow-near).
ShadowErrors measureShadowErrors(Renderer& renderer, const Scene& scene, uint32_t light,
                                 const ShadowTruth& truth, ShadowMethod method,
                                 const ShadowBias& bias, uint32_t mapSize, bool depthClamp = true);

// One point of the bias study.
struct BiasStudyRow {
  std::string lightKind;  // "directional" or "point"
  std::string biasKind;   // "constant", "slope", "normal-offset", "default-scaled"
  float value = 0.0f;     // texels (default-scaled: the factor on the default bias)
  ShadowErrors errors;
};
// Each kind of bias alone over `values` (the others 0), and the default bias
// scaled by each value, for every shadowed light of `scene`.
std::vector<BiasStudyRow> runBiasStudy(Renderer& renderer, const Scene& scene,
                                       const std::vector<float>& values, ShadowMethod method,
                                       uint32_t mapSize, uint32_t width, uint32_t height);
std::string biasStudyCsv(const std::vector<BiasStudyRow>& rows);
// Acne and peter-panning (percent) against the bias, a line per bias kind,
// a panel per light kind and error.
ImageU8 biasStudyChart(const std::vector<BiasStudyRow>& rows);

}  // namespace shadelab
