// The presets as aims and turns of the arms and legs; the spine, head, hands and feet stay.

#include "sim/body/PosePresets.h"

#include <cmath>

namespace figment {

namespace {

constexpr double kDegree = M_PI / 180.0;
constexpr double kSittingLean = 15.0;  // deg the trunk leans back from upright, sitting

Eigen::Quaterniond turn(double degrees, const Vec3& axis) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(degrees * kDegree, axis.normalized()));
}

// side: "L" (+x) or "R" (-x).
void aim(RigPose& pose, const HumanRig& rig, const std::vector<PlacedBone>& placed, const std::string& from,
         const std::string& to, const Vec3& direction) {
  pose.set(rig.require(from), aimLimb(rig, placed, pose, from, to, direction));
}

// The arm hanging `degrees` from straight down, out to its side.
void armDown(RigPose& pose, const HumanRig& rig, const std::vector<PlacedBone>& placed, const std::string& side,
             double degrees) {
  const double sign = side == "L" ? 1.0 : -1.0;
  aim(pose, rig, placed, "upperarm01." + side, "upperarm02." + side,
      Vec3(sign * std::sin(degrees * kDegree), -std::cos(degrees * kDegree), 0.0));
}

// Turns `bone` by `turnWorld` after what it has (a world-frame turn of the limb).
void turnAfter(RigPose& pose, const HumanRig& rig, const std::string& bone, const Eigen::Quaterniond& turnWorld) {
  const int b = rig.require(bone);
  pose.set(b, turnWorld * pose.of(b));
}

void walkingStep(RigPose& pose, const HumanRig& rig, const std::vector<PlacedBone>& placed) {
  const Vec3 x = Vec3::UnitX();
  pose.set(rig.require("upperleg01.L"), turn(-25, x));  // flexion: the thigh swings to +z
  pose.set(rig.require("upperleg01.R"), turn(15, x));
  pose.set(rig.require("lowerleg01.R"), turn(25, x));  // the knee bends the shin back
  armDown(pose, rig, placed, "L", 10);
  armDown(pose, rig, placed, "R", 10);
  turnAfter(pose, rig, "upperarm01.L", turn(15, x));  // back, against the left leg
  turnAfter(pose, rig, "upperarm01.R", turn(-15, x));
}

void sitting(RigPose& pose, const HumanRig& rig, const std::vector<PlacedBone>& placed) {
  const Vec3 x = Vec3::UnitX();
  pose.set(rig.require("spine05"), turn(-kSittingLean, x));  // leaning back opens the hips' fold
  for (const std::string side : {"L", "R"}) {
    const double sign = side == "L" ? 1.0 : -1.0;
    aim(pose, rig, placed, "upperleg01." + side, "upperleg02." + side, Vec3(sign * 0.1, 0.0, 1.0));
    aim(pose, rig, placed, "lowerleg01." + side, "lowerleg02." + side, -Vec3::UnitY());
    armDown(pose, rig, placed, side, 20);
    pose.set(rig.require("lowerarm01." + side), turn(-30, x));
  }
}

}  // namespace

Eigen::Quaterniond aimLimb(const HumanRig& rig, const std::vector<PlacedBone>& placed, const RigPose& pose,
                           const std::string& from, const std::string& to, const Vec3& direction) {
  const int first = rig.require(from), last = rig.require(to);
  const Vec3 rest = placed[last].tail - placed[first].head;
  const int parent = rig.bones()[first].parent;
  Eigen::Quaterniond parentTurn = Eigen::Quaterniond::Identity();
  if (parent >= 0) parentTurn = Eigen::Quaterniond(boneTransforms(rig, placed, pose)[parent].rotation());
  return Eigen::Quaterniond::FromTwoVectors(rest, parentTurn.conjugate() * direction.normalized());
}

RigPose presetPose(PosePreset preset, const HumanRig& rig, const std::vector<PlacedBone>& placed) {
  RigPose pose;
  switch (preset) {
    case PosePreset::APose:
      break;
    case PosePreset::ArmsDown:
      armDown(pose, rig, placed, "L", 10);
      armDown(pose, rig, placed, "R", 10);
      break;
    case PosePreset::ArmRaised:
      aim(pose, rig, placed, "upperarm01.L", "upperarm02.L", Vec3::UnitX());
      aim(pose, rig, placed, "lowerarm01.L", "lowerarm02.L", Vec3::UnitY());
      break;
    case PosePreset::WalkingStep:
      walkingStep(pose, rig, placed);
      break;
    case PosePreset::Sitting:
      sitting(pose, rig, placed);
      break;
  }
  return pose;
}

}  // namespace figment
