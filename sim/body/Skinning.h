#pragma once
// The body mesh follows its parts (paper §3.3's "jointed mannequin"), blended near the
// joints: linear blend skinning.
//
//   part      each vertex belongs to its part (assignParts(): the nearest bone);
//   blend     near each end of its part's bone, by x = how far the vertex lies beyond
//             that joint along the bone (m; < 0 on its own side), its weight passes to the
//             adjacent part across the joint: w = smoothstep((x + R) / 2R), R the blend
//             radius: 0 at R before the joint, 1/2 at the joint, 1 at R beyond it;
//   adjacent  across the first joint: the part carrying that joint (jointCarriers()); across
//             the last: the part starting there (the nearest to the vertex of several);
//   skin      v' = v + sum_i w_i (T_i v - v)   (identity maps give v exactly).

#include <Eigen/Geometry>
#include <array>
#include <vector>

#include "sim/body/Skeleton.h"

namespace figment {

struct SkinWeights {
  static constexpr int kInfluences = 3;  // its own part and the parts across both ends
  struct Influence {
    int part = -1;  // index into skeleton.parts; -1 = unused
    double weight = 0.0;
  };
  std::vector<std::array<Influence, kInfluences>> vertices;  // weights sum to 1
};

// Throws std::invalid_argument when blendRadius is not > 0.
SkinWeights skinWeights(const Skeleton& skeleton, const std::vector<Vec3>& restVertices, double blendRadius = 0.04);
// The same with each vertex's own part given (index into skeleton.parts; -1: by
// assignParts), e.g. the parts the collision volumes were shaped to (vertexParts).
SkinWeights skinWeights(const Skeleton& skeleton, const std::vector<Vec3>& restVertices, const std::vector<int>& owner,
                        double blendRadius = 0.04);
// Throws std::invalid_argument when the sizes disagree or a part has no transform.
std::vector<Vec3> skin(const SkinWeights& weights, const std::vector<Eigen::Affine3d>& partTransforms,
                       const std::vector<Vec3>& restVertices);

}  // namespace figment
