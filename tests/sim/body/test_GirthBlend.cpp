// Girth blending where torso parts of different girth factors meet (sim/body/GirthBlend.h),
// on a T-posed skeleton with round numbers: waist joint at y = 1.1, chest joint at 1.3
// (lower torso 1.1-1.3, upper torso 1.3-1.5, hips 0.9-1.1).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "sim/body/GirthBlend.h"
#include "support/RoundNumberSkeleton.h"

using namespace figment;
using figment::test::partIndex;
using figment::test::roundNumberTPose;

TEST(GirthBlend, TheNarrowerPartGrowsToTheWiderOneAtTheirJointAndFadesOverTheLength) {
  const Skeleton s = roundNumberTPose();
  Sizing sizing;
  sizing.chest = 0.98;  // upper torso narrower than the lower (waist 1)
  const GirthBlend blend(s, sizing, 0.04);
  const int upper = partIndex(s, "upperTorso"), lower = partIndex(s, "lowerTorso");
  // At the chest joint's plane (anywhere across it, not only near the joint) and below
  // it, where the volumes overlap: the lower torso's factor, 1 / 0.98 on top of 0.98.
  EXPECT_NEAR(blend.growth(upper, Vec3(0.15, 1.3, 0.1)), 1.0 / 0.98, 1e-12);
  EXPECT_NEAR(blend.growth(upper, Vec3(0, 1.28, 0)), 1.0 / 0.98, 1e-12);
  // Halfway through the length, halfway there; beyond it, nothing.
  EXPECT_NEAR(blend.growth(upper, Vec3(0, 1.32, 0.1)), (0.98 + 0.5 * 0.02) / 0.98, 1e-12);
  EXPECT_DOUBLE_EQ(blend.growth(upper, Vec3(0, 1.35, 0)), 1.0);
  // The wider part never changes (the skin, sized by its own factor, stays inside).
  for (double y : {1.2, 1.29, 1.3, 1.31}) EXPECT_DOUBLE_EQ(blend.growth(lower, Vec3(0, y, 0.1)), 1.0) << y;
}

TEST(GirthBlend, NothingGrowsWithEqualFactorsOrAwayFromTorsoJoints) {
  const Skeleton s = roundNumberTPose();
  Sizing sizing;
  sizing.chest = sizing.waist = sizing.hips = 1.1;
  sizing.height = 0.9;
  sizing.armLength = 1.2;
  const GirthBlend equal(s, sizing, 0.04);
  for (size_t k = 0; k < s.parts.size(); ++k)
    EXPECT_DOUBLE_EQ(equal.growth(static_cast<int>(k), Vec3(0, 1.3, 0)), 1.0) << s.parts[k].name;
  // Parts without a girth factor (the neck above a wider chest, the arms) never grow.
  Sizing wideChest;
  wideChest.chest = 1.2;
  const GirthBlend blend(s, wideChest, 0.04);
  EXPECT_DOUBLE_EQ(blend.growth(partIndex(s, "neck"), Vec3(0, 1.5, 0)), 1.0);
  EXPECT_DOUBLE_EQ(blend.growth(partIndex(s, "upperArmL"), Vec3(0.2, 1.45, 0)), 1.0);
  // The lower torso, narrower than the chest now, grows at the chest joint.
  EXPECT_NEAR(blend.growth(partIndex(s, "lowerTorso"), Vec3(0, 1.3, 0)), 1.2, 1e-12);
}

TEST(GirthBlend, HipsNarrowerThanTheWaistGrowAtTheWaistJoint) {
  const Skeleton s = roundNumberTPose();
  Sizing sizing;
  sizing.hips = 0.97;
  const GirthBlend blend(s, sizing, 0.04);
  EXPECT_NEAR(blend.growth(partIndex(s, "hips"), Vec3(0.1, 1.1, 0)), 1.0 / 0.97, 1e-12);
  EXPECT_DOUBLE_EQ(blend.growth(partIndex(s, "hips"), Vec3(0, 1.0, 0)), 1.0);
}

TEST(GirthBlend, RefusesABadLengthOrFactor) {
  const Skeleton s = roundNumberTPose();
  EXPECT_THROW(GirthBlend(s, Sizing{}, 0.0), std::invalid_argument);
  Sizing bad;
  bad.chest = 3.0;
  EXPECT_THROW(GirthBlend(s, bad, 0.04), std::invalid_argument);
}
