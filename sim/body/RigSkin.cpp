// Skinning by MakeHuman's weights: linear blend, or dual quaternions (Kavan et al. 2007,
// "Skinning with dual quaternions": blend, normalise by the real part, apply).

#include "sim/body/RigSkin.h"

#include <stdexcept>
#include <string>

namespace figment {

namespace {

struct DualQuaternion {
  Eigen::Vector4d real, dual;  // (x, y, z, w) as Eigen's coeffs()
};

Eigen::Quaterniond asQuaternion(const Eigen::Vector4d& c) {
  return Eigen::Quaterniond(c[3], c[0], c[1], c[2]);
}

DualQuaternion dualOf(const Eigen::Isometry3d& g) {
  const Eigen::Quaterniond q(g.rotation());
  const Vec3 t = g.translation();
  const Eigen::Quaterniond d = Eigen::Quaterniond(0.0, t.x(), t.y(), t.z()) * q;
  return {q.coeffs(), 0.5 * d.coeffs()};
}

Vec3 applyBlend(const DualQuaternion& blend, const Vec3& v) {
  const double norm = blend.real.norm();
  const Eigen::Quaterniond real = asQuaternion(blend.real / norm);
  const Eigen::Quaterniond dual = asQuaternion(blend.dual / norm);
  const Vec3 t = 2.0 * (dual * real.conjugate()).vec();
  return real * v + t;
}

Vec3 dualQuaternionSkin(const std::vector<std::pair<int, double>>& influences, const std::vector<DualQuaternion>& dq,
                        const Vec3& v) {
  int heaviest = influences.front().first;
  double most = -1.0;
  for (const auto& [bone, weight] : influences)
    if (weight > most) most = weight, heaviest = bone;
  DualQuaternion sum{Eigen::Vector4d::Zero(), Eigen::Vector4d::Zero()};
  for (const auto& [bone, weight] : influences) {
    const double sign = dq[bone].real.dot(dq[heaviest].real) < 0.0 ? -1.0 : 1.0;
    sum.real += sign * weight * dq[bone].real;
    sum.dual += sign * weight * dq[bone].dual;
  }
  return applyBlend(sum, v);
}

}  // namespace

RigSkin bindSkin(const HumanRig& rig, const std::vector<int>& fileIndex) {
  std::vector<int> skinOf(rig.fileVertexCount(), -1);
  for (size_t k = 0; k < fileIndex.size(); ++k) {
    if (fileIndex[k] < 0 || fileIndex[k] >= rig.fileVertexCount())
      throw std::invalid_argument("bindSkin: file vertex " + std::to_string(fileIndex[k]) + " outside the rig's mesh");
    skinOf[fileIndex[k]] = int(k);
  }
  RigSkin skin;
  skin.influences.resize(fileIndex.size());
  for (size_t b = 0; b < rig.bones().size(); ++b)
    for (const auto& [vertex, weight] : rig.bones()[b].weights)
      if (skinOf[vertex] >= 0 && weight > 0.0) skin.influences[skinOf[vertex]].push_back({int(b), weight});
  for (auto& list : skin.influences) {
    double total = 0.0;
    for (const auto& entry : list) total += entry.second;
    if (total <= 0.0) {
      list = {{0, 1.0}};
      continue;
    }
    for (auto& entry : list) entry.second /= total;
  }
  return skin;
}

std::vector<Vec3> skinVertices(const RigSkin& skin, const std::vector<Eigen::Isometry3d>& bones,
                               const std::vector<Vec3>& rest, SkinningMethod method) {
  if (rest.size() != skin.influences.size())
    throw std::invalid_argument("skinVertices: " + std::to_string(rest.size()) + " vertices for a skin of " +
                                std::to_string(skin.influences.size()));
  std::vector<DualQuaternion> dq;
  if (method == SkinningMethod::DualQuaternion)
    for (const Eigen::Isometry3d& g : bones) dq.push_back(dualOf(g));
  std::vector<Vec3> out(rest.size());
  for (size_t k = 0; k < rest.size(); ++k) {
    const auto& list = skin.influences[k];
    for (const auto& entry : list)
      if (entry.first < 0 || entry.first >= int(bones.size()))
        throw std::invalid_argument("skinVertices: bone " + std::to_string(entry.first) + " has no transform");
    if (method == SkinningMethod::DualQuaternion) {
      out[k] = dualQuaternionSkin(list, dq, rest[k]);
      continue;
    }
    Vec3 sum = Vec3::Zero();
    for (const auto& [bone, weight] : list) sum += weight * (bones[bone] * rest[k]);
    out[k] = sum;
  }
  return out;
}

}  // namespace figment
