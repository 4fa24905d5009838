// A rig's joints placed from the mesh's vertices (the mean of those each names), so they
// follow a morph; a rig whose parents come late or that names missing vertices is refused.
#include <gtest/gtest.h>

#include "sim/body/HumanRig.h"

using namespace figment;

TEST(HumanRig, JointsAreTheMeanOfTheirVertices) {
  const HumanRig rig({RigBone{"a", -1, {{0, 1}}, {{2}}, {}}}, 3);
  const std::vector<PlacedBone> placed = rig.place({Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 5, 0)});
  EXPECT_TRUE(placed[0].head.isApprox(Vec3(1, 0, 0)));
  EXPECT_TRUE(placed[0].tail.isApprox(Vec3(0, 5, 0)));
  const std::vector<PlacedBone> moved = rig.place({Vec3(0, 1, 0), Vec3(2, 1, 0), Vec3(0, 6, 0)});
  EXPECT_TRUE(moved[0].head.isApprox(Vec3(1, 1, 0)));  // follows the vertices
  EXPECT_EQ(rig.find("a"), 0);
  EXPECT_EQ(rig.find("b"), -1);
  EXPECT_THROW(rig.require("b"), std::invalid_argument);
  EXPECT_THROW(rig.place({Vec3::Zero()}), std::invalid_argument);
}

TEST(HumanRig, RefusesBadRigs) {
  EXPECT_THROW(HumanRig({RigBone{"a", 0, {{0}}, {{0}}, {}}}, 1), std::invalid_argument);  // its own parent
  EXPECT_THROW(HumanRig({RigBone{"a", -1, {{3}}, {{0}}, {}}}, 1), std::invalid_argument);
  EXPECT_THROW(HumanRig({RigBone{"a", -1, {}, {{0}}, {}}}, 1), std::invalid_argument);
  EXPECT_THROW(HumanRig({RigBone{"a", -1, {{0}}, {{0}}, {{0, NAN}}}}, 1), std::invalid_argument);
}
