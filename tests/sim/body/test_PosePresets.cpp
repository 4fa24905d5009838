// Aiming a limb: the smallest turn that points it along a direction, allowing for what
// its parents turned. The presets on MakeHuman's own rig: tests/io/test_MakeHumanRig.cpp.
#include <gtest/gtest.h>

#include "sim/body/PosePresets.h"

using namespace figment;

TEST(PosePresets, AimLimbPointsTheLimbAlongTheDirectionAfterItsParents) {
  // a "shoulder" bone, then an upper arm and a forearm hanging along -y
  const HumanRig rig({RigBone{"shoulder", -1, {{0}}, {{1}}, {}}, RigBone{"upper", 0, {{1}}, {{2}}, {}},
                      RigBone{"fore", 1, {{2}}, {{3}}, {}}},
                     4);
  const std::vector<PlacedBone> placed = rig.place({Vec3(0, 1, 0), Vec3(0, 0, 0), Vec3(0, -1, 0), Vec3(0, -2, 0)});
  RigPose pose;
  pose.set(0, Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Vec3::UnitY())));  // a parent's turn
  pose.set(1, aimLimb(rig, placed, pose, "upper", "upper", Vec3::UnitX()));
  pose.set(2, aimLimb(rig, placed, pose, "fore", "fore", Vec3::UnitY()));
  const auto g = boneTransforms(rig, placed, pose);
  EXPECT_TRUE((g[1] * placed[1].tail - g[1] * placed[1].head).normalized().isApprox(Vec3::UnitX(), 1e-12));
  EXPECT_TRUE((g[2] * placed[2].tail - g[2] * placed[2].head).normalized().isApprox(Vec3::UnitY(), 1e-12));
  EXPECT_THROW(aimLimb(rig, placed, pose, "hand", "fore", Vec3::UnitX()), std::invalid_argument);
  EXPECT_THROW(presetPose(PosePreset::ArmRaised, rig, placed), std::invalid_argument);  // no upperarm01.L
}
