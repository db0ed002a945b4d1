#include "gpu_test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <sstream>

namespace shadelab::test {
namespace fs = std::filesystem;

Context& sharedContext() {
  static std::unique_ptr<Context> context = [] {
    ContextOptions options;
    options.validation = true;  // always on in tests, whatever the build type
    return std::make_unique<Context>(options);
  }();
  return *context;
}

Renderer& sharedRenderer() {
  static std::unique_ptr<Renderer> renderer = std::make_unique<Renderer>(sharedContext());
  return *renderer;
}

void GpuTest::SetUp() {
  sharedContext().resetValidationReport();
}

void GpuTest::TearDown() {
  ValidationReport report = sharedContext().validationReport();
  EXPECT_EQ(report.total(), 0u) << "validation layer: " << report.errors << " error(s), "
                                << report.warnings << " warning(s); first: "
                                << (report.messages.empty() ? "" : report.messages.front());
}

ImageU8 GpuTest::render(const Scene& scene, const RenderSettings& settings) {
  return encodeSrgb8(renderer().renderToImage(scene, settings).image);
}

std::string testOutputDir() {
  fs::path dir(SHADELAB_TEST_OUTPUT_DIR);
  fs::create_directories(dir);
  return dir.string();
}

ImageU8 loadGolden(const std::string& name) {
  return readImageU8(fs::path(SHADELAB_GOLDEN_DIR) / (name + ".png"));
}

size_t valuesBeyondOneHalfStep(const std::vector<float>& a, const std::vector<float>& b) {
  EXPECT_EQ(a.size(), b.size());
  size_t count = 0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    float larger = std::max(std::abs(a[i]), std::abs(b[i]));
    // A half has 10 fraction bits; below 2^-14 its steps are 2^-24 apart.
    float step = larger < 0x1p-14f ? 0x1p-24f : std::exp2(std::floor(std::log2(larger)) - 10.0f);
    count += std::abs(a[i] - b[i]) > step;
  }
  return count;
}

::testing::AssertionResult matchesImage(const ImageU8& expected, const ImageU8& actual,
                                        const ImageTolerance& tolerance) {
  if (expected.width != actual.width || expected.height != actual.height)
    return ::testing::AssertionFailure()
           << "size " << actual.width << "x" << actual.height << " differs from expected "
           << expected.width << "x" << expected.height;
  ImageDifference difference = compareImages(expected, actual, tolerance.pixelThreshold);
  std::ostringstream numbers;
  numbers << "PSNR " << difference.psnr << " dB (min " << tolerance.minPsnr << "), RMSE "
          << difference.rmse << ", max diff " << difference.maxDifference << ", "
          << 100.0 * difference.fractionOverThreshold << "% pixels over "
          << tolerance.pixelThreshold << " (max " << 100.0 * tolerance.maxFractionOver << "%)";
  if (withinTolerance(difference, tolerance)) return ::testing::AssertionSuccess() << numbers.str();
  return ::testing::AssertionFailure() << numbers.str();
}

::testing::AssertionResult matchesGolden(const std::string& name, const ImageU8& actual,
                                         const ImageTolerance& tolerance) {
  fs::path golden = fs::path(SHADELAB_GOLDEN_DIR) / (name + ".png");
  const char* update = std::getenv("SHADELAB_UPDATE_GOLDEN");
  if (update && std::string(update) == "1") {
    writeImage(actual, golden);
    return ::testing::AssertionSuccess() << "golden " << golden << " written";
  }
  if (!fs::exists(golden))
    return ::testing::AssertionFailure()
           << "golden " << golden << " is missing (run with SHADELAB_UPDATE_GOLDEN=1 to create)";
  ImageU8 expected = loadGolden(name);
  ::testing::AssertionResult result = matchesImage(expected, actual, tolerance);
  if (!result) {
    fs::path dir = testOutputDir();
    writeImage(actual, dir / (name + ".actual.png"));
    writeImage(expected, dir / (name + ".expected.png"));
    if (expected.width == actual.width && expected.height == actual.height)
      writeImage(differenceHeatmap(expected, actual), dir / (name + ".diff.png"));
    result << "; actual/expected/diff written to " << dir;
  }
  return result;
}

}  // namespace shadelab::test
