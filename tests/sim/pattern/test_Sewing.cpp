// Sewing a pattern's panels around a body: the seams close, their nodes merge once, the
// body holds the cloth out, and the rest shape stays the flat panels.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numeric>

#include "sim/collision/CapsuleCollider.h"
#include "sim/core/BoundaryLoops.h"
#include "sim/pattern/Sewing.h"
#include "support/TestCapsules.h"
#include "support/TubePattern.h"

namespace figment {
namespace {

ClothParameters implicitCotton() {
  ClothParameters p;
  p.integrator = Integrator::Implicit;
  p.timeStep = 0.05;
  p.maxTime = 5.0;
  return p;
}

constexpr double kBodyRadius = 0.1;  // m
std::shared_ptr<const Collider> upright() {
  return std::make_shared<CapsuleCollider>(test::segmentCapsule(Vec3(0, 0.2, 0), Vec3(0, 1.2, 0), kBodyRadius));
}

// 40 cm panels make an 80 cm tube (radius 12.7 cm) around a 10 cm capsule; placed 40 cm
// apart, each side seam starts 40 cm open.
UnsewnGarment tube() {
  return test::tubePattern(10, 6, 0.4, 0.3, 0.9, 0.4);
}

TEST(Sewing, ClosesEverySeamAndMergesItsNodesOnce) {
  const UnsewnGarment garment = tube();
  EXPECT_NEAR(largestSeamGap(garment, garment.placed.vertices), 0.4, 1e-12);  // the control: it starts open
  const SewnGarment sewn = sewPanels(garment, implicitCotton(), upright());
  EXPECT_TRUE(sewn.openSeams.empty());
  EXPECT_LE(sewn.closedGap, SewingParameters{}.closedGap);
  // Each side seam's 7 pairs become 7 nodes: 2 x 77 panel nodes, 14 merged away.
  EXPECT_EQ(sewn.positions.size(), 2u * 77u - 14u);
  EXPECT_EQ(sewn.droppedTriangles, 0);
  for (const auto& [a, b] : garment.seams) EXPECT_EQ(sewn.nodeOf[a], sewn.nodeOf[b]);
  // One closed tube: its boundary is the top and the bottom ring, nothing along the sides.
  EXPECT_EQ(boundaryLoops(sewn.rest.triangles()).size(), 2u);
}

TEST(Sewing, TheBodyHoldsTheClothOut) {
  const SewnGarment sewn = sewPanels(tube(), implicitCotton(), upright());
  const ClothParameters p = implicitCotton();
  for (const Vec3& x : sewn.positions)
    EXPECT_GE(std::hypot(x.x(), x.z()), kBodyRadius + p.clearance - 1e-3) << x.transpose();
}

TEST(Sewing, KeepsTheFlatPanelsAsTheRestShape) {
  const UnsewnGarment garment = tube();
  const SewnGarment sewn = sewPanels(garment, implicitCotton(), upright());
  // Every sewn triangle rests as its panel has it: 2 panels of 40 x 30 cm.
  double area = 0.0;
  for (size_t t = 0; t < sewn.rest.triangles().size(); ++t) {
    const auto& c = sewn.rest.corners(t);
    area += 0.5 * (c[1] - c[0]).cross(c[2] - c[0]).norm();
  }
  EXPECT_NEAR(area, 2 * 0.4 * 0.3, 1e-12);
}

TEST(Sewing, LeavesASeamOpenWhenTimeRunsOutAndSaysSo) {
  SewingParameters quick;
  quick.maxTime = 0.05;  // one step: a 40 cm gap cannot close
  quick.snapGap = quick.closedGap;
  const SewnGarment sewn = sewPanels(tube(), implicitCotton(), upright(), quick);
  EXPECT_FALSE(sewn.openSeams.empty());
  EXPECT_EQ(sewn.sewing.iterations, 1);
}

TEST(Sewing, PullsHarderWhereTheClothMustStretchToClose) {
  // 2 x 30 cm panels round a capsule of girth 2 pi (10.3 cm) = 64.7 cm: the tube closes only
  // stretched by 8 %, which a pull scaled to the nodes' mass cannot do.
  const UnsewnGarment tight = test::tubePattern(8, 6, 0.3, 0.3, 0.9, 0.4);
  SewingParameters weak;
  weak.maxStrength = 1.0;  // the control: never pulls harder
  weak.snapGap = weak.closedGap;
  EXPECT_FALSE(sewPanels(tight, implicitCotton(), upright(), weak).openSeams.empty());
  const SewnGarment sewn = sewPanels(tight, implicitCotton(), upright());
  EXPECT_TRUE(sewn.openSeams.empty());
  EXPECT_GT(sewn.strength, 1.0);
  EXPECT_LE(sewn.closedGap, SewingParameters{}.snapGap);
}

TEST(Sewing, RefusesAGarmentWithoutSeamsNamingIt) {
  UnsewnGarment garment = tube();
  garment.seams.clear();
  try {
    sewPanels(garment, implicitCotton(), upright());
    FAIL() << "sewed a garment without seams";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "the pattern's garment has no seams to sew");
  }
  SewingParameters bad;
  bad.closedGap = -1.0;
  EXPECT_THROW(sewPanels(tube(), implicitCotton(), upright(), bad), std::invalid_argument);
}

TEST(Sewing, AGapStallsAfterItsStepsOfClosingByLessThanTheRule) {
  SewingParameters rule;  // 10 %, 3 steps
  StallCount stall(rule);
  EXPECT_FALSE(stall.stalledAfter(0.100, 0.095));  // 5 %: one
  EXPECT_FALSE(stall.stalledAfter(0.095, 0.090));  // two
  EXPECT_FALSE(stall.stalledAfter(0.090, 0.070));  // 22 %: closing again, none
  EXPECT_FALSE(stall.stalledAfter(0.070, 0.069));
  EXPECT_FALSE(stall.stalledAfter(0.069, 0.069));
  EXPECT_TRUE(stall.stalledAfter(0.069, 0.0695));  // a gap that widens counts too
  stall.restart();
  EXPECT_FALSE(stall.stalledAfter(0.0695, 0.069));
}

}  // namespace
}  // namespace figment
