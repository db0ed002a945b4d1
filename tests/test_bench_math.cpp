// The benchmark's CPU-side logic on known inputs: the Pareto front, axis
// ticks and charts, bench CSV round trips, the --quality choice, error
// metrics and depth-mode names.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/base/errors.h"
#include "core/metrics/chart.h"
#include "core/metrics/error_metric.h"
#include "core/metrics/pareto.h"
#include "core/metrics/sheet.h"
#include "core/metrics/text_wrap.h"
#include "core/scene/gltf_loader.h"
#include "core/scene/scene_loader.h"
#include "core/vulkan/depth.h"
#include "measure/benchmark.h"
#include "measure/quality.h"

namespace shadelab {
namespace {

TEST(ParetoFront, KeepsOnlyTheUndominatedPointsByIncreasingCost) {
  // (cost, error): 0 and 2 and 4 form the front; 1 is beaten by 0, 3 by 2, 5 by 4.
  std::vector<CostError> points = {{1, 10}, {2, 12}, {3, 5}, {4, 5}, {6, 1}, {7, 1}};
  EXPECT_EQ(paretoFront(points), (std::vector<size_t>{0, 2, 4}));
}

TEST(ParetoFront, OrderOfInputDoesNotMatterAndTiesKeepTheFirst) {
  std::vector<CostError> points = {{6, 1}, {3, 5}, {1, 10}, {3, 5}, {3, 4}};
  // Equal cost: the smaller error wins (index 4 over 1 and 3); sorted by cost.
  EXPECT_EQ(paretoFront(points), (std::vector<size_t>{2, 4, 0}));
  EXPECT_EQ(paretoFront({{2, 2}, {2, 2}}), (std::vector<size_t>{0}));
  EXPECT_TRUE(paretoFront({}).empty());
}

TEST(ParetoFront, AMonotoneTradeOffIsAllFront) {
  std::vector<CostError> points;
  for (int i = 0; i < 6; ++i) points.push_back({double(i), 10.0 - i});
  EXPECT_EQ(paretoFront(points).size(), 6u);
}

TEST(AxisTicks, LinearStepsOfOneTwoOrFive) {
  EXPECT_EQ(axisTicks(0, 7, AxisScale::Linear), (std::vector<double>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(axisTicks(0, 100, AxisScale::Linear), (std::vector<double>{0, 20, 40, 60, 80, 100}));
  EXPECT_EQ(axisTicks(0, 0.5, AxisScale::Linear).size(), 6u);  // 0, 0.1 .. 0.5
}

TEST(AxisTicks, LogDecadesWithTwoAndFiveWhenFew) {
  EXPECT_EQ(axisTicks(0.001, 10, AxisScale::Log), (std::vector<double>{0.001, 0.01, 0.1, 1, 10}));
  std::vector<double> fine = axisTicks(1, 100, AxisScale::Log);
  ASSERT_EQ(fine.size(), 7u);
  EXPECT_DOUBLE_EQ(fine[1], 2.0);
  EXPECT_DOUBLE_EQ(fine[5], 50.0);
}

size_t pixelsOfColor(const ImageU8& image, glm::vec3 color) {
  glm::u8vec4 wanted(glm::round(color * 255.0f), 255);
  size_t count = 0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) count += image.at(x, y) == wanted;
  return count;
}

TEST(Chart, DrawsEachSeriesInItsColourOnWhitePaper) {
  Chart chart{"title", "subtitle", {"x"}, {"y"}};
  chart.series.push_back({"a", glm::vec3(1, 0, 0), {{1, 1, "one"}, {2, 3, "two"}}, true});
  chart.series.push_back({"b", glm::vec3(0, 0, 1), {{1.5, 2, ""}}});
  ImageU8 image = drawChart(chart, 600, 400);
  ASSERT_EQ(image.width, 600u);
  EXPECT_GT(pixelsOfColor(image, glm::vec3(1)), size_t(600 * 400 / 2));  // mostly paper
  EXPECT_GT(pixelsOfColor(image, glm::vec3(1, 0, 0)), 100u);             // line and two dots
  EXPECT_GT(pixelsOfColor(image, glm::vec3(0, 0, 1)), 40u);              // a dot and its legend
  // Without series b no pixel is blue: the colour came from it.
  Chart without = chart;
  without.series.pop_back();
  EXPECT_LT(pixelsOfColor(drawChart(without, 600, 400), glm::vec3(0, 0, 1)), 1u);
}

// A subtitle wider than the panel wraps onto more lines and the plot moves
// down to make room (study acne's subtitle ran off the image). The frame's
// top edge: the first row that is dark across most of the plot's width. The
// twin: a subtitle that fits leaves the frame where it was.
// Break opportunities: spaces and hyphens between letters, never a minus
// sign (compare's "ab -0.25" kept its number whole).
TEST(Chart, WrappedTextBreaksAtSpacesAndHyphensNotMinusSigns) {
  const std::string font = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";
  // 14-pixel mono: about 8.4 pixels a character; 60 pixels hold 7.
  EXPECT_EQ(wrapText("blinn-phong vs reference", 14, font, 60),
            (std::vector<std::string>{"blinn-", "phong", "vs", "referen", "ce"}));
  std::vector<std::string> minus = wrapText("ab -0.25 cd", 14, font, 60);
  EXPECT_EQ(minus, (std::vector<std::string>{"ab", "-0.25", "cd"}));
  EXPECT_TRUE(wrapText("", 14, font, 60).empty());
  EXPECT_EQ(wrapText("fits", 14, font, 600), (std::vector<std::string>{"fits"}));
}

TEST(Chart, LongSubtitleWrapsAndPushesThePlotDown) {
  auto frameTop = [](const ImageU8& image) {
    for (uint32_t y = 0; y < image.height; ++y) {
      uint32_t dark = 0;
      for (uint32_t x = 0; x < image.width; ++x) dark += image.at(x, y).r < 80;
      if (dark > image.width / 3) return y;
    }
    return image.height;
  };
  auto darkRows = [](const ImageU8& image, uint32_t below) {
    uint32_t rows = 0;
    for (uint32_t y = 0; y < below; ++y)
      for (uint32_t x = 0; x < image.width; ++x)
        if (image.at(x, y).r < 80) {
          ++rows;
          break;
        }
    return rows;
  };
  Chart shortSubtitle{"title", "one short line", {"x"}, {"y"}};
  shortSubtitle.series.push_back({"a", glm::vec3(1, 0, 0), {{1, 1, ""}, {2, 2, ""}}, true});
  Chart longSubtitle = shortSubtitle;
  longSubtitle.subtitle =
      "acne: lit points drawn shadowed; leak: shadowed points drawn lit; epsilon 0 (off the log "
      "axis): 85.3% acne, and then some more words that could never fit on one line of this chart";
  ImageU8 fits = drawChart(shortSubtitle, 600, 400), wraps = drawChart(longSubtitle, 600, 400);
  EXPECT_GE(frameTop(wraps), frameTop(fits) + 2 * 16);  // two more lines of 16 pixels
  // The text above the frame covers more rows: the extra lines are drawn.
  EXPECT_GT(darkRows(wraps, frameTop(wraps)), darkRows(fits, frameTop(fits)) + 16);
  // No dark pixel in the last 4 columns: nothing runs off the right edge.
  for (uint32_t y = 0; y < frameTop(wraps); ++y)
    for (uint32_t x = wraps.width - 4; x < wraps.width; ++x)
      EXPECT_GE(wraps.at(x, y).r, 80) << x << ", " << y;
}

// A sheet's titles and lines wrap to their cell's width: with 64-pixel
// images, "gouraud vs reference" used to run across the next column. The
// 8-pixel gaps between the cells stay free of text (light pixels), and the
// sheet grows taller for the extra lines. Twin: the same sheet with images
// wide enough for the text is no taller than one line each needs.
TEST(Sheet, TitlesAndLinesWrapToTheCellWidth) {
  auto sheetOf = [](uint32_t cellWidth) {
    ImageU8 black(cellWidth, 20);
    for (size_t i = 3; i < black.pixels.size(); i += 4) black.pixels[i] = 255;
    std::vector<std::vector<SheetCell>> rows(1);
    for (const char* title : {"gouraud vs reference", "blinn-phong vs reference"})
      rows[0].push_back({black, title, {"RMSE 4.619  PSNR 34.84 dB", "SSIM 0.9759  FLIP 0.0315"}});
    return composeSheet(rows);
  };
  ImageU8 narrow = sheetOf(64), wide = sheetOf(400);
  EXPECT_GT(narrow.height, wide.height + 40u) << "two more title lines and two more lines";
  // The gap after the first cell: x from 8 + 64 to 8 + 64 + 8.
  size_t inGap = 0;
  for (uint32_t y = 0; y < narrow.height; ++y)
    for (uint32_t x = 8 + 64; x < 8 + 64 + 8; ++x) inGap += narrow.at(x, y).r > 128;
  EXPECT_EQ(inGap, 0u);
}

// An axis's own ticks replace the automatic ones (the shadow-bias study
// labels ranks 0..7 with its bias values). Counted as the grid's vertical
// lines strictly inside the frame: the automatic ticks of data over 0..7
// (steps of 1) give 6; ticks given at 0, 3.5 and 7 give 1.
TEST(Chart, AxisTicksGivenReplaceTheAutomaticOnes) {
  auto innerGridColumns = [](const ImageU8& image) {
    const glm::u8vec4 grid(224, 224, 230, 255);
    uint32_t columns = 0;
    for (uint32_t x = 0; x < image.width; ++x) {
      uint32_t count = 0;
      for (uint32_t y = 0; y < image.height; ++y) count += image.at(x, y) == grid;
      columns += count > image.height / 3;
    }
    return columns;
  };
  Chart chart{"title", "subtitle", {"x"}, {"y"}};
  chart.series.push_back({"a", glm::vec3(1, 0, 0), {}, true});
  for (int rank = 0; rank < 8; ++rank)
    chart.series[0].points.push_back({double(rank), double(rank % 3), ""});
  EXPECT_EQ(innerGridColumns(drawChart(chart, 600, 400)), 6u);
  chart.x.ticks = {{0.0, "none"}, {3.5, "half"}, {7.0, "all"}};
  EXPECT_EQ(innerGridColumns(drawChart(chart, 600, 400)), 1u);
}

// A point label keeps off the lines: on a flat line (bench's "--lod off"
// reference line) the label of its first point used to sit across the line.
// The twins: without the line boxes the label lands on the line (onLine
// 178 pixels, checked by hand); and the chart does draw the label.
TEST(Chart, PointLabelsKeepOffTheLines) {
  Chart chart{"title", "subtitle", {"x"}, {"y"}};
  // The line's first point on the left edge: the label fits only right of it or off a corner.
  chart.series.push_back(
      {"flat", glm::vec3(1, 0, 0), {{0, 1, "--lod off: 9.0 ms"}, {10, 1, ""}}, true});
  chart.series.push_back({"range", glm::vec3(0, 0, 1), {{5, 0, ""}, {5, 2, ""}}});
  auto dark = [](glm::u8vec4 p) { return p.r < 120 && p.g < 120 && p.b < 120; };
  ImageU8 image = drawChart(chart, 600, 400);
  // The line's row: the one with the most red pixels; its extent in x.
  uint32_t row = 0, most = 0;
  for (uint32_t y = 0; y < image.height; ++y) {
    uint32_t red = 0;
    for (uint32_t x = 0; x < image.width; ++x) red += image.at(x, y) == glm::u8vec4(255, 0, 0, 255);
    if (red > most) most = red, row = y;
  }
  ASSERT_GT(most, 100u);
  uint32_t left = image.width, right = 0;
  for (uint32_t x = 0; x < image.width; ++x)
    if (image.at(x, row) == glm::u8vec4(255, 0, 0, 255)) left = std::min(left, x), right = x;
  size_t onLine = 0;
  for (uint32_t y = row - 4; y <= row + 4; ++y)
    for (uint32_t x = left; x <= right; ++x) onLine += dark(image.at(x, y));
  EXPECT_EQ(onLine, 0u);
  auto darkPixels = [&](const ImageU8& picture) {
    size_t count = 0;
    for (uint32_t y = 0; y < picture.height; ++y)
      for (uint32_t x = 0; x < picture.width; ++x) count += dark(picture.at(x, y));
    return count;
  };
  Chart unlabelled = chart;
  unlabelled.series[0].points[0].label.clear();
  EXPECT_GT(darkPixels(image), darkPixels(drawChart(unlabelled, 600, 400)) + 50);
}

// A point whose eight spots beside it are all taken (here by eight dots a
// few pixels around it) gets its label further out with a grey leader line
// to it: bench-shadows.png had lost "hard 2048" that way. Twin: without the
// label there is no leader and fewer dark pixels.
TEST(Chart, CrowdedPointsGetTheirLabelOnALeaderLine) {
  Chart chart{"title",
              "subtitle",
              {"x", AxisScale::Linear, 0.0, 10.0},
              {"y", AxisScale::Linear, 0.0, 10.0}};
  chart.series.push_back({"crowd", glm::vec3(0, 0, 1), {}});
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      if (dx || dy) chart.series[0].points.push_back({5.0 + 0.3 * dx, 5.0 + 0.4 * dy, ""});
  chart.series.push_back({"labelled", glm::vec3(1, 0, 0), {{5.0, 5.0, "the crowded point"}}});
  auto count = [](const ImageU8& image, auto&& wanted) {
    size_t n = 0;
    for (uint32_t y = 0; y < image.height; ++y)
      for (uint32_t x = 0; x < image.width; ++x) n += wanted(image.at(x, y));
    return n;
  };
  auto leader = [](glm::u8vec4 p) { return p == glm::u8vec4(140, 140, 148, 255); };
  auto dark = [](glm::u8vec4 p) { return p.r < 120 && p.g < 120 && p.b < 120; };
  ImageU8 labelled = drawChart(chart, 600, 400);
  Chart unlabelled = chart;
  unlabelled.series[1].points[0].label.clear();
  ImageU8 bare = drawChart(unlabelled, 600, 400);
  EXPECT_GT(count(labelled, leader), 10u);
  EXPECT_EQ(count(bare, leader), 0u);
  EXPECT_GT(count(labelled, dark), count(bare, dark) + 50);
}

// The bench of assets/scenes/peer-shading.json at 800x600 aborted inside
// OpenImageIO: its RMSE range (2.26 to 16.1) gave a tick above the plot,
// whose label landed off the image. Every such range must draw.
TEST(Chart, RangesWhoseTicksOvershootTheAxisStillDraw) {
  for (double high : {16.126, 9.7, 31.3, 0.0123, 1234.5}) {
    Chart chart{"title", "subtitle", {"ms", AxisScale::Log}, {"rmse"}};
    chart.series.push_back({"s", glm::vec3(1, 0, 0), {{2.7, 2.264, "a"}, {4.0, high, "b"}}});
    ImageU8 image = drawChart(chart, 1100, 640);
    EXPECT_GT(pixelsOfColor(image, glm::vec3(1, 0, 0)), 20u) << high;
  }
}

TEST(BenchCsv, ParsesColumnsAndRowsAndRejectsRaggedLines) {
  BenchTable table = parseBenchCsv("a,b,c\n1,2,3\n4,5,\n", "t.csv");
  EXPECT_EQ(table.columns, (std::vector<std::string>{"a", "b", "c"}));
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.rows[1][2], "");
  EXPECT_EQ(table.column("b", "t.csv"), 1u);
  EXPECT_THROW(table.column("z", "t.csv"), InputError);
  EXPECT_THROW(parseBenchCsv("a,b\n1\n", "t.csv"), InputError);
  EXPECT_THROW(parseBenchCsv("", "t.csv"), InputError);
}

// As a spreadsheet saves a results.csv: a byte order mark, CRLF and quoted
// fields read as the plain file; a header naming a column twice is refused.
TEST(BenchCsv, ReadsWhatASpreadsheetSavesAndRefusesAColumnTwice) {
  BenchTable plain = parseBenchCsv("scene,mode\nspheres,flat\n", "t.csv");
  for (const char* saved : {"\xEF\xBB\xBFscene,mode\r\nspheres,flat\r\n\r\n",
                            "\"scene\",\"mode\"\n\"spheres\",flat\n"}) {
    BenchTable table = parseBenchCsv(saved, "t.csv");
    EXPECT_EQ(table.columns, plain.columns) << saved;
    EXPECT_EQ(table.rows, plain.rows) << saved;
  }
  EXPECT_EQ(parseBenchCsv("a\n\"say \"\"hi\"\"\"\n", "t.csv").rows[0][0], "say \"hi\"");
  try {
    parseBenchCsv("scene,flip,flip\nspheres,0.1,0.2\n", "t.csv");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(), "'t.csv': column 'flip' twice in the header; expected each once");
  }
}

TEST(BenchCsv, WritesOneRowPerResultWithEveryMetric) {
  BenchOptions options{4, 1, {"raster", "", {}}, errorMetrics()};
  BenchResult result;
  result.point = {ShadingModel::Gouraud, 2.0f, 4};
  result.point.width = 64;
  result.point.height = 36;
  result.triangles = 80;
  result.lights = 3;
  result.errors = {1.5, 44.6};
  BenchTable table = parseBenchCsv(benchCsv({result}, options, "spheres"), "out");
  ASSERT_EQ(table.rows.size(), 1u);
  const auto& row = table.rows[0];
  EXPECT_EQ(row[table.column("mode", "out")], "gouraud");
  EXPECT_EQ(row[table.column("tessellation", "out")], "2");
  EXPECT_EQ(row[table.column("msaa", "out")], "4");
  EXPECT_EQ(row[table.column("rmse", "out")], "1.5");
  EXPECT_EQ(row[table.column("psnr", "out")], "44.6");
  EXPECT_EQ(row[table.column("reference", "out")], "raster");
  EXPECT_EQ(row[table.column("width", "out")], "64");
  EXPECT_EQ(row[table.column("height", "out")], "36");
  EXPECT_EQ(row[table.column("lights", "out")], "3");
  EXPECT_EQ(row[table.column("lod_error_px", "out")], "0");
  EXPECT_EQ(table.columns.back(), "flip_vs_lod_off") << "a later column goes last";
}

TEST(BenchAxes, SizesAndLightsAreAxesWithModelsVaryingFastest) {
  BenchAxes axes;
  axes.models = {ShadingModel::Unlit, ShadingModel::Phong};
  axes.sizes = {{320, 180}, {640, 360}};
  axes.lights = {1, 8};
  std::vector<BenchPoint> points = benchPoints(axes);
  ASSERT_EQ(points.size(), 8u);
  EXPECT_EQ(points[0].model, ShadingModel::Unlit);
  EXPECT_EQ(points[1].model, ShadingModel::Phong);
  EXPECT_EQ(points[1].lights, 1u);
  EXPECT_EQ(points[2].lights, 8u);
  EXPECT_EQ(points[3].width, 320u);
  EXPECT_EQ(points[4].width, 640u);
  EXPECT_EQ(points[7].height, 360u);
  EXPECT_EQ(benchPointName(points[2]), "unlit t1 1x 8 lights");
}

TEST(BenchAxes, LightRingReplacesTheLightsWithEqualShares) {
  Scene scene = builtinScene("default");
  Scene lit = withLightRing(scene, 5);
  ASSERT_EQ(lit.lights.size(), 5u);
  Bounds bounds = sceneBounds(scene);
  for (const Light& light : lit.lights) {
    EXPECT_EQ(light.type, LightType::Point);
    EXPECT_FLOAT_EQ(light.intensity.x, 0.2f);
    EXPECT_GT(light.position.y, bounds.max.y) << "above the scene";
  }
  EXPECT_NE(lit.lights[0].position, lit.lights[1].position);
  EXPECT_EQ(lit.objects.size(), scene.objects.size());
}

std::vector<QualityCandidate> candidates() {
  // cost rises as error falls, except blinn-phong t1, dearer and worse than gouraud t2.
  return {{{ShadingModel::Flat, 0.5f, 1}, 100, 1.0, 6.0},
          {{ShadingModel::Gouraud, 1.0f, 1}, 400, 2.0, 3.0},
          {{ShadingModel::BlinnPhong, 1.0f, 1}, 400, 3.5, 3.5},
          {{ShadingModel::Gouraud, 2.0f, 1}, 1600, 3.0, 2.0},
          {{ShadingModel::Phong, 4.0f, 1}, 6400, 9.0, 0.5}};
}

TEST(QualityChoice, LooseBoundTakesTheCheapestTightOnlyTheBest) {
  const ErrorMetric& rmse = findErrorMetric("rmse", "--metric");
  EXPECT_EQ(cheapestMeeting(candidates(), rmse, 100.0), 0u);
  EXPECT_EQ(cheapestMeeting(candidates(), rmse, 3.2), 1u);
  EXPECT_EQ(cheapestMeeting(candidates(), rmse, 2.0), 3u);  // the bound itself meets
  EXPECT_EQ(cheapestMeeting(candidates(), rmse, 0.5), 4u);
  EXPECT_FALSE(cheapestMeeting(candidates(), rmse, 0.1).has_value());
}

TEST(QualityChoice, PsnrIsAFloorNotACeiling) {
  const ErrorMetric& psnr = findErrorMetric("psnr", "--metric");
  std::vector<QualityCandidate> scored = candidates();
  for (QualityCandidate& c : scored) c.error = 50.0 - c.error;  // higher is better now
  EXPECT_EQ(cheapestMeeting(scored, psnr, 47.5), 3u);
  EXPECT_EQ(cheapestMeeting(scored, psnr, 0.0), 0u);
  EXPECT_TRUE(psnr.meets(40.0, 35.0));
  EXPECT_FALSE(psnr.meets(30.0, 35.0));
  EXPECT_THROW(findErrorMetric("ssim-ish", "--metric"), InputError);
}

TEST(QualityChoice, CandidatesFromBenchKeepTheSceneSampleCountAndLitModels) {
  std::string csv =
      "scene,mode,tessellation,msaa,triangles,device_median_ms,rmse\n"
      "spheres,unlit,1,1,10,0.5,30\n"
      "spheres,flat,1,1,10,1.0,5\n"
      "spheres,phong,2,4,40,4.0,1\n"
      "teapot,gouraud,1,1,10,0.7,2\n"
      "spheres,gouraud,2,1,40,2.0,\n";
  BenchTable table = parseBenchCsv(csv, "r.csv");
  const ErrorMetric& rmse = findErrorMetric("rmse", "--metric");
  std::vector<QualityCandidate> found = candidatesFromBench(table, "r.csv", "spheres", rmse, 1);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].point.model, ShadingModel::Flat);
  EXPECT_DOUBLE_EQ(found[0].costMs, 1.0);
  EXPECT_THROW(candidatesFromBench(table, "r.csv", "default", rmse, 1), InputError);
  EXPECT_THROW(candidatesFromBench(table, "r.csv", "spheres", findErrorMetric("psnr", "m"), 1),
               InputError);
  // A metric outside the values it can take (FLIP is 0..1) is refused.
  BenchTable negative = parseBenchCsv(
      "scene,mode,tessellation,msaa,triangles,device_median_ms,flip\n"
      "spheres,flat,1,1,10,1.0,-0.5\n",
      "r.csv");
  EXPECT_THROW(candidatesFromBench(negative, "r.csv", "spheres", findErrorMetric("flip", "m"), 1),
               InputError);
}

TEST(QualityChoice, RowsOverridingTheTextureFilterAreNotCandidates) {
  BenchTable table = parseBenchCsv(
      "scene,mode,tessellation,msaa,filter,triangles,device_median_ms,rmse\n"
      "spheres,flat,1,1,nearest,10,0.5,5\n"
      "spheres,flat,1,1,material,10,1.0,4\n",
      "r.csv");
  std::vector<QualityCandidate> found =
      candidatesFromBench(table, "r.csv", "spheres", findErrorMetric("rmse", "m"), 1);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_DOUBLE_EQ(found[0].costMs, 1.0);
}

TEST(DepthModes, NamesFormatsAndReversedZState) {
  EXPECT_EQ(namesOf(kDepthModeNames),
            (std::vector<std::string_view>{"d16", "d24", "d32f", "reversed"}));
  EXPECT_EQ(valueOf(kDepthModeNames, "reversed"), DepthMode::ReversedZ);
  EXPECT_FALSE(valueOf(kDepthModeNames, "d8").has_value());
  EXPECT_EQ(depthFormat(DepthMode::D24), VK_FORMAT_X8_D24_UNORM_PACK32);
  EXPECT_EQ(depthFormat(DepthMode::ReversedZ), VK_FORMAT_D32_SFLOAT);
  EXPECT_EQ(depthClearValue(DepthMode::ReversedZ), 0.0f);
  EXPECT_EQ(depthClearValue(DepthMode::D16), 1.0f);
  EXPECT_EQ(depthCompareOp(DepthMode::ReversedZ), VK_COMPARE_OP_GREATER_OR_EQUAL);
  EXPECT_EQ(depthCompareOp(DepthMode::D32F), VK_COMPARE_OP_LESS);
}

// depthPrecisionWarning's edge cases (the GPU agreement is in
// test_depth.cpp): a scene reaching past the far plane is clipped there,
// not "not drawn" (depth is exactly 1 on the far plane itself); the fix it
// names suits the projection and mode.
TEST(DepthModes, PrecisionWarningsNameTheRightFix) {
  Camera camera;
  camera.eye = {0.0f, 3.0f, 7.0f};
  camera.near = 0.1f;
  camera.far = 10.0f;
  for (DepthMode mode : {DepthMode::D16, DepthMode::D24, DepthMode::D32F})
    EXPECT_FALSE(depthPrecisionWarning(camera, mode, 100.0).has_value()) << depthModeName(mode);
  camera.near = 1e-7f;
  camera.far = 100.0f;
  std::optional<std::string> perspective = depthPrecisionWarning(camera, DepthMode::D32F, 10.0);
  ASSERT_TRUE(perspective.has_value());
  EXPECT_NE(perspective->find("surfaces are not drawn; raise the camera's near plane or use the "
                              "reversed depth mode"),
            std::string::npos)
      << *perspective;
  EXPECT_FALSE(depthPrecisionWarning(camera, DepthMode::ReversedZ, 10.0).has_value());
  // Orthographic depth is spread evenly: a far plane a billion units out
  // leaves reversed-Z floats steps of tens of units; the fix is the far plane.
  camera.projection = Projection::Orthographic;
  camera.near = 0.001f;
  camera.far = 1e9f;
  std::optional<std::string> orthographic =
      depthPrecisionWarning(camera, DepthMode::ReversedZ, 10.0);
  ASSERT_TRUE(orthographic.has_value());
  EXPECT_NE(orthographic->find("bring the camera's far plane nearer"), std::string::npos)
      << *orthographic;
  EXPECT_EQ(orthographic->find("reversed depth mode"), std::string::npos) << *orthographic;
}

}  // namespace
}  // namespace shadelab
