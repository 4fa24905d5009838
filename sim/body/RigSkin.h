#pragma once
// The skin following the rig (sim/body/RigPose.h) by MakeHuman's own weights:
//
//   linear blend     v' = sum_b w_b G_b v   (the weights sum to 1 per vertex)
//   dual quaternion  v' = D(v), D the normalised blend sum_b w_b s_b d_b of the bones' unit
//                    dual quaternions d_b (s_b = -1 where d_b's rotation lies in the
//                    other hemisphere from the vertex's heaviest bone's), which stays a
//                    rigid map: a joint bent far keeps its girth where the linear blend
//                    of two rotations pinches it (the "candy wrapper").
//
// Which one the body uses was measured (docs/bodies.md: the skin's volume in each pose).

#include <Eigen/Geometry>
#include <utility>
#include <vector>

#include "sim/body/HumanRig.h"

namespace figment {

enum class SkinningMethod { LinearBlend, DualQuaternion };

struct RigSkin {
  // Per skin vertex: (bone index, weight), the weights summing to 1.
  std::vector<std::vector<std::pair<int, double>>> influences;
};

// Binds the skin whose vertex k is the file's vertex fileIndex[k] (HumanBase::fileIndex).
// A vertex the weights leave out follows the root bone. Throws std::invalid_argument
// when a file index lies outside the rig's mesh.
RigSkin bindSkin(const HumanRig& rig, const std::vector<int>& fileIndex);

// The posed skin. Throws std::invalid_argument when `rest` does not have one vertex per
// bound vertex or a bone index has no transform.
std::vector<Vec3> skinVertices(const RigSkin& skin, const std::vector<Eigen::Isometry3d>& bones,
                               const std::vector<Vec3>& rest, SkinningMethod method);

}  // namespace figment
