#include "core/metrics/chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "core/base/oiio_module.h"
#include "core/metrics/text_wrap.h"

namespace shadelab {
namespace {

// Drawn through the OpenImageIO module (FreeType text): a chart loads it.
using oiio::AlignX;
using oiio::AlignY;
using oiio::Canvas;
using oiio::Clip;
constexpr const char* kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr int kMarginLeft = 86, kMarginRight = 170, kMarginTop = 52, kMarginBottom = 62;
constexpr int kTitleSize = 18, kAxisLabelSize = 15, kTickSize = 13, kPointLabelSize = 12;
const float kInk[4] = {0.1f, 0.1f, 0.12f, 1.0f};
const float kGrid[4] = {0.88f, 0.88f, 0.9f, 1.0f};
const float kLeader[4] = {0.55f, 0.55f, 0.58f, 1.0f};
const float kPaper[4] = {1.0f, 1.0f, 1.0f, 1.0f};

struct Rect {
  int x0, y0, x1, y1;
  bool overlaps(const Rect& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

oiio::Module& module() {
  return oiio::oiioModule("draw a chart");
}

void drawText(Canvas& image, int x, int y, const std::string& text, int size, const float* color,
              AlignX alignX = AlignX::Left, AlignY alignY = AlignY::Baseline) {
  if (text.empty()) return;
  std::string error;
  if (!image.text(x, y, text, size, kFont, color, alignX, alignY, error))
    throw std::runtime_error("cannot draw chart text with " + std::string(kFont) + ": " + error +
                             " (install Debian package fonts-dejavu-core)");
}

Rect textRect(const std::string& text, int size, int x, int baseline) {
  oiio::TextBox box = module().textSize(text, size, kFont);
  return {x + box.xBegin, baseline + box.yBegin, x + box.xEnd, baseline + box.yEnd};
}

constexpr int kSubtitleLineHeight = 16;

std::string tickText(double value) {
  char text[32];
  if (value != 0.0 && (std::abs(value) >= 1e7 || std::abs(value) < 1e-3))
    std::snprintf(text, sizeof text, "%.0e", value);
  else
    std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// Maps data values to pixels along one axis.
struct Mapping {
  double low, high;
  AxisScale scale;
  int from, to;  // pixel positions of low and high
  double unit(double value) const {
    if (scale == AxisScale::Log) return std::log10(value);
    return value;
  }
  double operator()(double value) const {
    double t = (unit(value) - unit(low)) / (unit(high) - unit(low));
    return from + t * (to - from);
  }
};

// The axis's own ticks, or the automatic ones over the mapped range.
std::vector<ChartTick> ticksOf(const ChartAxis& axis, const Mapping& mapping) {
  if (!axis.ticks.empty()) return axis.ticks;
  std::vector<ChartTick> ticks;
  for (double value : axisTicks(mapping.low, mapping.high, axis.scale))
    ticks.push_back({value, tickText(value)});
  return ticks;
}

// The axis range: the data's, widened to whole ticks.
std::pair<double, double> axisRange(const ChartAxis& axis, double low, double high) {
  if (axis.scale == AxisScale::Log) {
    low = std::max(low, 1e-12);
    high = std::max(high, low);
    // The nearest 1, 2 or 5 times a power of ten outside the data, or within
    // 1% inside it (the marks may overhang the frame a little).
    double lowPower = std::pow(10.0, std::floor(std::log10(low)));
    double lowTick = lowPower;
    for (double step : {2.0, 5.0})
      if (step * lowPower <= low * 1.01) lowTick = step * lowPower;
    double highPower = std::pow(10.0, std::floor(std::log10(high)));
    double highTick = 10.0 * highPower;
    for (double step : {5.0, 2.0, 1.0})
      if (step * highPower >= high * 0.99) highTick = step * highPower;
    if (highTick <= lowTick) highTick = lowTick * 10.0;
    return {axis.min.value_or(lowTick), axis.max.value_or(highTick)};
  }
  if (low > 0.0 && low < 0.5 * high) low = 0.0;  // start from zero when that costs little room
  if (high <= low) high = low + 1.0;
  std::vector<double> ticks = axisTicks(low, high, AxisScale::Linear);
  return {axis.min.value_or(std::min(low, ticks.front())),
          axis.max.value_or(std::max(high, ticks.back()))};
}

// Marks and lines are clipped to `clip` (the plot area, or the whole image).
void fillDisc(Canvas& image, double cx, double cy, double radius, const float* color, double inner,
              const Clip& clip) {
  for (int y = int(std::floor(cy - radius)); y <= int(std::ceil(cy + radius)); ++y)
    for (int x = int(std::floor(cx - radius)); x <= int(std::ceil(cx + radius)); ++x) {
      double d = std::hypot(x - cx, y - cy);
      if (d <= radius && d >= inner && clip.contains(x, y)) image.setPixel(x, y, color);
    }
}

void drawThickLine(Canvas& image, double x0, double y0, double x1, double y1, const float* color,
                   const Clip& clip) {
  for (int offset = 0; offset < 2; ++offset) {
    image.line(int(std::lround(x0)), int(std::lround(y0)) + offset, int(std::lround(x1)),
               int(std::lround(y1)) + offset, color, clip);
  }
}

void drawMarker(Canvas& image, Marker marker, double x, double y, double size, const float* color,
                const Clip& clip) {
  if (marker == Marker::Dot) fillDisc(image, x, y, size, color, -1.0, clip);
  if (marker == Marker::Ring) fillDisc(image, x, y, size + 4.0, color, size + 2.0, clip);
}

void drawVerticalText(Canvas& image, int centerX, int centerY, const std::string& text) {
  oiio::TextBox box = module().textSize(text, kAxisLabelSize, kFont);
  int width = box.xEnd - box.xBegin + 4, height = box.yEnd - box.yBegin + 4;
  std::unique_ptr<Canvas> label = module().createCanvas(width, height, oiio::PixelType::Float);
  label->fill(kPaper);
  drawText(*label, 2 - box.xBegin, 2 - box.yBegin, text, kAxisLabelSize, kInk);
  std::unique_ptr<Canvas> turned = label->rotated270();  // reads bottom to top
  image.paste(centerX - height / 2, centerY - width / 2, *turned);
}

void drawAxes(Canvas& image, const Chart& chart, const std::vector<std::string>& subtitle,
              const Mapping& mx, const Mapping& my, int plotLeft, int plotTop, int plotRight,
              int plotBottom) {
  // A tick can fall just outside the plot when the range was widened with
  // another tick step; OpenImageIO aborts on text placed off the image.
  for (const ChartTick& tick : ticksOf(chart.x, mx)) {
    int x = int(std::lround(mx(tick.value)));
    if (x < plotLeft || x > plotRight) continue;
    image.line(x, plotTop, x, plotBottom, kGrid, std::nullopt);
    image.line(x, plotBottom, x, plotBottom + 5, kInk, std::nullopt);
    drawText(image, x, plotBottom + 20, tick.label, kTickSize, kInk, AlignX::Center);
  }
  for (const ChartTick& tick : ticksOf(chart.y, my)) {
    int y = int(std::lround(my(tick.value)));
    if (y < plotTop || y > plotBottom) continue;
    image.line(plotLeft, y, plotRight, y, kGrid, std::nullopt);
    image.line(plotLeft - 5, y, plotLeft, y, kInk, std::nullopt);
    drawText(image, plotLeft - 8, y, tick.label, kTickSize, kInk, AlignX::Right, AlignY::Center);
  }
  image.box(plotLeft, plotTop, plotRight, plotBottom, kInk);
  drawText(image, (plotLeft + plotRight) / 2, plotBottom + 46, chart.x.label, kAxisLabelSize, kInk,
           AlignX::Center);
  drawVerticalText(image, plotLeft - kMarginLeft + 16, (plotTop + plotBottom) / 2, chart.y.label);
  drawText(image, plotLeft, 22, chart.title, kTitleSize, kInk);
  for (size_t line = 0; line < subtitle.size(); ++line)
    drawText(image, plotLeft, 38 + kSubtitleLineHeight * int(line), subtitle[line], kTickSize,
             kInk);
}

void drawLegend(Canvas& image, const Chart& chart, int left, int top) {
  int y = top + 8;
  Clip all{0, image.width(), 0, image.height()};
  for (size_t i = 0; i < chart.series.size(); ++i) {
    const ChartSeries& series = chart.series[i];
    if (series.name.empty()) continue;
    float color[4] = {series.color.r, series.color.g, series.color.b, 1.0f};
    if (series.connect) drawThickLine(image, left, y, left + 22, y, color, all);
    drawMarker(image, series.marker, left + 11, y, series.markerSize, color, all);
    drawText(image, left + 30, y, series.name, kTickSize, kInk, AlignX::Left, AlignY::Center);
    y += 20;
  }
}

void drawChartInto(Canvas& image, const Chart& chart, int originX, int width, int height) {
  int plotLeft = originX + kMarginLeft, plotRight = originX + width - kMarginRight;
  // A subtitle wider than the panel wraps; the plot starts below its lines.
  std::vector<std::string> subtitle =
      wrapText(chart.subtitle, kTickSize, kFont, originX + width - 8 - plotLeft);
  int plotTop = kMarginTop + kSubtitleLineHeight * std::max(0, int(subtitle.size()) - 1);
  int plotBottom = height - kMarginBottom;
  double minX = std::numeric_limits<double>::infinity(), maxX = -minX;
  double minY = minX, maxY = -minX;
  for (const ChartSeries& series : chart.series)
    for (const ChartPoint& p : series.points) {
      minX = std::min(minX, p.x), maxX = std::max(maxX, p.x);
      minY = std::min(minY, p.y), maxY = std::max(maxY, p.y);
    }
  if (minX > maxX) minX = 0.0, maxX = 1.0, minY = 0.0, maxY = 1.0;  // no data: empty axes
  auto [lowX, highX] = axisRange(chart.x, minX, maxX);
  auto [lowY, highY] = axisRange(chart.y, minY, maxY);
  Mapping mx{lowX, highX, chart.x.scale, plotLeft, plotRight};
  Mapping my{lowY, highY, chart.y.scale, plotBottom, plotTop};
  drawAxes(image, chart, subtitle, mx, my, plotLeft, plotTop, plotRight, plotBottom);

  // Marks may reach a little past the frame, so points on an axis stay visible.
  Clip clip{plotLeft - 8, plotRight + 9, plotTop - 8, plotBottom + 9};
  for (size_t s = 0; s < chart.series.size(); ++s) {
    const ChartSeries& series = chart.series[s];
    float color[4] = {series.color.r, series.color.g, series.color.b, 1.0f};
    for (size_t i = 0; series.connect && i + 1 < series.points.size(); ++i)
      drawThickLine(image, mx(series.points[i].x), my(series.points[i].y),
                    mx(series.points[i + 1].x), my(series.points[i + 1].y), color, clip);
    for (const ChartPoint& p : series.points)
      drawMarker(image, series.marker, mx(p.x), my(p.y), series.markerSize, color, clip);
  }
  // Labels go right, left, above or below their point, or off one of its
  // corners, wherever they overlap no marker, no line and no label placed
  // before; a label with no free spot is left out.
  std::vector<Rect> taken;
  for (const ChartSeries& series : chart.series)
    for (const ChartPoint& p : series.points) {
      int x = int(std::lround(mx(p.x))), y = int(std::lround(my(p.y)));
      int r = int(std::ceil(series.markerSize)) - 1;
      if (series.marker == Marker::Dot) taken.push_back({x - r, y - r, x + r, y + r});
    }
  // A line is a chain of 2-pixel boxes along it (it is drawn ~2 pixels wide).
  for (const ChartSeries& series : chart.series)
    for (size_t i = 0; series.connect && i + 1 < series.points.size(); ++i) {
      double x0 = mx(series.points[i].x), y0 = my(series.points[i].y);
      double x1 = mx(series.points[i + 1].x), y1 = my(series.points[i + 1].y);
      // A point off a log axis maps to an infinity or NaN: no line to avoid.
      double length = std::max(std::abs(x1 - x0), std::abs(y1 - y0));
      if (!(length < 20000.0)) continue;
      int steps = int(std::ceil(length / 2.0));
      for (int k = 0; k <= steps; ++k) {
        double t = steps ? double(k) / steps : 0.0;
        int x = int(std::lround(x0 + (x1 - x0) * t)), y = int(std::lround(y0 + (y1 - y0) * t));
        taken.push_back({x - 1, y - 1, x + 2, y + 2});
      }
    }
  Rect bounds{plotLeft + 2, plotTop + 2, plotRight - 2, plotBottom - 2};
  for (const ChartSeries& series : chart.series)
    for (const ChartPoint& p : series.points) {
      if (p.label.empty()) continue;
      int x = int(std::lround(mx(p.x))), y = int(std::lround(my(p.y)));
      Rect size = textRect(p.label, kPointLabelSize, 0, 0);
      int w = size.x1 - size.x0, h = size.y1 - size.y0;
      std::vector<std::pair<int, int>> spots = {
          {x + 9, y + h / 2}, {x - 9 - w, y + h / 2}, {x - w / 2, y - 9}, {x - w / 2, y + 9 + h},
          {x + 6, y - 6},     {x - 6 - w, y - 6},     {x + 6, y + 6 + h}, {x - 6 - w, y + 6 + h}};
      // Crowded there: further out in eight directions, joined to the point
      // by a leader line (spots from this index on).
      const size_t firstFar = spots.size();
      for (int reach : {28, 46, 64})
        for (int k = 0; k < 8; ++k) {
          const double angle = double(k) * 0.785398163397448;  // pi / 4
          const int dx = int(std::lround(reach * std::cos(angle)));
          const int dy = int(std::lround(reach * std::sin(angle)));
          spots.push_back({dx > 0   ? x + dx
                           : dx < 0 ? x + dx - w
                                    : x - w / 2,
                           dy > 0   ? y + dy + h
                           : dy < 0 ? y + dy
                                    : y + h / 2});
        }
      for (size_t spot = 0; spot < spots.size(); ++spot) {
        auto [left, baseline] = spots[spot];
        Rect rect = textRect(p.label, kPointLabelSize, left, baseline);
        rect = {rect.x0 - 1, rect.y0 - 1, rect.x1 + 1, rect.y1 + 1};
        bool inside = rect.x0 >= bounds.x0 && rect.x1 <= bounds.x1 && rect.y0 >= bounds.y0 &&
                      rect.y1 <= bounds.y1;
        if (!inside || std::any_of(taken.begin(), taken.end(),
                                   [&](const Rect& t) { return t.overlaps(rect); }))
          continue;
        if (spot >= firstFar) {
          // From the marker's edge to the label box's nearest point.
          const int toX = std::clamp(x, rect.x0, rect.x1), toY = std::clamp(y, rect.y0, rect.y1);
          const double length = std::hypot(toX - x, toY - y);
          const double start = (std::ceil(series.markerSize) + 2.0) / std::max(length, 1.0);
          image.line(int(std::lround(x + (toX - x) * start)),
                     int(std::lround(y + (toY - y) * start)), toX, toY, kLeader, std::nullopt);
        }
        drawText(image, left, baseline, p.label, kPointLabelSize, kInk);
        taken.push_back(rect);
        break;
      }
    }
  drawLegend(image, chart, plotRight + 14, plotTop);
}

ImageU8 toImage(const Canvas& image) {
  ImageU8 result(uint32_t(image.width()), uint32_t(image.height()));
  image.getRgba8(result.pixels.data());
  return result;
}

}  // namespace

std::vector<double> axisTicks(double low, double high, AxisScale scale) {
  std::vector<double> ticks;
  if (!(high > low)) return {low};
  if (scale == AxisScale::Log) {
    int first = int(std::floor(std::log10(low) + 1e-9));
    int last = int(std::ceil(std::log10(high) - 1e-9));
    bool fine = last - first < 3;
    for (int decade = first; decade <= last; ++decade)
      for (double step : {1.0, 2.0, 5.0}) {
        if (step != 1.0 && !fine) continue;
        double tick = step * std::pow(10.0, decade);
        if (tick >= low * (1 - 1e-9) && tick <= high * (1 + 1e-9)) ticks.push_back(tick);
      }
    return ticks;
  }
  // About five ticks at 1, 2 or 5 times a power of ten.
  double raw = (high - low) / 5.0;
  double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power * (raw / power < 1.5   ? 1.0
                         : raw / power < 3.5 ? 2.0
                         : raw / power < 7.5 ? 5.0
                                             : 10.0);
  for (double tick = std::floor(low / step + 1e-9) * step; tick <= high + step * 0.999;
       tick += step)
    ticks.push_back(std::abs(tick) < step * 1e-9 ? 0.0 : tick);
  return ticks;
}

glm::vec3 chartColor(size_t index) {
  // Okabe-Ito, distinguishable with the common colour-vision deficiencies.
  static const glm::vec3 palette[] = {
      {0.0f, 0.45f, 0.70f}, {0.90f, 0.62f, 0.0f},  {0.0f, 0.62f, 0.45f},  {0.80f, 0.47f, 0.65f},
      {0.84f, 0.37f, 0.0f}, {0.34f, 0.71f, 0.91f}, {0.60f, 0.60f, 0.60f}, {0.94f, 0.89f, 0.26f}};
  return palette[index % std::size(palette)];
}

ImageU8 drawChart(const Chart& chart, uint32_t width, uint32_t height) {
  return drawChartRow({chart}, width, height);
}

ImageU8 drawChartRow(const std::vector<Chart>& charts, uint32_t panelWidth, uint32_t height) {
  int width = int(panelWidth * charts.size());
  std::unique_ptr<Canvas> image = module().createCanvas(width, int(height), oiio::PixelType::Float);
  image->fill(kPaper);
  for (size_t i = 0; i < charts.size(); ++i)
    drawChartInto(*image, charts[i], int(i * panelWidth), int(panelWidth), int(height));
  return toImage(*image);
}

}  // namespace shadelab
