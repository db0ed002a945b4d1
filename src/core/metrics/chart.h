#pragma once
// Charts drawn by shadelab itself (OpenImageIO, DejaVu Sans): scatter and
// line series on linear or logarithmic axes with ticks, labelled points and
// a legend, for the benchmark's speed-against-accuracy plots.
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/base/image.h"

namespace shadelab {

struct ChartPoint {
  double x = 0.0;
  double y = 0.0;
  std::string label;  // drawn beside the point where it fits; empty: none
};

enum class Marker { Dot, Ring, None };

struct ChartSeries {
  std::string name;  // in the legend; empty: not listed
  glm::vec3 color{0.2f};
  std::vector<ChartPoint> points;
  bool connect = false;  // a line through the points in order
  Marker marker = Marker::Dot;
  double markerSize = 4.0;  // radius in pixels
};

enum class AxisScale { Linear, Log };

struct ChartTick {
  double value = 0.0;
  std::string label;
};

struct ChartAxis {
  std::string label;
  AxisScale scale = AxisScale::Linear;
  std::optional<double> min, max;  // default: the data's range (linear axes include 0 if close)
  // Ticks to draw instead of the automatic ones (e.g. the values a sweep
  // took, evenly spaced by their index: an ordinal axis); empty: automatic.
  std::vector<ChartTick> ticks;
};

struct Chart {
  std::string title;
  std::string subtitle;  // one smaller line under the title
  ChartAxis x, y;
  std::vector<ChartSeries> series;  // drawn in order; labels of earlier series win a contested spot
};

// Throws std::runtime_error if the font (Debian fonts-dejavu-core) is missing.
ImageU8 drawChart(const Chart& chart, uint32_t width, uint32_t height);
// Charts side by side, each panelWidth x height.
ImageU8 drawChartRow(const std::vector<Chart>& charts, uint32_t panelWidth, uint32_t height);

// Tick positions covering [low, high]: 1-2-5 steps on a linear axis, powers of
// ten (with 2 and 5 between when fewer than three decades) on a log axis.
std::vector<double> axisTicks(double low, double high, AxisScale scale);
// A distinct, legible colour for the i-th series.
glm::vec3 chartColor(size_t index);

}  // namespace shadelab
