#pragma once
// Shared by the GPU tests: one Vulkan context with the validation layer on
// for the whole test program, a check that no test produced a validation
// message, and golden-image comparison with a stated tolerance.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/metrics/metrics.h"
#include "core/vulkan/context.h"
#include "passes/renderer.h"

namespace shadelab::test {

Context& sharedContext();
Renderer& sharedRenderer();

// Every GPU test derives from this: TearDown fails the test on any validation
// message produced while it ran.
class GpuTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;
  Context& context() { return sharedContext(); }
  Renderer& renderer() { return sharedRenderer(); }
  ImageU8 render(const Scene& scene, const RenderSettings& settings);
};

// The tolerance every golden comparison uses unless a test states another:
// lavapipe output is bit-identical here, the slack is for other Mesa/LLVM
// versions. PSNR >= 40 dB and at most 0.5% of pixels off by more than 4/255.
inline constexpr ImageTolerance kGoldenTolerance{40.0, 4, 0.005};

// Compares with tests/golden/<name>.png. On failure writes <name>.actual.png,
// <name>.expected.png and <name>.diff.png to the test output folder. With
// SHADELAB_UPDATE_GOLDEN=1 in the environment, (re)writes the golden instead.
::testing::AssertionResult matchesGolden(const std::string& name, const ImageU8& actual,
                                         const ImageTolerance& tolerance = kGoldenTolerance);
// The same comparison against an explicit expected image (no files written).
::testing::AssertionResult matchesImage(const ImageU8& expected, const ImageU8& actual,
                                        const ImageTolerance& tolerance = kGoldenTolerance);
ImageU8 loadGolden(const std::string& name);
// How many values of `a` and `b` (linear RGBA, read back from the RGBA16F
// target) are more than one half-float step apart.
size_t valuesBeyondOneHalfStep(const std::vector<float>& a, const std::vector<float>& b);
std::string testOutputDir();

}  // namespace shadelab::test
