// Posing and sizing the jointed mannequin (sim/body/Posing.h) on a small T-posed humanoid
// skeleton whose joints sit on round numbers: y up, floor at y = 0, arms along +-x.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "sim/body/Posing.h"
#include "sim/body/Skinning.h"
#include "sim/collision/CollisionVolume.h"
#include "sim/collision/VolumeSetCollider.h"
#include "support/RoundNumberSkeleton.h"
#include "support/TestCapsules.h"

using namespace figment;
using figment::test::partIndex;
using figment::test::roundNumberTPose;

namespace {
Pose rotate(const Skeleton& s, const std::string& joint, const Eigen::Quaterniond& q, Pose pose = {}) {
  pose.rotations.resize(s.joints.size(), Eigen::Quaterniond::Identity());
  pose.rotations[s.joint(joint)] = q;
  return pose;
}

Eigen::Quaterniond about(const Vec3& axis, double angle) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis));
}

Eigen::Affine3d rotationAbout(const Vec3& centre, const Eigen::Quaterniond& q) {
  return Eigen::Translation3d(centre) * q * Eigen::Translation3d(-centre);
}

using test::segmentCapsule;
}  // namespace

TEST(Posing, IdentityPoseAndUnitSizingGiveIdentityTransforms) {
  const Skeleton s = roundNumberTPose();
  for (const Pose& pose : {Pose{}, rotate(s, "elbowL", Eigen::Quaterniond::Identity())}) {
    for (const Eigen::Affine3d& t : partTransforms(s, pose, Sizing{}))
      EXPECT_EQ(t.matrix(), Eigen::Matrix4d::Identity());
    const std::vector<Vec3> joints = posedJoints(s, pose, Sizing{});
    for (size_t j = 0; j < joints.size(); ++j) EXPECT_EQ(joints[j], s.joints[j].position);
  }
}

TEST(Posing, ShoulderRotationMovesTheWholeArm) {
  const Skeleton s = roundNumberTPose();
  const Eigen::Quaterniond q = about(Vec3::UnitZ(), M_PI / 2);
  const Pose pose = rotate(s, "shoulderL", q);
  const std::vector<Eigen::Affine3d> transforms = partTransforms(s, pose, Sizing{});
  const Eigen::Affine3d expected = rotationAbout(s["shoulderL"].position, q);
  for (const char* name : {"upperArmL", "forearmL", "handL"})
    EXPECT_TRUE(transforms[partIndex(s, name)].isApprox(expected, 1e-14)) << name;
  for (const char* name : {"upperTorso", "lowerTorso", "hips", "head", "upperArmR", "thighL"})
    EXPECT_EQ(transforms[partIndex(s, name)].matrix(), Eigen::Matrix4d::Identity()) << name;
  const std::vector<Vec3> joints = posedJoints(s, pose, Sizing{});
  EXPECT_LT((joints[s.joint("elbowL")] - Vec3(0.2, 1.75, 0)).norm(), 1e-14);
  EXPECT_LT((joints[s.joint("fingertipL")] - Vec3(0.2, 2.2, 0)).norm(), 1e-14);
  EXPECT_LT((joints[s.joint("shoulderL")] - s["shoulderL"].position).norm(), 1e-15);

  // The forearm's volume and the mesh vertices on the forearm move together: a vertex
  // keeps its distance to the volume's surface.
  const int forearm = partIndex(s, "forearmL");
  const VolumeSetCollider rest({{forearm, makeVolume(segmentCapsule(s["elbowL"].position, s["wristL"].position, 0.04)),
                                 Eigen::Affine3d::Identity()}});
  const VolumeSetCollider posed(
      {{forearm, makeVolume(segmentCapsule(s["elbowL"].position, s["wristL"].position, 0.04)), transforms[forearm]}});
  const std::vector<Vec3> vertices = {{0.625, 1.47, 0.01}, {0.6, 1.45, -0.045}, {0.65, 1.41, 0.0}};
  const std::vector<Vec3> skinned = skin(skinWeights(s, vertices), transforms, vertices);
  for (size_t v = 0; v < vertices.size(); ++v)
    EXPECT_NEAR(posed.worldVolume(0).nearest(skinned[v]).distance, rest.worldVolume(0).nearest(vertices[v]).distance,
                1e-9);
}

TEST(Posing, RotationsComposeDownTheChain) {
  const Skeleton s = roundNumberTPose();
  const Eigen::Quaterniond shoulder = about(Vec3::UnitZ(), M_PI / 2), elbow = about(Vec3::UnitY(), M_PI / 2);
  const Pose pose = rotate(s, "elbowL", elbow, rotate(s, "shoulderL", shoulder));
  const Vec3 sh = s["shoulderL"].position, el = s["elbowL"].position, wr = s["wristL"].position,
             tip = s["fingertipL"].position;
  const std::vector<Vec3> joints = posedJoints(s, pose, Sizing{});
  EXPECT_LT((joints[s.joint("elbowL")] - (sh + shoulder * (el - sh))).norm(), 1e-14);
  EXPECT_LT((joints[s.joint("wristL")] - (sh + shoulder * ((el - sh) + elbow * (wr - el)))).norm(), 1e-14);
  EXPECT_LT((joints[s.joint("fingertipL")] - (sh + shoulder * ((el - sh) + elbow * (tip - el)))).norm(), 1e-14);
  const std::vector<Eigen::Affine3d> transforms = partTransforms(s, pose, Sizing{});
  const Eigen::Affine3d forearm = rotationAbout(sh, shoulder) * rotationAbout(el, elbow);
  EXPECT_TRUE(transforms[partIndex(s, "forearmL")].isApprox(forearm, 1e-14));
  EXPECT_TRUE(transforms[partIndex(s, "handL")].isApprox(forearm, 1e-14));
  EXPECT_TRUE(transforms[partIndex(s, "upperArmL")].isApprox(rotationAbout(sh, shoulder), 1e-14));
}

TEST(Posing, PartsStayAttachedUnderAnyPoseAndSizing) {
  const Skeleton s = roundNumberTPose();
  Pose pose;
  for (size_t j = 0; j < s.joints.size(); ++j)
    pose.rotations.push_back(about(Vec3(std::sin(j), std::cos(3.0 * j), 0.5).normalized(), 0.1 * j));
  const Sizing sizing{1.05, 1.1, 0.9, 1.2, 1.15};
  const std::vector<Eigen::Affine3d> transforms = partTransforms(s, pose, sizing);
  const std::vector<Vec3> joints = posedJoints(s, pose, sizing);
  for (size_t k = 0; k < s.parts.size(); ++k) {
    const BodyPart& p = s.parts[k];
    EXPECT_LT((transforms[k] * s.joints[p.from].position - joints[p.from]).norm(), 1e-12) << p.name;
    EXPECT_LT((transforms[k] * s.joints[p.to].position - joints[p.to]).norm(), 1e-12) << p.name;
  }
}

TEST(Posing, HeightScalesTheBodyAboutTheFloor) {
  const Skeleton s = roundNumberTPose();
  const std::vector<Vec3> joints = posedJoints(s, Pose{}, Sizing{1.1});
  double low = 1e9, high = -1e9;
  for (size_t j = 0; j < joints.size(); ++j) {
    EXPECT_LT((joints[j] - 1.1 * s.joints[j].position).norm(), 1e-14);  // the floor point is the origin
    low = std::min(low, joints[j].y()), high = std::max(high, joints[j].y());
  }
  EXPECT_NEAR(low, 0.0, 1e-15);  // the feet stay on the floor
  EXPECT_NEAR(high - low, 1.1 * 1.8, 1e-14);
  for (const Eigen::Affine3d& t : partTransforms(s, Pose{}, Sizing{1.1}))
    EXPECT_TRUE(t.linear().isApprox(1.1 * Eigen::Matrix3d::Identity(), 1e-15));
}

TEST(Posing, ArmLengthStretchesTheArmsAlongTheirBones) {
  const Skeleton s = roundNumberTPose();
  Sizing sizing;
  sizing.armLength = 1.2;
  const std::vector<Vec3> joints = posedJoints(s, Pose{}, sizing);
  const Vec3 shoulder = joints[s.joint("shoulderL")], tip = joints[s.joint("fingertipL")];
  EXPECT_EQ(shoulder, s["shoulderL"].position);
  EXPECT_NEAR((tip - shoulder).norm(), 1.2 * 0.75, 1e-14);
  EXPECT_NEAR((joints[s.joint("fingertipR")] - joints[s.joint("shoulderR")]).norm(), 1.2 * 0.75, 1e-14);
  // Along, not across: a point 4 cm off the forearm's bone stays 4 cm off it.
  const Eigen::Affine3d forearm = partTransforms(s, Pose{}, sizing)[partIndex(s, "forearmL")];
  const Vec3 mid = forearm * Vec3(0.625, 1.45, 0.0), off = forearm * Vec3(0.625, 1.49, 0.0);
  EXPECT_NEAR((off - mid).norm(), 0.04, 1e-14);
  EXPECT_NEAR(mid.x(), 0.2 + 1.2 * 0.425, 1e-14);
  // The legs and torso are untouched.
  EXPECT_EQ(joints[s.joint("toeL")], s["toeL"].position);
}

TEST(Posing, GirthWidensTheTorsoAndCarriesTheLimbsOut) {
  const Skeleton s = roundNumberTPose();
  Sizing sizing;
  sizing.chest = 1.1, sizing.hips = 1.2;
  const std::vector<Eigen::Affine3d> transforms = partTransforms(s, Pose{}, sizing);
  const std::vector<Vec3> joints = posedJoints(s, Pose{}, sizing);
  // The upper torso is 10 % wider across its (vertical) axis, not taller.
  EXPECT_LT((transforms[partIndex(s, "upperTorso")] * Vec3(0.1, 1.4, 0.05) - Vec3(0.11, 1.4, 0.055)).norm(), 1e-14);
  EXPECT_LT((transforms[partIndex(s, "hips")] * Vec3(0.1, 1.0, 0.05) - Vec3(0.12, 1.0, 0.06)).norm(), 1e-14);
  EXPECT_EQ(transforms[partIndex(s, "lowerTorso")].matrix(), Eigen::Matrix4d::Identity());
  // The shoulders move out with the chest, the hip joints with the hips, the limbs with them.
  EXPECT_LT((joints[s.joint("shoulderL")] - Vec3(0.22, 1.45, 0)).norm(), 1e-14);
  EXPECT_LT((joints[s.joint("shoulderR")] - Vec3(-0.22, 1.45, 0)).norm(), 1e-14);
  EXPECT_LT((joints[s.joint("hipL")] - Vec3(0.12, 0.95, 0)).norm(), 1e-14);
  EXPECT_LT((transforms[partIndex(s, "upperArmL")].translation() - Vec3(0.02, 0, 0)).norm(), 1e-14);
  EXPECT_TRUE(transforms[partIndex(s, "upperArmL")].linear().isIdentity(1e-15));
  EXPECT_LT((joints[s.joint("kneeR")] - Vec3(-0.12, 0.5, 0)).norm(), 1e-14);
  // The spine stays where it was.
  for (const char* joint : {"waist", "chest", "neckBase", "headTop"})
    EXPECT_EQ(joints[s.joint(joint)], s[joint].position) << joint;
}

TEST(Posing, RejectsBadFactorsAndPoses) {
  const Skeleton s = roundNumberTPose();
  for (const char* name : {"height", "chest", "waist", "hips", "armLength"}) {
    for (const double value : {0.4, 2.5}) {
      Sizing sizing;
      const std::string field = name;
      (field == "height"  ? sizing.height
       : field == "chest" ? sizing.chest
       : field == "waist" ? sizing.waist
       : field == "hips"  ? sizing.hips
                          : sizing.armLength) = value;
      try {
        partTransforms(s, Pose{}, sizing);
        ADD_FAILURE() << name << " = " << value << " accepted";
      } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(value == 0.4 ? "0.4" : "2.5"), std::string::npos) << e.what();
      }
    }
  }
  Pose tooMany;
  tooMany.rotations.resize(s.joints.size() + 1, Eigen::Quaterniond::Identity());
  EXPECT_THROW(partTransforms(s, tooMany, Sizing{}), std::invalid_argument);
  EXPECT_THROW(posedJoints(s, rotate(s, "kneeL", Eigen::Quaterniond(0, 0, 0, 0)), Sizing{}), std::invalid_argument);
  EXPECT_NO_THROW(partTransforms(s, Pose{}, Sizing{0.5, 2.0, 1.0, 1.0, 1.0}));
}

TEST(Posing, JointsAreCarriedByTheirBonesOrTorsoParts) {
  const Skeleton s = roundNumberTPose();
  const std::vector<int> carriers = jointCarriers(s);
  EXPECT_EQ(carriers[s.joint("pelvis")], -1);
  EXPECT_EQ(carriers[s.joint("elbowL")], partIndex(s, "upperArmL"));
  EXPECT_EQ(carriers[s.joint("shoulderL")], partIndex(s, "upperTorso"));
  EXPECT_EQ(carriers[s.joint("shoulderBaseR")], partIndex(s, "upperTorso"));
  EXPECT_EQ(carriers[s.joint("hipR")], partIndex(s, "hips"));
  EXPECT_EQ(carriers[s.joint("chest")], partIndex(s, "lowerTorso"));
}
