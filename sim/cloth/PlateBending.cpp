#include "sim/cloth/PlateBending.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace figment {

namespace {

// Triangle t's bending form (false for a triangle of no area), from its edges' in-plane
// normals t_k and weights w_k = l_k / 2A: (tr dS)^2 = (sum_i w_i d_i)^2 and
// |dS|^2 = sum_ij w_i w_j d_i d_j (t_i . t_j)^2.
bool bendingForm(const std::array<Vec3, 3>& corners, double stiffness, double poissonRatio, Eigen::Matrix3d& form) {
  const Vec3 normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
  const double area = 0.5 * normal.norm();
  if (!(area > 0.0)) return false;
  std::array<Vec3, 3> edgeNormal;
  std::array<double, 3> weight;
  for (int k = 0; k < 3; ++k) {
    const Vec3 edge = corners[(k + 1) % 3] - corners[k];
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

PlateBending::PlateBending(const TriangleMesh& rest, double stiffness, double poissonRatio)
    : PlateBending(RestShape(rest), stiffness, poissonRatio) {}

PlateBending::PlateBending(const RestShape& rest, double stiffness, double poissonRatio) {
  const std::vector<Triangle>& triangles = rest.triangles();
  // Each undirected edge -> the sections that run along it, as (from, to, opposite).
  struct EdgeUse {
    int section, from, to, opposite;
  };
  std::map<std::pair<int, int>, std::vector<EdgeUse>> uses;
  for (int s = 0; s < static_cast<int>(triangles.size()); ++s) {
    const Triangle& t = triangles[s];
    for (int k = 0; k < 3; ++k)
      uses[std::minmax(t[k], t[(k + 1) % 3])].push_back({s, t[k], t[(k + 1) % 3], t[(k + 2) % 3]});
  }
  // Per section and local edge k (corners k -> k+1): the joint there and its sign.
  std::vector<std::array<int, 3>> jointOf(triangles.size(), {-1, -1, -1});
  std::vector<std::array<int, 3>> neighbourOf(triangles.size(), {-1, -1, -1});
  std::vector<std::array<double, 3>> signOf(triangles.size(), {1.0, 1.0, 1.0});
  for (const auto& [edge, list] : uses) {
    if (list.size() != 2) continue;
    const EdgeUse &A = list[0], &B = list[1];
    const std::array<int, 4> corners{A.from, A.to, A.opposite, B.opposite};
    const BendingJoint joint(corners, rest.hinge(A.section, B.section, corners));
    if (!joint.valid()) continue;
    const int index = static_cast<int>(joints_.size());
    joints_.push_back(joint);
    // The joint's angle is signed by A's normal; B sees the same curvature when it runs
    // the edge the other way (consistent winding), the opposite when it does not.
    const double signB = B.from == A.to ? 1.0 : -1.0;
    for (const auto& [use, other, sign] : {std::tuple{A, B.section, 1.0}, std::tuple{B, A.section, signB}}) {
      const Triangle& t = triangles[use.section];
      for (int k = 0; k < 3; ++k)
        if (t[k] == use.from && t[(k + 1) % 3] == use.to) {
          jointOf[use.section][k] = index;
          neighbourOf[use.section][k] = other;
          signOf[use.section][k] = sign;
        }
    }
  }
  for (size_t s = 0; s < triangles.size(); ++s) {
    SectionForm section{static_cast<int>(s), jointOf[s], neighbourOf[s],         signOf[s],
                        signOf[s],           false,      Eigen::Matrix3d::Zero()};
    if (!bendingForm(rest.corners(s), stiffness, poissonRatio, section.form)) continue;
    if (section.joints == std::array<int, 3>{-1, -1, -1}) continue;
    sections_.push_back(section);
    stencils_.push_back(stencilOf(section));
  }
  triangles_ = triangles;
  linkJoints();
}

PlateBending::Stencil PlateBending::stencilOf(const SectionForm& section) const {
  Stencil stencil;
  for (int r = 0; r < 3; ++r) {
    stencil.local[r].fill(-1);
    if (section.joints[r] < 0) continue;
    const std::array<int, 4>& corners = joints_[section.joints[r]].corners();
    for (int k = 0; k < 4; ++k) {
      auto at = std::find(stencil.nodes.begin(), stencil.nodes.end(), corners[k]);
      if (at == stencil.nodes.end()) at = stencil.nodes.insert(at, corners[k]);
      stencil.local[r][k] = static_cast<int>(at - stencil.nodes.begin());
    }
  }
  return stencil;
}

void PlateBending::linkJoints() {
  jointSections_.assign(joints_.size(), JointSections{});
  for (int s = 0; s < static_cast<int>(sections_.size()); ++s) {
    if (sections_[s].held) continue;
    for (int r = 0; r < 3; ++r) {
      const int j = sections_[s].joints[r];
      if (j < 0) continue;
      JointSections& joint = jointSections_[j];
      const int at = joint.section[0] < 0 ? 0 : 1;
      joint.section[at] = s;
      joint.side[at] = r;
      const double scale = sections_[s].scale[r];
      joint.scale[at] = scale;
      joint.stiffness += scale * scale * sections_[s].form.row(r).cwiseAbs().sum();
    }
  }
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
  linkJoints();
}

double PlateBending::energy(const std::vector<Vec3>& x) const {
  std::vector<double> changes(joints_.size());
  for (size_t j = 0; j < joints_.size(); ++j) changes[j] = joints_[j].angleChange(x);
  double total = 0.0;
  for (size_t s = 0; s < sections_.size(); ++s) {
    const SectionForm& section = sections_[s];
    if (section.held) continue;
    Eigen::Vector3d d = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
      if (section.joints[k] >= 0) d[k] = section.scale[k] * changes[section.joints[k]];
    total += 0.5 * d.dot(section.form * d);
  }
  return total;
}

void PlateBending::addForces(const std::vector<Vec3>& x, std::vector<Vec3>& force) const {
  std::vector<double> changes(joints_.size());
  std::vector<AngleGradient> gradients(joints_.size());
  std::vector<Eigen::Vector3d> moments(sections_.size());
  for (size_t j = 0; j < joints_.size(); ++j) changes[j] = joints_[j].measure(x, gradients[j]);
  for (size_t s = 0; s < sections_.size(); ++s) moments[s] = sectionMoments(static_cast<int>(s), changes);
  for (size_t j = 0; j < joints_.size(); ++j) {
    std::array<Vec3, 4> f;
    BendingJoint::momentForces(jointMoment(static_cast<int>(j), moments), gradients[j], f.data());
    for (int k = 0; k < 4; ++k) force[joints_[j].corners()[k]] += f[k];
  }
}

namespace {
// What Gauss-Newton leaves out, M_r d2theta_r/dx2 with M_r the joint's moment, can
// outweigh J^T Q J where a fold bends hard, and a step that underestimates the
// stiffness overshoots: the node flips back and forth each step (seen at the free
// edges of cloth folded over a ball at dt = 1/30 s). The angle's second derivatives
// are of the order of its squared gradient (1/height^2), so |M_r| |dtheta_r/dx_a|^2 I
// on each corner's diagonal bounds them: positive semi-definite, and zero at rest.
constexpr double kBound = 2.0;
}  // namespace

void PlateBending::addAngleCurvatureBound(int s, const std::vector<AngleGradient>& gradients,
                                          const Eigen::Vector3d& moments, const std::vector<Vec3>& v,
                                          const SystemWeights& weights, const ElementOutput& out) const {
  const SectionForm& section = sections_[s];
  const Stencil& stencil = stencils_[s];
  if (section.held) return;
  const int k = static_cast<int>(stencil.nodes.size());
  for (int r = 0; r < 3; ++r) {
    if (section.joints[r] < 0) continue;
    const double jointMoment = kBound * std::abs(section.scale[r] * moments[r]);
    const AngleGradient& gradient = gradients[section.joints[r]];
    for (int corner = 0; corner < 4; ++corner) {
      const int a = stencil.local[r][corner];
      const double stiffness = jointMoment * gradient[corner].squaredNorm();
      out.stiffnessTimesVelocity[a] += stiffness * v[stencil.nodes[a]];
      out.blocks[a * k + a].diagonal().array() += weights.stiffness * stiffness;
    }
  }
}

void PlateBending::sectionStiffness(int s, const std::vector<AngleGradient>& gradients, const Eigen::Vector3d& moments,
                                    const std::vector<Vec3>& v, const SystemWeights& weights,
                                    const ElementOutput& out) const {
  const SectionForm& section = sections_[s];
  const Stencil& stencil = stencils_[s];
  const int k = static_cast<int>(stencil.nodes.size());
  // G[a]: column r = scale_r dtheta_r/dx_a, so J's block at node a is G[a]^T.
  std::array<Eigen::Matrix3d, 6> G;
  for (int a = 0; a < k; ++a) G[a].setZero();
  for (int r = 0; r < 3 && !section.held; ++r) {
    if (section.joints[r] < 0) continue;
    const AngleGradient& gradient = gradients[section.joints[r]];
    for (int corner = 0; corner < 4; ++corner) G[stencil.local[r][corner]].col(r) = section.scale[r] * gradient[corner];
  }
  std::array<Eigen::Matrix3d, 6> GQ;
  Eigen::Vector3d Jv = Eigen::Vector3d::Zero();
  for (int a = 0; a < k; ++a) {
    GQ[a] = G[a] * section.form;
    Jv += G[a].transpose() * v[stencil.nodes[a]];
  }
  for (int a = 0; a < k; ++a) {
    out.stiffnessTimesVelocity[a] = GQ[a] * Jv;
    for (int b = 0; b < k; ++b) out.blocks[a * k + b] = weights.stiffness * (GQ[a] * G[b].transpose());
  }
  addAngleCurvatureBound(s, gradients, moments, v, weights, out);
}

void PlateBending::jointStiffness(int j, const AngleGradient& gradient, const std::vector<Eigen::Vector3d>& moments,
                                  const std::vector<Vec3>& v, const SystemWeights& weights,
                                  const ElementOutput& out) const {
  const JointSections& joint = jointSections_[j];
  if (joint.section[0] < 0) {  // on no free section: a clamp's, or one left out as degenerate
    for (int a = 0; a < 4; ++a) out.stiffnessTimesVelocity[a] = Vec3::Zero();
    for (int b = 0; b < 16; ++b) out.blocks[b].setZero();
    return;
  }
  double jointMoment = 0.0;  // for the curvature bound, as addAngleCurvatureBound's
  for (int at = 0; at < 2; ++at) {
    const int s = joint.section[at];
    if (s >= 0) jointMoment += std::abs(joint.scale[at] * moments[s][joint.side[at]]);
  }
  const std::array<int, 4>& corners = joints_[j].corners();
  double rate = 0.0;  // dtheta/dt
  for (int a = 0; a < 4; ++a) rate += gradient[a].dot(v[corners[a]]);
  for (int a = 0; a < 4; ++a) {
    const double bound = kBound * jointMoment * gradient[a].squaredNorm();
    out.stiffnessTimesVelocity[a] = (joint.stiffness * rate) * gradient[a] + bound * v[corners[a]];
    for (int b = 0; b < 4; ++b)
      out.blocks[a * 4 + b] = (weights.stiffness * joint.stiffness) * (gradient[a] * gradient[b].transpose());
    out.blocks[a * 4 + a].diagonal().array() += weights.stiffness * bound;
  }
}

}  // namespace figment
