#include "core/metrics/error_metric.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/base/errors.h"
#include "core/metrics/metrics.h"

namespace shadelab {

// PSNR of identical images is infinite; it is capped so that it can be
// charted, written to CSV and compared with a bound.
constexpr double kPsnrCap = 100.0;

const std::vector<ErrorMetric>& errorMetrics() {
  static const std::vector<ErrorMetric> metrics = {
      {"rmse", "RMSE (8-bit sRGB, lower is better)", true,
       [](const ImageU8& reference, const ImageU8& image) {
         return compareImages(reference, image).rmse;
       },
       0.0, 255.0},
      {"psnr", "PSNR dB (higher is better)", false,
       [](const ImageU8& reference, const ImageU8& image) {
         return std::min(compareImages(reference, image).psnr, kPsnrCap);
       },
       0.0, kPsnrCap},
      {"ssim", "SSIM (1 = identical, higher is better)", false,
       [](const ImageU8& reference, const ImageU8& image) {
         return structuralSimilarity(reference, image).mean;
       },
       -1.0, 1.0},
      {"flip", "mean FLIP (0 = identical, lower is better)", true,
       [](const ImageU8& reference, const ImageU8& image) {
         return flipError(reference, image).mean;
       },
       0.0, 1.0},
  };
  return metrics;
}

void checkMetricBound(const ErrorMetric& metric, double bound, const std::string& option) {
  // A ceiling above the range (or a floor below it) is met by anything and
  // is fine; one no image can meet is refused. !(...) also refuses NaN.
  bool reachable = metric.lowerIsBetter ? bound >= metric.lowest : bound <= metric.highest;
  if (reachable && !std::isnan(bound)) return;
  char text[240];
  std::snprintf(text, sizeof text, "%s %g: no image can meet it, expected a %s of %s %g",
                option.c_str(), bound, metric.description.c_str(),
                metric.lowerIsBetter ? "at least" : "at most",
                metric.lowerIsBetter ? metric.lowest : metric.highest);
  throw InputError(text);
}

const ErrorMetric& findErrorMetric(const std::string& name, const std::string& option) {
  for (const ErrorMetric& metric : errorMetrics())
    if (metric.name == name) return metric;
  std::string names;
  for (const ErrorMetric& metric : errorMetrics())
    names += (names.empty() ? "" : ", ") + metric.name;
  throw InputError(option + " '" + name + "': expected one of " + names);
}

}  // namespace shadelab
