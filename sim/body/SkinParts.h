#pragma once
// MakeHuman's skin cut into coarse body parts by its rig: each vertex belongs to the bone
// that weighs most on it, and bones group into the parts a tape or a garment tells apart
// (the trunk, the head and neck, and per side the upper arm, forearm, hand, thigh, lower leg
// and foot). What the made bodies' self-intersection check names (issue 30: no two parts of
// the skin cross that do not in the base mesh); a fold within a part, as of a toe, is no
// part crossing.

#include <string>
#include <vector>

#include "sim/body/HumanModel.h"
#include "sim/body/HumanRig.h"

namespace figment {

// "trunk", "head", "left upper arm", "right upper arm", "left forearm", ..., "right foot".
const std::vector<std::string>& skinPartNames();

// The part (index into skinPartNames()) of a bone of MakeHuman's default rig, by its name:
// spine, root, pelvis, breast and clavicle bones are the trunk; neck, head and face bones the
// head; ".L" and ".R" the body's left (+x) and right sides.
int skinPartOfBone(const std::string& bone);

// The part of each triangle of `base`'s skin: the part most of its three vertices are in
// (each vertex in its heaviest bone's part; ties: the lowest part index). Throws
// std::invalid_argument when the rig is over another vertex count than the base's file.
std::vector<int> skinTriangleParts(const HumanRig& rig, const HumanBase& base);

}  // namespace figment
