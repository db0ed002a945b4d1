#pragma once
// The Pareto front of (cost, error) points: the settings no other setting
// beats on both counts, the only ones worth choosing.
#include <cstddef>
#include <vector>

namespace shadelab {

struct CostError {
  double cost = 0.0;   // e.g. milliseconds per frame
  double error = 0.0;  // lower is better
};

// Indices of the non-dominated points, by increasing cost. A point is
// dominated when another costs no more and errs no more, and is strictly
// better in one; of exact duplicates only the first index is kept.
std::vector<size_t> paretoFront(const std::vector<CostError>& points);

}  // namespace shadelab
