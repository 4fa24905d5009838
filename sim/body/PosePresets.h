#pragma once
// Named poses of MakeHuman's rig (sim/body/RigPose.h), made for the body at hand: a limb
// is aimed along a direction (the smallest turn of its rest direction onto it), so a
// heavier body's arms hang as a lighter one's do, whatever angle its rest pose had them at.
// Frame: metres, y up, the body facing +z, its left (bones ".L") at +x.
//
//   A_POSE        the rest pose (MakeHuman's arms about 45 deg from the sides)
//   ARMS_DOWN     upper arms 10 deg from hanging straight down, elbows as at rest
//   ARM_RAISED    left upper arm raised 90 deg from hanging (sideways, level) and its
//                 forearm pointing straight up, the hand above the shoulder; the right arm
//                 as at rest (brought down to the side it would pinch a sleeve's armhole
//                 between arm and torso, where cloth never comes to rest)
//   WALKING_STEP  left hip flexed 25 deg, right hip extended 15 deg and right knee bent
//                 25 deg, the arms down and swinging 15 deg against the legs
//   SITTING       hips flexed 90 deg, knees bent 90 deg (shins straight down), arms 20 deg
//                 from hanging with the elbows bent 30 deg

#include <string>
#include <vector>

#include "sim/body/RigPose.h"

namespace figment {

enum class PosePreset { APose, ArmsDown, ArmRaised, WalkingStep, Sitting };

// The preset's rotations for the rig as placed on one body. Throws std::invalid_argument
// when the rig lacks a bone the preset turns.
RigPose presetPose(PosePreset preset, const HumanRig& rig, const std::vector<PlacedBone>& placed);

// The rotation of `bone` that turns the limb from `from`'s head to `to`'s tail onto
// `direction` (world, posed), given the pose of its parents so far. For presets and tests.
Eigen::Quaterniond aimLimb(const HumanRig& rig, const std::vector<PlacedBone>& placed, const RigPose& pose,
                           const std::string& from, const std::string& to, const Vec3& direction);

}  // namespace figment
