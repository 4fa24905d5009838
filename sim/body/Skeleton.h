#pragma once
// The mannequin's skeleton (paper §3: "hierarchically jointed mannequin models"): named
// joints with rest positions and a hierarchy, the body parts they bound, and which part
// each body vertex belongs to.

#include <string>
#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

struct Joint {
  std::string name;
  int parent = -1;  // index into Skeleton::joints; -1 for the root
  Vec3 position;    // rest position, m, in the body's frame
};

// A body part: the bone from joint `from` to joint `to` (the part's axis).
struct BodyPart {
  std::string name;
  int from = -1, to = -1;
};

struct Skeleton {
  std::vector<Joint> joints;
  std::vector<BodyPart> parts;

  int joint(const std::string& name) const;                // index, or -1
  const Joint& operator[](const std::string& name) const;  // throws std::invalid_argument naming it
};

// The humanoid skeleton FIGMENT uses: 25 joints (pelvis at the root; pelvis floor (the
// crotch); spine: waist, chest, neck base, neck top, head top; per side: hip, knee,
// ankle, toe, shoulder base (clavicle), shoulder, elbow, wrist, fingertip, with left =
// +x for a body facing +z) and its 17 parts: head, neck, upper torso, lower torso, hips;
// per side: upper arm, forearm, hand, thigh, shin, foot.
// `positions` in the order of humanoidJointNames().
Skeleton humanoidSkeleton(const std::vector<Vec3>& positions);
const std::vector<std::string>& humanoidJointNames();

// The part each vertex belongs to: the nearest bone (distance to the segment), for
// every vertex of `body`. Indices into skeleton.parts.
std::vector<int> assignParts(const Skeleton& skeleton, const std::vector<Vec3>& vertices);

}  // namespace figment
