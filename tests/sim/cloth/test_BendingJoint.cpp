// The dihedral angle at a joint and its gradient against finite differences.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/cloth/BendingJoint.h"
#include "support/FiniteDifferences.h"

using namespace figment;

namespace {
// Hinge on the x axis; x2 on the +y side (z = 0), x3 folded by `fold` radians.
std::vector<Vec3> hinge(double fold) {
  return {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.4, 1, 0), Vec3(0.6, -std::cos(fold), std::sin(fold))};
}
}  // namespace

TEST(BendingJoint, FlatHingeHasZeroAngleAndFoldsAreSigned) {
  auto flat = hinge(0.0);
  EXPECT_NEAR(BendingJoint::angle(flat[0], flat[1], flat[2], flat[3]), 0.0, 1e-12);
  auto up = hinge(0.3), down = hinge(-0.3);
  const double a = BendingJoint::angle(up[0], up[1], up[2], up[3]);
  const double b = BendingJoint::angle(down[0], down[1], down[2], down[3]);
  EXPECT_NEAR(std::abs(a), 0.3, 1e-12);
  EXPECT_NEAR(a, -b, 1e-12);
}

TEST(BendingJoint, AngleIsTheSameWhicheverSectionIsFirst) {
  // Consistent winding: A = (x0, x1, x2) and B = (x1, x0, x3); swapped, B runs (x1, x0).
  const auto x = hinge(0.4);
  EXPECT_NEAR(BendingJoint::angle(x[0], x[1], x[2], x[3]), BendingJoint::angle(x[1], x[0], x[3], x[2]), 1e-12);
}

TEST(BendingJoint, AngleGradientMatchesFiniteDifferences) {
  std::vector<Vec3> x = {Vec3(0.01, 0.02, -0.01), Vec3(1.0, 0.1, 0.05), Vec3(0.3, 0.9, 0.2), Vec3(0.7, -0.8, 0.4)};
  const auto g = BendingJoint::angleGradient(x[0], x[1], x[2], x[3]);
  const auto fd = meshes::numericalGradient(
      [](const std::vector<Vec3>& p) { return BendingJoint::angle(p[0], p[1], p[2], p[3]); }, x, 1e-7);
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(g[i][k], fd[i][k], 1e-6) << "corner " << i << " axis " << k;
}

TEST(BendingJoint, AngleChangeIsMeasuredFromTheRestFoldTheShortWay) {
  const BendingJoint joint(0, 1, 2, 3, hinge(3.0));
  // From a fold of 3 rad to -3 rad is 2 pi - 6 = 0.28 rad the short way, not -6.
  EXPECT_NEAR(std::abs(joint.angleChange(hinge(-3.0))), 2 * M_PI - 6.0, 1e-9);
  EXPECT_NEAR(joint.angleChange(hinge(3.0)), 0.0, 1e-12);
}

// A section collapsed onto its edge (its opposite corner on the edge's line, or within
// 1e-17 of it) has no normal: its gradient is that of a section kMinHeightShare of the edge
// high, finite and bounded, never 1/height (caught: 1e10 N on a warm-started T-shirt's
// node, held still by the contacts, read as 1e8 kPa of pressure by the fit map). A section
// higher than that keeps its exact gradient.
TEST(BendingJoint, ACollapsedSectionsGradientIsBoundedByTheSmallestHeight) {
  const double bound = 1.0 / (BendingJoint::kMinHeightShare * 1.0);  // 1/m, for the unit edge
  for (const double height : {0.0, 1e-17, 1e-9}) {
    SCOPED_TRACE(testing::Message() << "x2 at " << height << " m from the edge");
    const std::vector<Vec3> x = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.4, height, 0), Vec3(0.6, -1, 0.2)};
    const auto g = BendingJoint::angleGradient(x[0], x[1], x[2], x[3]);
    for (int corner = 0; corner < 4; ++corner) {
      ASSERT_TRUE(g[corner].allFinite()) << "corner " << corner;
      EXPECT_LE(g[corner].norm(), 2.0 * bound) << "corner " << corner;
    }
  }
  // Ten times the smallest height: the exact 1/height along the section's normal.
  const std::vector<Vec3> x = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.4, 0.01, 0), Vec3(0.6, -1, 0.2)};
  const auto g = BendingJoint::angleGradient(x[0], x[1], x[2], x[3]);
  EXPECT_NEAR(g[2].norm(), 100.0, 1e-9);
}
