// Forward kinematics over the rig's bones, which come parents first.

#include "sim/body/RigPose.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace figment {

Eigen::Quaterniond RigPose::of(int b) const {
  return b >= 0 && b < int(rotations.size()) ? rotations[b] : Eigen::Quaterniond::Identity();
}

void RigPose::set(int b, const Eigen::Quaterniond& rotation) {
  if (b < 0) throw std::invalid_argument("RigPose: bone index " + std::to_string(b));
  if (int(rotations.size()) <= b) rotations.resize(b + 1, Eigen::Quaterniond::Identity());
  rotations[b] = rotation;
}

RigPose RigPose::partway(double share) const {
  RigPose out;
  out.rotations.reserve(rotations.size());
  for (const Eigen::Quaterniond& q : rotations)
    out.rotations.push_back(Eigen::Quaterniond::Identity().slerp(share, q.normalized()));
  return out;
}

std::vector<Eigen::Isometry3d> boneTransforms(const HumanRig& rig, const std::vector<PlacedBone>& placed,
                                              const RigPose& pose) {
  const std::vector<RigBone>& bones = rig.bones();
  if (placed.size() != bones.size())
    throw std::invalid_argument("boneTransforms: " + std::to_string(placed.size()) + " placed bones for " +
                                std::to_string(bones.size()));
  std::vector<Eigen::Isometry3d> g(bones.size());
  for (size_t b = 0; b < bones.size(); ++b) {
    const Eigen::Quaterniond q = pose.of(int(b));
    const double norm = q.norm();
    if (!std::isfinite(norm) || norm == 0.0)
      throw std::invalid_argument("pose: bone " + bones[b].name + " has a zero or non-finite rotation");
    const Vec3& h = placed[b].head;
    const Eigen::Isometry3d local =
        Eigen::Translation3d(h) * Eigen::Isometry3d(q.normalized()) * Eigen::Translation3d(-h);
    g[b] = bones[b].parent >= 0 ? g[bones[b].parent] * local : local;
  }
  return g;
}

}  // namespace figment
