// Study billboard-failures' headline numbers, asserted with the study's own
// measurement code at a smaller size: the cylindrical kind's coverage
// failing from above, and the ground's cut against where an overlay without
// depth would end.
#include "gpu_test_support.h"
#include "measure/billboard_failures.h"

namespace shadelab::test {
namespace {

constexpr uint32_t kWidth = 160;
constexpr uint32_t kHeight = 90;

using BillboardFailuresStudy = GpuTest;

// Seen from straight above, a cylindrical billboard is edge-on: no pixels,
// where a spherical one keeps its whole area. Level, both cover the exact
// orthographic area to within the edge pixels.
TEST_F(BillboardFailuresStudy, CylindricalGoesEdgeOnSphericalKeepsItsArea) {
  for (BillboardKind kind : {BillboardKind::Cylindrical, BillboardKind::Spherical}) {
    for (float elevation : {0.0f, 45.0f}) {
      BillboardCoverage c = measureBillboardCoverage(renderer(), kind, elevation, kWidth, kHeight);
      EXPECT_NEAR(double(c.covered), c.expected, 0.04 * c.fullArea)
          << nameOf(kBillboardKindNames, kind) << " at " << elevation;
    }
  }
  BillboardCoverage cylindrical =
      measureBillboardCoverage(renderer(), BillboardKind::Cylindrical, 90.0f, kWidth, kHeight);
  BillboardCoverage spherical =
      measureBillboardCoverage(renderer(), BillboardKind::Spherical, 90.0f, kWidth, kHeight);
  EXPECT_NEAR(double(spherical.covered), spherical.fullArea, 0.04 * spherical.fullArea);
  EXPECT_LT(double(cylindrical.covered), 0.01 * cylindrical.fullArea)
      << "cylindrical from above: " << cylindrical.covered << " pixels";
}

// The ground cuts a sunk quad along the projected line where the quad's
// plane meets y = 0, straight and within a pixel. Must-fail twin: the quad's
// own bottom edge, where a billboard drawn without depth would end, is rows
// away from it.
TEST_F(BillboardFailuresStudy, GroundCutsASunkQuadAlongTheExpectedLine) {
  for (BillboardKind kind : {BillboardKind::Cylindrical, BillboardKind::Spherical}) {
    for (float elevation : {20.0f, 50.0f}) {
      SCOPED_TRACE(std::string(nameOf(kBillboardKindNames, kind)) + " at " +
                   std::to_string(elevation));
      BillboardGroundCut cut = measureGroundCut(renderer(), kind, elevation, 0.3f, kWidth, kHeight);
      ASSERT_GT(cut.columns, 20u);
      EXPECT_LE(cut.maxRowError, 1.0);
      EXPECT_LE(cut.maxLineResidual, 1.0);
      EXPECT_GT(cut.bottomEdgeGap, 3.0);
    }
  }
  // The spherical quad leans back as the eye rises and sinks further.
  BillboardGroundCut cylindrical =
      measureGroundCut(renderer(), BillboardKind::Cylindrical, 70.0f, 0.3f, kWidth, kHeight);
  BillboardGroundCut spherical =
      measureGroundCut(renderer(), BillboardKind::Spherical, 70.0f, 0.3f, kWidth, kHeight);
  EXPECT_LT(spherical.visibleShare(), 0.5 * cylindrical.visibleShare());
}

}  // namespace
}  // namespace shadelab::test
