#include "sim/body/Posing.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/core/ParameterChecks.h"

namespace figment {

namespace {
constexpr double kMinFactor = 0.5, kMaxFactor = 2.0;

bool startsWith(const std::string& name, const char* prefix) {
  return name.rfind(prefix, 0) == 0;
}

int partNamed(const Skeleton& skeleton, const char* name) {
  for (size_t k = 0; k < skeleton.parts.size(); ++k)
    if (skeleton.parts[k].name == name) return static_cast<int>(k);
  return -1;
}

// The linear part of part k's sizing: a stretch along the bone or a scale across it,
// written as I + (f - 1) P so that f = 1 gives the identity exactly.
Eigen::Matrix3d sizingLinear(const Skeleton& skeleton, const BodyPart& part, const Sizing& sizing) {
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  const Vec3 bone = skeleton.joints[part.to].position - skeleton.joints[part.from].position;
  if (!(bone.norm() > 0.0)) return identity;
  const Vec3 u = bone.normalized();
  const Eigen::Matrix3d along = u * u.transpose(), across = identity - along;
  if (const std::optional<double> girth = girthFactor(part, sizing)) return identity + (*girth - 1.0) * across;
  if (startsWith(part.name, "upperArm") || startsWith(part.name, "forearm") || startsWith(part.name, "hand"))
    return identity + (sizing.armLength - 1.0) * along;
  return identity;
}

}  // namespace

std::optional<double> girthFactor(const BodyPart& part, const Sizing& sizing) {
  if (part.name == "upperTorso") return sizing.chest;
  if (part.name == "lowerTorso") return sizing.waist;
  if (part.name == "hips") return sizing.hips;
  return std::nullopt;
}

namespace {

void checkHierarchy(const Skeleton& skeleton) {
  const int n = static_cast<int>(skeleton.joints.size());
  for (int j = 0; j < n; ++j) {
    const int parent = skeleton.joints[j].parent;
    if (parent < -1 || parent >= n)
      throw std::invalid_argument("joint " + skeleton.joints[j].name + ": parent = " + std::to_string(parent) +
                                  " is not a joint index");
    // Walking up from j must reach the root within n steps.
    int steps = 0;
    for (int k = parent; k >= 0; k = skeleton.joints[k].parent)
      if (++steps > n) throw std::invalid_argument("joint " + skeleton.joints[j].name + " is in a parent cycle");
  }
  for (const BodyPart& part : skeleton.parts)
    if (part.from < 0 || part.from >= n || part.to < 0 || part.to >= n)
      throw std::invalid_argument("part " + part.name + ": joint index out of range");
}

// The sized rest frame: per part rest -> sized rest (S_k), per joint its sized position.
// Evaluated on demand (memoised), since a carrier part may start at a joint that comes
// after the one it carries (the hips part starts at the pelvis floor, beside the hips).
class Sizer {
 public:
  Sizer(const Skeleton& skeleton, const Sizing& sizing)
      : skeleton_(skeleton),
        sizing_(sizing),
        carriers_(jointCarriers(skeleton)),
        sized_(skeleton.joints.size()),
        parts_(skeleton.parts.size()),
        jointState_(skeleton.joints.size(), kTodo),
        partDone_(skeleton.parts.size(), false) {
    // Height: uniform about the floor point below the root.
    double floor = skeleton.joints.empty() ? 0.0 : skeleton.joints[0].position.y();
    Vec3 root = Vec3::Zero();
    for (const Joint& joint : skeleton.joints) {
      floor = std::min(floor, joint.position.y());
      if (joint.parent < 0) root = joint.position;
    }
    height_.linear() = sizing.height * Eigen::Matrix3d::Identity();
    height_.translation() = (1.0 - sizing.height) * Vec3(root.x(), floor, root.z());
  }

  Vec3 joint(int j) { return height_ * sizedJoint(j); }
  Eigen::Affine3d part(int k) { return height_ * sizedPart(k); }

 private:
  Vec3 sizedJoint(int j) {
    if (jointState_[j] == kDone) return sized_[j];
    if (jointState_[j] == kBusy)
      throw std::invalid_argument("joint " + skeleton_.joints[j].name + " is carried by a part it carries");
    jointState_[j] = kBusy;
    const Joint& joint = skeleton_.joints[j];
    if (carriers_[j] >= 0)
      sized_[j] = sizedPart(carriers_[j]) * joint.position;
    else if (joint.parent >= 0)
      sized_[j] = joint.position + (sizedJoint(joint.parent) - skeleton_.joints[joint.parent].position);
    else
      sized_[j] = joint.position;
    jointState_[j] = kDone;
    return sized_[j];
  }
  const Eigen::Affine3d& sizedPart(int k) {
    if (!partDone_[k]) {
      const BodyPart& part = skeleton_.parts[k];
      const Eigen::Matrix3d linear = sizingLinear(skeleton_, part, sizing_);
      parts_[k].linear() = linear;
      parts_[k].translation() = sizedJoint(part.from) - linear * skeleton_.joints[part.from].position;
      partDone_[k] = true;
    }
    return parts_[k];
  }

  const Skeleton& skeleton_;
  const Sizing& sizing_;
  std::vector<int> carriers_;
  std::vector<Vec3> sized_;
  std::vector<Eigen::Affine3d> parts_;
  enum State : char { kTodo, kBusy, kDone };
  std::vector<State> jointState_;
  std::vector<bool> partDone_;
  Eigen::Affine3d height_ = Eigen::Affine3d::Identity();
};

Eigen::Matrix3d rotationOf(const Skeleton& skeleton, const Pose& pose, int j) {
  if (j >= static_cast<int>(pose.rotations.size())) return Eigen::Matrix3d::Identity();
  const Eigen::Quaterniond& q = pose.rotations[j];
  if (!q.coeffs().allFinite() || !(q.norm() > 1e-12))
    throw std::invalid_argument("pose.rotations[" + std::to_string(j) + "] (joint " + skeleton.joints[j].name +
                                ") = " + formatNumber(q.w()) + " " + formatNumber(q.x()) + " " + formatNumber(q.y()) +
                                " " + formatNumber(q.z()) + " is not a rotation");
  return q.normalized().toRotationMatrix();
}

// Sizing, then forward kinematics: per joint G_j and its sized position.
struct Kinematics {
  std::vector<Eigen::Affine3d> joint;
  std::vector<Vec3> sized;
  std::vector<Eigen::Affine3d> partSizing;
};

Kinematics kinematics(const Skeleton& skeleton, const Pose& pose, const Sizing& sizing) {
  sizing.validate();
  checkHierarchy(skeleton);
  const size_t n = skeleton.joints.size();
  if (pose.rotations.size() > n)
    throw std::invalid_argument("pose.rotations: " + std::to_string(pose.rotations.size()) + " rotations for " +
                                std::to_string(n) + " joints");
  Sizer sizer(skeleton, sizing);
  Kinematics k;
  k.sized.resize(n);
  for (size_t j = 0; j < n; ++j) k.sized[j] = sizer.joint(static_cast<int>(j));
  for (size_t p = 0; p < skeleton.parts.size(); ++p) k.partSizing.push_back(sizer.part(static_cast<int>(p)));
  k.joint.resize(n);
  std::vector<bool> done(n, false);
  // Parents first: walk up to the nearest done ancestor, then down (the hierarchy is acyclic).
  std::vector<int> chain;
  for (size_t start = 0; start < n; ++start) {
    chain.clear();
    for (int j = static_cast<int>(start); j >= 0 && !done[j]; j = skeleton.joints[j].parent) chain.push_back(j);
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      const int j = *it, parent = skeleton.joints[j].parent;
      const Vec3& s = k.sized[j];
      Eigen::Affine3d local = Eigen::Affine3d::Identity();
      local.linear() = rotationOf(skeleton, pose, j);
      local.translation() = s - local.linear() * s;
      k.joint[j] = parent >= 0 ? k.joint[parent] * local : local;
      done[j] = true;
    }
  }
  return k;
}
}  // namespace

void Sizing::validate() const {
  const std::pair<const char*, double> factors[] = {
      {"height", height}, {"chest", chest}, {"waist", waist}, {"hips", hips}, {"armLength", armLength}};
  for (const auto& [name, value] : factors)
    if (!(value >= kMinFactor && value <= kMaxFactor))
      throw std::invalid_argument(std::string(name) + " = " + formatNumber(value) + " must be in [" +
                                  formatNumber(kMinFactor) + ", " + formatNumber(kMaxFactor) + "]");
}

std::vector<int> jointCarriers(const Skeleton& skeleton) {
  const int n = static_cast<int>(skeleton.joints.size());
  std::vector<int> carrier(n, -1);
  std::vector<bool> own(n, false);
  for (size_t k = 0; k < skeleton.parts.size(); ++k) {
    const BodyPart& part = skeleton.parts[k];
    if (part.to >= 0 && part.to < n && !own[part.to]) carrier[part.to] = static_cast<int>(k), own[part.to] = true;
  }
  // The humanoid's joints that sit inside a torso part rather than at a bone's end.
  const std::pair<const char*, const char*> seated[] = {
      {"shoulderBaseL", "upperTorso"}, {"shoulderBaseR", "upperTorso"}, {"hipL", "hips"}, {"hipR", "hips"}};
  for (const auto& [joint, part] : seated) {
    const int j = skeleton.joint(joint), k = partNamed(skeleton, part);
    if (j >= 0 && k >= 0 && !own[j]) carrier[j] = k, own[j] = true;
  }
  // The rest inherit from their parents (walked up; a cycle stops at n steps).
  for (int j = 0; j < n; ++j) {
    if (own[j]) continue;
    int steps = 0, k = skeleton.joints[j].parent;
    while (k >= 0 && k < n && !own[k] && ++steps <= n) k = skeleton.joints[k].parent;
    carrier[j] = k >= 0 && k < n && own[k] ? carrier[k] : -1;
  }
  return carrier;
}

std::vector<Eigen::Affine3d> partTransforms(const Skeleton& skeleton, const Pose& pose, const Sizing& sizing) {
  const Kinematics k = kinematics(skeleton, pose, sizing);
  std::vector<Eigen::Affine3d> transforms(skeleton.parts.size());
  for (size_t p = 0; p < skeleton.parts.size(); ++p) {
    // The bone turns with the joint it hangs from: its last joint's parent.
    const BodyPart& part = skeleton.parts[p];
    const int pivot = skeleton.joints[part.to].parent >= 0 ? skeleton.joints[part.to].parent : part.from;
    transforms[p] = k.joint[pivot] * k.partSizing[p];
  }
  return transforms;
}

std::vector<Vec3> posedJoints(const Skeleton& skeleton, const Pose& pose, const Sizing& sizing) {
  const Kinematics k = kinematics(skeleton, pose, sizing);
  std::vector<Vec3> joints(skeleton.joints.size());
  for (size_t j = 0; j < joints.size(); ++j) joints[j] = k.joint[j] * k.sized[j];
  return joints;
}

}  // namespace figment
