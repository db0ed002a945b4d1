#include "core/metrics/error_metric.h"

#include <algorithm>

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
       }},
      {"psnr", "PSNR dB (higher is better)", false,
       [](const ImageU8& reference, const ImageU8& image) {
         return std::min(compareImages(reference, image).psnr, kPsnrCap);
       }},
      {"ssim", "SSIM (1 = identical, higher is better)", false,
       [](const ImageU8& reference, const ImageU8& image) {
         return structuralSimilarity(reference, image).mean;
       }},
      {"flip", "mean FLIP (0 = identical, lower is better)", true,
       [](const ImageU8& reference, const ImageU8& image) {
         return flipError(reference, image).mean;
       }},
  };
  return metrics;
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
