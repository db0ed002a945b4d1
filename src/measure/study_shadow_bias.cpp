// Study `shadow-bias`: each kind of shadow-map bias alone (constant,
// slope-scaled, normal offset) and the default bias scaled, against the two
// ways a bias fails, measured against the tracer's exact shadow rays on the
// `shadows` scene: acne (truly lit pixels drawn shadowed: too little bias)
// and peter-panning (truly shadowed pixels near contact drawn lit: too much).
#include <cstdio>

#include "core/base/files.h"
#include "measure/shadow_study.h"
#include "measure/study.h"

namespace shadelab {

StudyResult runShadowBiasStudy(const StudyOptions& options, const StudyServices& services) {
  const std::vector<float> values = {0.0f, 0.25f, 0.5f, 1.0f, 2.0f, 4.0f, 8.0f, 16.0f};
  services.progress("tracing the exact shadows, then " + std::to_string(values.size() * 4) +
                    " biases per light, each drawn with and without its map");
  std::vector<BiasStudyRow> rows =
      runBiasStudy(services.renderer(), builtinScene("shadows"), values, kDefaultShadowMethod,
                   kDefaultShadowMapSize, options.width, options.height);
  StudyResult result;
  result.report = "light        bias kind       texels    acne %   peter-panning %\n";
  for (const BiasStudyRow& row : rows) {
    char line[160];
    std::snprintf(line, sizeof line, "%-12s %-15s %6g %9.3f %17.3f", row.lightKind.c_str(),
                  row.biasKind.c_str(), row.value, 100.0 * row.errors.acneFraction(),
                  100.0 * row.errors.peterPanningFraction());
    result.report += std::string(line) + "\n";
  }
  writeTextFile(options.output / "shadow_bias.csv", biasStudyCsv(rows));
  writeImage(biasStudyChart(rows), options.output / "shadow_bias.png");
  result.files = {"shadow_bias.csv", "shadow_bias.png"};
  return result;
}

}  // namespace shadelab
