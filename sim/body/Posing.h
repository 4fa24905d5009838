#pragma once
// Posing and sizing the jointed mannequin (paper §3.3: "since the collision objects
// correspond directly with the jointed body parts of the mannequin, the application of
// geometric transformations to animate the mannequin and to adjust its dimensions and
// proportions is quite straightforward"). One affine map per part, rest frame -> posed
// world; y is up.
//
// Sizing first, in the rest frame, part by part (S_k), then the pose (G_j):
//   armLength  upper arms, forearms, hands (parts named upperArm*, forearm*, hand*)
//              stretch along their bones about their first joint; the joints below move
//              out with them;
//   chest, waist, hips  the girth of upperTorso, lowerTorso, hips: scaled across the bone
//              (not along) about the bone's line;
//   joints     each follows the part carrying it (jointCarriers()): the end of a bone with
//              its bone, so the shoulders move out with the chest girth and the hip joints
//              with the hips girth, and the limbs stay attached;
//   height     scales everything uniformly about the floor point below the root joint at
//              the lowest joint's height (the feet stay on the floor).
//   pose       G_j = G_parent(j) T(s_j) R_j T(-s_j), s_j the sized rest position of
//              joint j, R_j its rotation (rest frame, about s_j): a joint turns every part
//              below it.
//   part k     G_pivot(k) S_k, the pivot the parent of the bone's last joint: its first
//              joint, except for the humanoid's hips part, which runs from the pelvis floor
//              (a leaf of the pelvis) up to the waist and so turns with the pelvis.

#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "sim/body/Skeleton.h"

namespace figment {

struct Sizing {  // factors, 1 = as fitted; each in [0.5, 2]
  double height = 1, chest = 1, waist = 1, hips = 1, armLength = 1;

  // Throws std::invalid_argument naming the factor ("chest = 2.5 must be in [0.5, 2]").
  void validate() const;
};

struct Pose {  // rotation of each joint about its rest position (rest frame), by joint index; missing = identity
  std::vector<Eigen::Quaterniond> rotations;
};

// The girth factor sizing gives `part` across its bone (chest: upperTorso, waist:
// lowerTorso, hips: hips); nullopt for a part whose girth sizing leaves alone.
std::optional<double> girthFactor(const BodyPart& part, const Sizing& sizing);

// One map per skeleton part (index = skeleton.parts), rest frame -> posed world frame.
// Throws std::invalid_argument naming the factor and value when a factor is out of range,
// when pose.rotations has more entries than the skeleton has joints or a zero or
// non-finite rotation, or when the hierarchy has a cycle.
std::vector<Eigen::Affine3d> partTransforms(const Skeleton& skeleton, const Pose& pose, const Sizing& sizing);
// Posed joint positions (the same kinematics), for drawing and tests.
std::vector<Vec3> posedJoints(const Skeleton& skeleton, const Pose& pose, const Sizing& sizing);

// The part each joint moves with under sizing, and blends into in skinning: the part
// ending at it (the first, if several); for the humanoid's shoulder bases the upper
// torso and for its hips the hips part (the torso parts they sit in); else its parent's
// carrier; -1 for none (the root).
std::vector<int> jointCarriers(const Skeleton& skeleton);

}  // namespace figment
