#include "measure/study.h"

#include "core/base/errors.h"

namespace shadelab {

// Each study's runner, defined in its own study_<name>.cpp.
StudyResult runZFightStudy(const StudyOptions& options, const StudyServices& services);
StudyResult runAcneStudy(const StudyOptions& options, const StudyServices& services);
StudyResult runTirStudy(const StudyOptions& options, const StudyServices& services);
StudyResult runGouraudHighlightStudy(const StudyOptions& options, const StudyServices& services);
StudyResult runEnvVsTraceStudy(const StudyOptions& options, const StudyServices& services);
StudyResult runBumpSilhouetteStudy(const StudyOptions& options, const StudyServices& services);
StudyResult runShadowBiasStudy(const StudyOptions& options, const StudyServices& services);
StudyResult runShadowEdgesStudy(const StudyOptions& options, const StudyServices& services);
StudyResult runShadowGrazingStudy(const StudyOptions& options, const StudyServices& services);
StudyResult runShadowNearStudy(const StudyOptions& options, const StudyServices& services);
StudyResult runLodPoppingStudy(const StudyOptions& options, const StudyServices& services);
StudyResult runBillboardFailuresStudy(const StudyOptions& options, const StudyServices& services);
StudyResult runImpostorParallaxStudy(const StudyOptions& options, const StudyServices& services);

const std::vector<Study>& studies() {
  static const std::vector<Study> table = {
      {"zfight",
       "z-fighting per depth mode, perspective and orthographic, against the near plane and "
       "against the polygons' distance",
       640, 360, runZFightStudy},
      {"acne",
       "the tracer's epsilon against shadow acne (lit points shadowed) and light leaks "
       "(shadowed points lit); CPU only",
       320, 180, runAcneStudy},
      {"tir",
       "total internal reflection: light refracted out of glass per ior and angle, energy kept, "
       "the critical angle against asin(1/ior); CPU only",
       256, 256, runTirStudy},
      {"gouraud-highlight",
       "Gouraud's peak highlight over Phong's against how finely the plane is subdivided", 320, 180,
       runGouraudHighlightStudy},
      {"bump-silhouette",
       "a bump-mapped sphere beside the same height field as displaced geometry: outline and "
       "interior differences",
       480, 360, runBumpSilhouetteStudy},
      {"env-vs-trace",
       "environment mapping against the traced reflection on env, FLIP split by where the traced "
       "path goes (hits an object or escapes), per shading model",
       480, 270, runEnvVsTraceStudy},
      {"shadow-bias",
       "shadow-map bias (constant, slope, normal offset, the default scaled) against acne and "
       "peter-panning, measured with the tracer's exact shadow rays",
       320, 180, runShadowBiasStudy},
      {"shadow-edges",
       "shadow-map size and filter against the traced shadow edges: mean FLIP and frame time", 480,
       270, runShadowEdgesStudy},
      {"shadow-grazing",
       "the sun lowered to a grazing angle: acne and peter-panning with no bias and the default "
       "one, hard and pcf3, against the tracer's exact shadow rays",
       320, 180, runShadowGrazingStudy},
      {"shadow-near",
       "a caster crossing the point light's near plane: truly shadowed pixels drawn lit with the "
       "shadow pass's depth clamp and without it, against the tracer's exact shadow rays",
       320, 180, runShadowNearStudy},
      {"lod-popping",
       "levels of detail chosen every frame: switches and the jump they add between frames on a "
       "dolly and on a camera oscillating about a switching distance, with hysteresis and without",
       320, 180, runLodPoppingStudy},
      {"billboard-failures",
       "billboards: cylindrical coverage against the eye's elevation (edge-on from above) beside "
       "spherical, and the ground cutting a sunk quad along the expected line",
       320, 180, runBillboardFailuresStudy},
      {"impostor-parallax",
       "an octahedral impostor against its full mesh as the atlas's cells per side grow: the "
       "bound the level-of-detail chain uses beside measured outline distance and FLIP",
       320, 240, runImpostorParallaxStudy},
  };
  return table;
}

const Study& findStudy(const std::string& name) {
  std::string names;
  for (const Study& study : studies()) {
    if (study.name == name) return study;
    names += (names.empty() ? "" : ", ") + std::string(study.name);
  }
  throw InputError("study '" + name + "': expected one of " + names);
}

}  // namespace shadelab
