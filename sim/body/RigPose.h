#pragma once
// A pose of MakeHuman's rig (sim/body/HumanRig.h): a rotation per bone about its head, in
// the rest frame (metres, y up, the body facing +z, its left at +x), and the rigid map of
// each bone it gives by forward kinematics:
//
//   G_b = G_parent(b) T(h_b) R_b T(-h_b),   h_b the bone's rest head, G_root's parent = I
//
// so a joint turns every bone below it and R_b means the same turn whatever the parents
// did (a hip flexed 90 deg and a knee flexed 90 deg give a shin pointing straight down).

#include <Eigen/Geometry>
#include <vector>

#include "sim/body/HumanRig.h"

namespace figment {

struct RigPose {
  // By bone index; missing entries (a shorter list) are the identity.
  std::vector<Eigen::Quaterniond> rotations;

  // The rotation of bone `b` (identity when unset).
  Eigen::Quaterniond of(int b) const;
  // Sets bone `b`'s rotation (growing the list as needed).
  void set(int b, const Eigen::Quaterniond& rotation);
  // The pose `share` of the way from the rest pose (0) to this one (1): each rotation
  // slerped from the identity, so a limb moves along its arc, never through the body
  // along a chord.
  RigPose partway(double share) const;
};

// One rigid map per bone, rest frame -> posed. Throws std::invalid_argument when `placed`
// does not have one entry per bone or a rotation is zero or not finite.
std::vector<Eigen::Isometry3d> boneTransforms(const HumanRig& rig, const std::vector<PlacedBone>& placed,
                                              const RigPose& pose);

}  // namespace figment
