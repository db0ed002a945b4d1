#include "measure/bench_charts.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <tuple>

#include "core/metrics/chart.h"

namespace shadelab {
namespace {

constexpr uint32_t kChartWidth = 1100, kChartHeight = 640;

AxisScale scaleFor(double low, double high) {
  return low > 0.0 && high / low > 8.0 ? AxisScale::Log : AxisScale::Linear;
}

}  // namespace

std::vector<size_t> chartedResults(const std::vector<BenchResult>& results, size_t metricIndex) {
  std::vector<size_t> indices;
  for (size_t i = 0; i < results.size(); ++i)
    if (results[i].point.model != ShadingModel::Unlit && metricIndex < results[i].errors.size())
      indices.push_back(i);
  return indices;
}

std::vector<size_t> benchParetoFront(const std::vector<BenchResult>& results,
                                     const std::vector<size_t>& indices, size_t metricIndex,
                                     const ErrorMetric& metric) {
  std::vector<CostError> points;
  for (size_t i : indices)
    points.push_back({results[i].deviceMedianMs, metric.badness(results[i].errors[metricIndex])});
  std::vector<size_t> front;
  for (size_t f : paretoFront(points)) front.push_back(indices[f]);
  return front;
}

ImageU8 errorTimeChart(const std::vector<BenchResult>& results, size_t metricIndex,
                       const ErrorMetric& metric, const std::string& title) {
  std::vector<size_t> indices = chartedResults(results, metricIndex);
  std::vector<size_t> front = benchParetoFront(results, indices, metricIndex, metric);
  Chart chart;
  chart.title = title;
  chart.subtitle =
      "each point a setting (model, tessellation t, MSAA); ring and line: the Pareto "
      "front, nothing is both faster and more accurate";
  chart.y = {metric.description, AxisScale::Linear};
  // The front is listed first so that its points win the contested label spots.
  ChartSeries frontSeries{"Pareto front", glm::vec3(0.1f), {}, true, Marker::Ring};
  for (size_t i : front)
    frontSeries.points.push_back({results[i].deviceMedianMs, results[i].errors[metricIndex],
                                  benchPointName(results[i].point)});
  chart.series.push_back(frontSeries);
  std::map<ShadingModel, ChartSeries> byModel;
  double lowMs = 1e300, highMs = 0.0;
  for (size_t i : indices) {
    const BenchResult& r = results[i];
    lowMs = std::min(lowMs, r.deviceMedianMs), highMs = std::max(highMs, r.deviceMedianMs);
    ChartSeries& series = byModel[r.point.model];
    series.name = shadingModelName(r.point.model);
    series.color = chartColor(size_t(r.point.model));
    bool onFront = std::find(front.begin(), front.end(), i) != front.end();
    series.points.push_back(
        {r.deviceMedianMs, r.errors[metricIndex], onFront ? "" : benchPointName(r.point)});
  }
  for (auto& [model, series] : byModel) chart.series.push_back(series);
  AxisScale scale = indices.empty() ? AxisScale::Linear : scaleFor(lowMs, highMs);
  chart.x = {scale == AxisScale::Log ? "device frame time, median ms (log)"
                                     : "device frame time, median ms",
             scale};
  return drawChart(chart, kChartWidth, kChartHeight);
}

ImageU8 errorTriangleChart(const std::vector<BenchResult>& results, size_t metricIndex,
                           const ErrorMetric& metric, const std::string& title) {
  Chart chart;
  chart.title = title;
  chart.subtitle =
      "one line per shading model and MSAA (rings: multisampled) through the tessellation "
      "sweep (t = tessellation factor)";
  chart.y = {metric.description, AxisScale::Linear};
  // One line per (model, samples, filter): the tessellation sweep runs along it.
  std::map<std::tuple<ShadingModel, uint32_t, std::string>, std::vector<size_t>> lines;
  auto label = [](const BenchPoint& point) {
    std::string text = point.filter ? benchFilterName(point.filter) : "";
    if (point.shadows != ShadowMethod::Off)
      text += (text.empty() ? "" : " ") + std::string("shadows ") + benchShadowName(point);
    return text;
  };
  double lowTriangles = 1e300, highTriangles = 0.0;
  for (size_t i : chartedResults(results, metricIndex)) {
    const BenchPoint& point = results[i].point;
    lines[{point.model, point.msaaSamples, label(point)}].push_back(i);
    lowTriangles = std::min(lowTriangles, double(results[i].triangles));
    highTriangles = std::max(highTriangles, double(results[i].triangles));
  }
  std::vector<uint64_t> labelled;  // each tessellation's column is labelled once
  for (auto& [key, members] : lines) {
    std::sort(members.begin(), members.end(),
              [&](size_t a, size_t b) { return results[a].triangles < results[b].triangles; });
    ChartSeries series;
    const auto& [model, samples, filter] = key;
    series.name = std::string(shadingModelName(model)) + " " + std::to_string(samples) + "x" +
                  (filter.empty() ? "" : " " + filter);
    // Colours by model as in the time chart; multisampled lines get rings.
    series.color = chartColor(size_t(model));
    series.marker = samples > 1 ? Marker::Ring : Marker::Dot;
    series.markerSize = samples > 1 ? 2.0 : 4.0;
    series.connect = true;
    for (size_t i : members) {
      char label[24] = "";
      if (std::find(labelled.begin(), labelled.end(), results[i].triangles) == labelled.end()) {
        std::snprintf(label, sizeof label, "t%g", results[i].point.tessellation);
        labelled.push_back(results[i].triangles);
      }
      series.points.push_back(
          {double(results[i].triangles), results[i].errors[metricIndex], label});
    }
    chart.series.push_back(series);
  }
  AxisScale scale = lines.empty() ? AxisScale::Linear : scaleFor(lowTriangles, highTriangles);
  chart.x = {scale == AxisScale::Log ? "triangles per frame (log)" : "triangles per frame", scale};
  return drawChart(chart, kChartWidth, kChartHeight);
}

ImageU8 scalingChart(const std::vector<BenchResult>& results, const std::string& title) {
  if (results.empty()) return {};
  // An axis: its value in a result, the chart's x of that result, its label.
  struct Axis {
    const char* name;
    const char* label;
    double (*key)(const BenchResult&);
    double (*x)(const BenchResult&);
  };
  const Axis axes[] = {
      {"triangles", "triangles per frame (log)",
       [](const BenchResult& r) { return double(r.point.tessellation); },
       [](const BenchResult& r) { return double(r.triangles); }},
      {"pixels", "pixels per frame (log)",
       [](const BenchResult& r) { return double(r.point.width) * r.point.height; },
       [](const BenchResult& r) { return double(r.point.width) * r.point.height; }},
      {"lights", "lights (log)", [](const BenchResult& r) { return double(r.point.lights); },
       [](const BenchResult& r) { return double(r.lights); }}};
  const BenchPoint& first = results.front().point;
  auto sameOtherwise = [&](const BenchResult& r, const Axis& free) {
    const BenchPoint& p = r.point;
    bool same = p.msaaSamples == first.msaaSamples && p.filter == first.filter &&
                p.shadows == first.shadows && p.shadowMapSize == first.shadowMapSize &&
                p.lodError == first.lodError;
    for (const Axis& axis : axes)
      if (&axis != &free) same = same && axis.key(r) == axis.key(results.front());
    return same;
  };
  std::vector<Chart> charts;
  for (const Axis& axis : axes) {
    std::vector<double> values;
    for (const BenchResult& r : results)
      if (std::find(values.begin(), values.end(), axis.key(r)) == values.end())
        values.push_back(axis.key(r));
    if (values.size() < 2) continue;
    Chart chart;
    chart.title = std::string("Frame time against ") + axis.name;
    // What the panel holds still: the first value of every other axis.
    const BenchResult& held = results.front();
    char part[64];
    std::string subtitle = title;
    if (&axis != &axes[1]) {
      std::snprintf(part, sizeof part, ", %ux%u", held.point.width, held.point.height);
      subtitle += part;
    }
    if (&axis != &axes[2]) subtitle += ", " + std::to_string(held.lights) + " lights";
    if (&axis != &axes[0]) {
      std::snprintf(part, sizeof part, ", %llu triangles",
                    static_cast<unsigned long long>(held.triangles));
      subtitle += part;
    }
    std::snprintf(part, sizeof part, ", %ux MSAA, shadows %s", held.point.msaaSamples,
                  benchShadowName(held.point).c_str());
    chart.subtitle = subtitle + part;
    chart.x = {axis.label, AxisScale::Log};
    chart.y = {"device frame time, median ms (log)", AxisScale::Log};
    std::map<ShadingModel, ChartSeries> byModel;
    for (const BenchResult& r : results) {
      if (!sameOtherwise(r, axis)) continue;
      ChartSeries& series = byModel[r.point.model];
      series.name = r.point.model == ShadingModel::Unlit
                        ? "unlit (floor)"
                        : std::string(shadingModelName(r.point.model));
      series.color = chartColor(size_t(r.point.model));
      series.connect = true;
      series.points.push_back({axis.x(r), r.deviceMedianMs, ""});
    }
    for (auto& [model, series] : byModel) {
      std::sort(series.points.begin(), series.points.end(),
                [](const ChartPoint& a, const ChartPoint& b) { return a.x < b.x; });
      chart.series.push_back(series);
    }
    charts.push_back(chart);
  }
  if (charts.empty()) return {};
  return drawChartRow(charts, 520, 420);
}

ImageU8 levelOfDetailChart(const std::vector<BenchResult>& results, const std::string& title) {
  if (results.empty()) return {};
  // The other axes at the first result's values: only the bound and the model vary.
  BenchPoint first = results.front().point;
  auto sameOtherwise = [&](const BenchPoint& point) {
    BenchPoint probe = point;
    probe.lodError = first.lodError;
    probe.model = first.model;
    return probe == first;
  };
  Chart time, error;
  time.title = title;
  time.subtitle = "frame time (device median) against --lod-error; flat lines: --lod off";
  time.x = {"error bound (pixels, log)", AxisScale::Log};
  time.y = {"device median (ms)", AxisScale::Linear};
  error.title = "Accuracy of the levels";
  error.subtitle = "mean FLIP against the same model at --lod off; grey: 0.01";
  error.x = time.x;
  error.y = {"mean FLIP", AxisScale::Linear};
  double low = 1e30, high = 0.0;
  for (const BenchResult& r : results)
    if (r.point.lodError > 0.0f && sameOtherwise(r.point)) {
      low = std::min(low, double(r.point.lodError));
      high = std::max(high, double(r.point.lodError));
    }
  if (high == 0.0) return {};
  std::map<ShadingModel, std::vector<const BenchResult*>> byModel;
  std::map<ShadingModel, const BenchResult*> full;
  for (const BenchResult& r : results) {
    if (!sameOtherwise(r.point)) continue;
    if (r.point.lodError > 0.0f)
      byModel[r.point.model].push_back(&r);
    else
      full[r.point.model] = &r;
  }
  if (full.empty()) return {};  // nothing to measure the levels against
  for (auto& [model, members] : byModel) {
    std::sort(members.begin(), members.end(), [](const BenchResult* a, const BenchResult* b) {
      return a->point.lodError < b->point.lodError;
    });
    glm::vec3 color = chartColor(size_t(model));
    std::string name(shadingModelName(model));
    ChartSeries times{name, color, {}, true, Marker::Dot};
    ChartSeries flips{name, color, {}, true, Marker::Dot};
    for (const BenchResult* r : members) {
      char label[32];
      std::snprintf(label, sizeof label, "%.1f ms", r->deviceMedianMs);
      times.points.push_back({r->point.lodError, r->deviceMedianMs, label});
      if (r->flipAgainstFull >= 0.0)
        flips.points.push_back({r->point.lodError, r->flipAgainstFull, ""});
    }
    time.series.push_back(times);
    if (!flips.points.empty()) error.series.push_back(flips);
    if (auto found = full.find(model); found != full.end()) {
      char label[48];
      std::snprintf(label, sizeof label, "%s --lod off: %.1f ms", name.c_str(),
                    found->second->deviceMedianMs);
      time.series.push_back(
          {"",
           color,
           {{low, found->second->deviceMedianMs, label}, {high, found->second->deviceMedianMs, ""}},
           true,
           Marker::None});
    }
  }
  error.series.push_back(
      {"", glm::vec3(0.5f), {{low, 0.01, "0.01"}, {high, 0.01, ""}}, true, Marker::None});
  return drawChartRow({time, error}, 560, 380);
}

}  // namespace shadelab
