// A panel placed along a limb starts clear of it: moved along its normal, away from the
// limb's part within its outline, until that lies behind it.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "sim/pattern/LimbClearance.h"
#include "support/TestMeshes.h"

namespace figment {
namespace {

constexpr double kRadius = 0.05;
// An "arm": a sphere of 5 cm about (0.15, 1.05, 0).
const TriangleMesh kArm = meshes::sphere(kRadius, 32, 16, Vec3(0.15, 1.05, 0.0));

// A 0.3 x 0.2 m rectangle whose middle lies over the arm, at depth z, facing +z (or -z
// when `facingBack`, turned half round about y).
Panel sleevePanel(double z, bool facingBack = false) {
  Panel p;
  p.vertices = {Vec2(-0.15, -0.1), Vec2(0.15, -0.1), Vec2(0.15, 0.1), Vec2(-0.15, 0.1)};
  for (int k = 0; k < 4; ++k) p.edges.push_back({k, (k + 1) % 4, {}});
  if (facingBack) p.rotation = Eigen::AngleAxisd(M_PI, Vec3::UnitY()).toRotationMatrix();
  p.translation = Vec3(0.15, 1.05, z);
  return p;
}

TEST(LimbClearance, MovesAPanelThroughTheLimbOutInFrontOfIt) {
  Panel front = sleevePanel(0.03);  // through the arm, nearer its front
  moveClearOf(front, kArm, 0.01);
  EXPECT_NEAR(front.translation.z(), kRadius + 0.01, 1e-9);
  EXPECT_NEAR(front.translation.x(), 0.15, 1e-12);  // along its normal only
  EXPECT_NEAR(front.translation.y(), 1.05, 1e-12);
}

TEST(LimbClearance, MovesABackPanelBehindTheLimbWhicheverWayItFaces) {
  for (bool facingBack : {false, true}) {
    Panel back = sleevePanel(-0.02, facingBack);
    moveClearOf(back, kArm, 0.01);
    EXPECT_NEAR(back.translation.z(), -kRadius - 0.01, 1e-9) << facingBack;
  }
}

TEST(LimbClearance, LeavesAPanelClearOfTheLimbOrBesideItWhereItIs) {
  EXPECT_EQ(clearingShift(sleevePanel(0.2), kArm, 0.01), 0.0);  // already in front
  Panel beside = sleevePanel(0.0);
  beside.translation.x() = 1.0;  // the arm is not within its outline
  EXPECT_EQ(clearingShift(beside, kArm, 0.01), 0.0);
}

}  // namespace
}  // namespace figment
