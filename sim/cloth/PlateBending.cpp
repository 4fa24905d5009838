#include "sim/cloth/PlateBending.h"

#include <map>
#include <tuple>

namespace figment {

namespace {

// Triangle t's bending form (false for a triangle of no area), from its edges' in-plane
// normals t_k and weights w_k = l_k / 2A: (tr dS)^2 = (sum_i w_i d_i)^2 and
// |dS|^2 = sum_ij w_i w_j d_i d_j (t_i . t_j)^2.
bool bendingForm(const TriangleMesh& rest, const Triangle& t, double stiffness, double poissonRatio,
                 Eigen::Matrix3d& form) {
  const Vec3 normal = (rest.vertices[t[1]] - rest.vertices[t[0]]).cross(rest.vertices[t[2]] - rest.vertices[t[0]]);
  const double area = 0.5 * normal.norm();
  if (!(area > 0.0)) return false;
  std::array<Vec3, 3> edgeNormal;
  std::array<double, 3> weight;
  for (int k = 0; k < 3; ++k) {
    const Vec3 edge = rest.vertices[t[(k + 1) % 3]] - rest.vertices[t[k]];
    edgeNormal[k] = edge.cross(normal).normalized();
    weight[k] = edge.norm() / (2.0 * area);
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double c = edgeNormal[i].dot(edgeNormal[j]);
      form(i, j) = stiffness * area * weight[i] * weight[j] * (poissonRatio + (1.0 - poissonRatio) * c * c);
    }
  return true;
}

}  // namespace

PlateBending::PlateBending(const TriangleMesh& rest, double stiffness, double poissonRatio) {
  // Each undirected edge -> the sections that run along it, as (from, to, opposite).
  struct EdgeUse {
    int section, from, to, opposite;
  };
  std::map<std::pair<int, int>, std::vector<EdgeUse>> uses;
  for (int s = 0; s < static_cast<int>(rest.triangles.size()); ++s) {
    const Triangle& t = rest.triangles[s];
    for (int k = 0; k < 3; ++k) uses[std::minmax(t[k], t[(k + 1) % 3])].push_back({s, t[k], t[(k + 1) % 3], t[(k + 2) % 3]});
  }
  // Per section and local edge k (corners k -> k+1): the joint there and its sign.
  std::vector<std::array<int, 3>> jointOf(rest.triangles.size(), {-1, -1, -1});
  std::vector<std::array<int, 3>> neighbourOf(rest.triangles.size(), {-1, -1, -1});
  std::vector<std::array<double, 3>> signOf(rest.triangles.size(), {1.0, 1.0, 1.0});
  for (const auto& [edge, list] : uses) {
    if (list.size() != 2) continue;
    const EdgeUse &A = list[0], &B = list[1];
    BendingJoint joint(A.from, A.to, A.opposite, B.opposite, rest.vertices);
    if (!joint.valid()) continue;
    const int index = static_cast<int>(joints_.size());
    joints_.push_back(joint);
    // The joint's angle is signed by A's normal; B sees the same curvature when it runs
    // the edge the other way (consistent winding), the opposite when it does not.
    const double signB = B.from == A.to ? 1.0 : -1.0;
    for (const auto& [use, other, sign] : {std::tuple{A, B.section, 1.0}, std::tuple{B, A.section, signB}}) {
      const Triangle& t = rest.triangles[use.section];
      for (int k = 0; k < 3; ++k)
        if (t[k] == use.from && t[(k + 1) % 3] == use.to) {
          jointOf[use.section][k] = index;
          neighbourOf[use.section][k] = other;
          signOf[use.section][k] = sign;
        }
    }
  }
  for (size_t s = 0; s < rest.triangles.size(); ++s) {
    SectionForm section{static_cast<int>(s), jointOf[s], neighbourOf[s], signOf[s], signOf[s], false,
                        Eigen::Matrix3d::Zero()};
    if (!bendingForm(rest, rest.triangles[s], stiffness, poissonRatio, section.form)) continue;
    if (section.joints != std::array<int, 3>{-1, -1, -1}) sections_.push_back(section);
  }
  triangles_ = rest.triangles;
  angleChange_.resize(joints_.size());
  moment_.resize(joints_.size());
}

void PlateBending::hold(const std::vector<char>& heldNodes) {
  std::vector<char> heldTriangle(triangles_.size());
  for (size_t t = 0; t < triangles_.size(); ++t)
    heldTriangle[t] = heldNodes[triangles_[t][0]] && heldNodes[triangles_[t][1]] && heldNodes[triangles_[t][2]];
  for (SectionForm& s : sections_) {
    s.held = heldTriangle[s.triangle];
    for (int k = 0; k < 3; ++k)
      s.scale[k] = s.sign[k] * (s.neighbours[k] >= 0 && heldTriangle[s.neighbours[k]] ? 2.0 : 1.0);
  }
}

void PlateBending::measureAngles(const std::vector<Vec3>& x) const {
  for (size_t j = 0; j < joints_.size(); ++j) angleChange_[j] = joints_[j].angleChange(x);
}

Eigen::Vector3d PlateBending::angleChanges(const SectionForm& s) const {
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k)
    if (s.joints[k] >= 0) d[k] = s.scale[k] * angleChange_[s.joints[k]];
  return d;
}

double PlateBending::energy(const std::vector<Vec3>& x) const {
  measureAngles(x);
  double total = 0.0;
  for (const SectionForm& s : sections_) {
    if (s.held) continue;
    const Eigen::Vector3d d = angleChanges(s);
    total += 0.5 * d.dot(s.form * d);
  }
  return total;
}

void PlateBending::addForces(const std::vector<Vec3>& x, std::vector<Vec3>& force) const {
  measureAngles(x);
  std::fill(moment_.begin(), moment_.end(), 0.0);
  for (const SectionForm& s : sections_) {
    if (s.held) continue;
    const Eigen::Vector3d dWdd = s.form * angleChanges(s);
    for (int k = 0; k < 3; ++k)
      if (s.joints[k] >= 0) moment_[s.joints[k]] += s.scale[k] * dWdd[k];
  }
  for (size_t j = 0; j < joints_.size(); ++j)
    if (moment_[j] != 0.0) joints_[j].addMomentForces(x, moment_[j], force);
}

}  // namespace figment
