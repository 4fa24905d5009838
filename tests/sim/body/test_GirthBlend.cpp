// Girth blending where torso parts of different girth factors meet (sim/body/GirthBlend.h),
// on a T-posed skeleton with round numbers: waist joint at y = 1.1, chest joint at 1.3
// (lower torso 1.1-1.3, upper torso 1.3-1.5, hips 0.9-1.1).
#include "sim/body/GirthBlend.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

using namespace figment;

namespace {

Skeleton tPose() {
  return humanoidSkeleton({
      {0, 1.0, 0},      {0, 1.1, 0},      {0, 1.3, 0},      {0, 1.5, 0},     {0, 1.6, 0},    {0, 1.8, 0},  // spine
      {0.1, 0.95, 0},   {0.1, 0.5, 0},    {0.1, 0.08, 0},   {0.1, 0.0, 0.15},                                 // left leg
      {-0.1, 0.95, 0},  {-0.1, 0.5, 0},   {-0.1, 0.08, 0},  {-0.1, 0.0, 0.15},                                // right leg
      {0.2, 1.45, 0},   {0.5, 1.45, 0},   {0.75, 1.45, 0},  {0.95, 1.45, 0},                                  // left arm
      {-0.2, 1.45, 0},  {-0.5, 1.45, 0},  {-0.75, 1.45, 0}, {-0.95, 1.45, 0},                                 // right arm
      {0.05, 1.45, 0},  {-0.05, 1.45, 0}, {0, 0.9, 0}});  // shoulder bases, pelvis floor
}

int part(const Skeleton& s, const std::string& name) {
  for (size_t k = 0; k < s.parts.size(); ++k)
    if (s.parts[k].name == name) return static_cast<int>(k);
  return -1;
}

}  // namespace

TEST(GirthBlend, TheNarrowerPartGrowsToTheWiderOneAtTheirJointAndFadesOverTheLength) {
  const Skeleton s = tPose();
  Sizing sizing;
  sizing.chest = 0.98;  // upper torso narrower than the lower (waist 1)
  const GirthBlend blend(s, sizing, 0.04);
  const int upper = part(s, "upperTorso"), lower = part(s, "lowerTorso");
  // At the chest joint's plane (anywhere across it, not only near the joint) and below
  // it, where the volumes overlap: the lower torso's factor, 1 / 0.98 on top of 0.98.
  EXPECT_NEAR(blend.growth(upper, Vec3(0.15, 1.3, 0.1)), 1.0 / 0.98, 1e-12);
  EXPECT_NEAR(blend.growth(upper, Vec3(0, 1.28, 0)), 1.0 / 0.98, 1e-12);
  // Halfway through the length, halfway there; beyond it, nothing.
  EXPECT_NEAR(blend.growth(upper, Vec3(0, 1.32, 0.1)), (0.98 + 0.5 * 0.02) / 0.98, 1e-12);
  EXPECT_DOUBLE_EQ(blend.growth(upper, Vec3(0, 1.35, 0)), 1.0);
  // The wider part never changes (the skin, sized by its own factor, stays inside).
  for (double y : {1.2, 1.29, 1.3, 1.31})
    EXPECT_DOUBLE_EQ(blend.growth(lower, Vec3(0, y, 0.1)), 1.0) << y;
}

TEST(GirthBlend, NothingGrowsWithEqualFactorsOrAwayFromTorsoJoints) {
  const Skeleton s = tPose();
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
  EXPECT_DOUBLE_EQ(blend.growth(part(s, "neck"), Vec3(0, 1.5, 0)), 1.0);
  EXPECT_DOUBLE_EQ(blend.growth(part(s, "upperArmL"), Vec3(0.2, 1.45, 0)), 1.0);
  // The lower torso, narrower than the chest now, grows at the chest joint.
  EXPECT_NEAR(blend.growth(part(s, "lowerTorso"), Vec3(0, 1.3, 0)), 1.2, 1e-12);
}

TEST(GirthBlend, HipsNarrowerThanTheWaistGrowAtTheWaistJoint) {
  const Skeleton s = tPose();
  Sizing sizing;
  sizing.hips = 0.97;
  const GirthBlend blend(s, sizing, 0.04);
  EXPECT_NEAR(blend.growth(part(s, "hips"), Vec3(0.1, 1.1, 0)), 1.0 / 0.97, 1e-12);
  EXPECT_DOUBLE_EQ(blend.growth(part(s, "hips"), Vec3(0, 1.0, 0)), 1.0);
}

TEST(GirthBlend, RefusesABadLengthOrFactor) {
  const Skeleton s = tPose();
  EXPECT_THROW(GirthBlend(s, Sizing{}, 0.0), std::invalid_argument);
  Sizing bad;
  bad.chest = 3.0;
  EXPECT_THROW(GirthBlend(s, bad, 0.04), std::invalid_argument);
}
