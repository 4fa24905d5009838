// Forward kinematics of a rig: a turn about a bone's head carries the bones below it, and
// a pose part way is each rotation slerped from the identity.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/body/RigPose.h"

using namespace figment;

namespace {

// Three file vertices on the y axis at 0, -1, -2 m: an upper and a lower "leg".
HumanRig leg() {
  RigBone upper{"upper", -1, {{0}}, {{1}}, {}};
  RigBone lower{"lower", 0, {{1}}, {{2}}, {}};
  return HumanRig({upper, lower}, 3);
}
const std::vector<Vec3> kVertices = {Vec3(0, 0, 0), Vec3(0, -1, 0), Vec3(0, -2, 0)};

}  // namespace

TEST(RigPose, AJointTurnsTheBonesBelowIt) {
  const HumanRig rig = leg();
  const std::vector<PlacedBone> placed = rig.place(kVertices);
  RigPose pose;
  pose.set(0, Eigen::Quaterniond(Eigen::AngleAxisd(-M_PI / 2, Vec3::UnitX())));  // the hip flexed: forward, +z
  pose.set(1, Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitX())));   // the knee bent back
  const auto g = boneTransforms(rig, placed, pose);
  EXPECT_TRUE((g[0] * placed[0].tail).isApprox(Vec3(0, 0, 1), 1e-12));
  EXPECT_TRUE((g[1] * placed[1].tail).isApprox(Vec3(0, -1, 1), 1e-12));  // the shin straight down
  const auto half = boneTransforms(rig, placed, pose.partway(0.5));
  EXPECT_TRUE((half[0] * placed[0].tail).isApprox(Vec3(0, -std::sqrt(0.5), std::sqrt(0.5)), 1e-12));
}

TEST(RigPose, BadInputIsNamed) {
  const HumanRig rig = leg();
  RigPose pose;
  pose.set(1, Eigen::Quaterniond(0, 0, 0, 0));
  EXPECT_THROW(boneTransforms(rig, rig.place(kVertices), pose), std::invalid_argument);
  EXPECT_THROW(boneTransforms(rig, {}, RigPose{}), std::invalid_argument);
  EXPECT_THROW(pose.set(-1, Eigen::Quaterniond::Identity()), std::invalid_argument);
}
