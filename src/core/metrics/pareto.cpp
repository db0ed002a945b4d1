#include "core/metrics/pareto.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace shadelab {

std::vector<size_t> paretoFront(const std::vector<CostError>& points) {
  std::vector<size_t> order(points.size());
  std::iota(order.begin(), order.end(), size_t(0));
  // Cheapest first, the smaller error first among equal costs, then by index
  // so duplicates keep the first.
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    if (points[a].cost != points[b].cost) return points[a].cost < points[b].cost;
    return points[a].error < points[b].error;
  });
  // Sweeping by cost, a point is on the front exactly when its error is
  // below every cheaper (or equally cheap, earlier) point's.
  std::vector<size_t> front;
  double bestError = std::numeric_limits<double>::infinity();
  for (size_t index : order)
    if (points[index].error < bestError) {
      front.push_back(index);
      bestError = points[index].error;
    }
  return front;
}

}  // namespace shadelab
