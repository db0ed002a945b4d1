#pragma once
// The error the benchmark and `render --quality` measure against a
// reference, chosen by name so that a new metric is one table entry: RMSE,
// PSNR (8-bit sRGB), SSIM and mean FLIP (core/metrics/metrics.h).
#include <functional>
#include <string>
#include <vector>

#include "core/base/image.h"

namespace shadelab {

struct ErrorMetric {
  std::string name;         // "rmse"
  std::string description;  // for chart axes and messages
  bool lowerIsBetter = true;
  std::function<double(const ImageU8& reference, const ImageU8& image)> measure;
  // The values the metric can take: a bound outside them is refused before
  // any measuring (a FLIP of -1 can never be met).
  double lowest = 0.0;
  double highest = 0.0;

  // Whether `value` meets `bound`: at most the bound for an error, at least
  // it for a quality score such as PSNR.
  bool meets(double value, double bound) const {
    return lowerIsBetter ? value <= bound : value >= bound;
  }
  // Ordered so that smaller is always better (for Pareto fronts).
  double badness(double value) const { return lowerIsBetter ? value : -value; }
};

// Throws InputError naming `option` and the value when no image can meet
// `bound`: an error ceiling below `lowest`, a score floor above `highest`.
void checkMetricBound(const ErrorMetric& metric, double bound, const std::string& option);
// Throws InputError naming `option` and the metrics that exist.
const ErrorMetric& findErrorMetric(const std::string& name, const std::string& option);
const std::vector<ErrorMetric>& errorMetrics();

}  // namespace shadelab
