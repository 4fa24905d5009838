// Skinning by weights: a vertex on one bone moves rigidly with it; at a joint bent 90 deg
// half-and-half, the linear blend pulls the vertex in towards the joint (the collapse at
// bent elbows) while dual quaternions keep its distance.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/body/RigPose.h"
#include "sim/body/RigSkin.h"

using namespace figment;

namespace {

// Bones along -y from the origin (0 -> 1 -> 2); skin vertices 3 (on the upper bone) and
// 4 (at the joint, weighted to both), both 0.1 m in front (+z) of the axis.
HumanRig arm() {
  RigBone upper{"upper", -1, {{0}}, {{1}}, {{3, 1.0}, {4, 0.5}}};
  RigBone lower{"lower", 0, {{1}}, {{2}}, {{4, 0.5}, {5, 2.0}}};
  return HumanRig({upper, lower}, 6);
}
const std::vector<Vec3> kFile = {Vec3(0, 0, 0),      Vec3(0, -1, 0),     Vec3(0, -2, 0),
                                 Vec3(0, -0.5, 0.1), Vec3(0, -1.0, 0.1), Vec3(0, -1.5, 0.1)};

}  // namespace

TEST(RigSkin, BindsWeightsNormalisedPerSkinVertex) {
  const HumanRig rig = arm();
  const RigSkin skin = bindSkin(rig, {3, 4, 5});
  ASSERT_EQ(skin.influences.size(), 3u);
  EXPECT_EQ(skin.influences[1].size(), 2u);
  EXPECT_DOUBLE_EQ(skin.influences[2][0].second, 1.0);  // 2.0 alone, normalised
  EXPECT_THROW(bindSkin(rig, {6}), std::invalid_argument);
}

TEST(RigSkin, DualQuaternionsKeepAJointsGirthWhereTheLinearBlendPinchesIt) {
  const HumanRig rig = arm();
  const RigSkin skin = bindSkin(rig, {3, 4, 5});
  const std::vector<Vec3> rest = {kFile[3], kFile[4], kFile[5]};
  RigPose pose;
  pose.set(1, Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitX())));  // the lower bone bent 90 deg
  const auto g = boneTransforms(rig, rig.place(kFile), pose);
  const Vec3 joint(0, -1, 0);
  for (SkinningMethod method : {SkinningMethod::LinearBlend, SkinningMethod::DualQuaternion}) {
    const std::vector<Vec3> v = skinVertices(skin, g, rest, method);
    EXPECT_TRUE(v[0].isApprox(rest[0], 1e-12));                             // the upper bone did not move
    EXPECT_TRUE(v[2].isApprox(Vec3(0, -1.1, -0.5), 1e-12)) << int(method);  // rigid with the lower
  }
  const double linear = (skinVertices(skin, g, rest, SkinningMethod::LinearBlend)[1] - joint).norm();
  const double dual = (skinVertices(skin, g, rest, SkinningMethod::DualQuaternion)[1] - joint).norm();
  EXPECT_NEAR(linear, 0.1 * std::sqrt(0.5), 1e-12);  // the chord's midpoint
  EXPECT_NEAR(dual, 0.1, 1e-12);                     // on the arc
  EXPECT_THROW(skinVertices(skin, g, {rest[0]}, SkinningMethod::LinearBlend), std::invalid_argument);
}
