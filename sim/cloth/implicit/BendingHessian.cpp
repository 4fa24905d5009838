#include "sim/cloth/implicit/BendingHessian.h"

#include <algorithm>
#include <cmath>

namespace figment {

BendingStencil bendingStencil(const PlateBending& bending, const PlateBending::SectionForm& section) {
  BendingStencil stencil;
  for (int r = 0; r < 3; ++r) {
    stencil.local[r].fill(-1);
    if (section.joints[r] < 0) continue;
    const std::array<int, 4>& corners = bending.joints()[section.joints[r]].corners();
    for (int k = 0; k < 4; ++k) {
      auto at = std::find(stencil.nodes.begin(), stencil.nodes.end(), corners[k]);
      if (at == stencil.nodes.end()) at = stencil.nodes.insert(at, corners[k]);
      stencil.local[r][k] = static_cast<int>(at - stencil.nodes.begin());
    }
  }
  return stencil;
}

JointAngle jointAngle(const BendingJoint& joint, const std::vector<Vec3>& x) {
  const std::array<int, 4>& c = joint.corners();
  return {joint.angleChange(x), BendingJoint::angleGradient(x[c[0]], x[c[1]], x[c[2]], x[c[3]])};
}

namespace {
// What Gauss-Newton leaves out, M_r d2theta_r/dx2 with M_r the joint's moment, can
// outweigh J^T Q J where a fold bends hard, and a step that underestimates the
// stiffness overshoots: the node flips back and forth each step (seen at the free
// edges of cloth folded over a ball at dt = 1/30 s). The angle's second derivatives
// are of the order of its squared gradient (1/height^2), so |M_r| |dtheta_r/dx_a|^2 I
// on each corner's diagonal bounds them: positive semi-definite, and zero at rest.
constexpr double kBound = 2.0;
void addAngleCurvatureBound(const PlateBending::SectionForm& section, const BendingStencil& stencil,
                            const std::vector<JointAngle>& angles, const Eigen::Vector3d& moment,
                            const std::vector<Vec3>& v, const SystemWeights& weights, const ElementOutput& out) {
  if (section.held) return;
  const int k = static_cast<int>(stencil.nodes.size());
  for (int r = 0; r < 3; ++r) {
    if (section.joints[r] < 0) continue;
    const double jointMoment = kBound * std::abs(section.scale[r] * moment[r]);
    const JointAngle& angle = angles[section.joints[r]];
    for (int corner = 0; corner < 4; ++corner) {
      const int a = stencil.local[r][corner];
      const double stiffness = jointMoment * angle.gradient[corner].squaredNorm();
      out.stiffnessTimesVelocity[a] += stiffness * v[stencil.nodes[a]];
      out.blocks[a * k + a].diagonal().array() += weights.stiffness * stiffness;
    }
  }
}
}  // namespace

void bendingContribution(const PlateBending::SectionForm& section, const BendingStencil& stencil,
                         const std::vector<JointAngle>& angles, const std::vector<Vec3>& v,
                         const SystemWeights& weights, const ElementOutput& out) {
  const int k = static_cast<int>(stencil.nodes.size());
  // G[a]: column r = scale_r dtheta_r/dx_a, so J's block at node a is G[a]^T.
  std::array<Eigen::Matrix3d, 6> G;
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  for (int a = 0; a < k; ++a) G[a].setZero();
  for (int r = 0; r < 3 && !section.held; ++r) {
    if (section.joints[r] < 0) continue;
    const JointAngle& angle = angles[section.joints[r]];
    d[r] = section.scale[r] * angle.change;
    for (int corner = 0; corner < 4; ++corner)
      G[stencil.local[r][corner]].col(r) = section.scale[r] * angle.gradient[corner];
  }
  const Eigen::Vector3d moment = section.form * d;
  std::array<Eigen::Matrix3d, 6> GQ;
  Eigen::Vector3d Jv = Eigen::Vector3d::Zero();
  for (int a = 0; a < k; ++a) {
    GQ[a] = G[a] * section.form;
    Jv += G[a].transpose() * v[stencil.nodes[a]];
  }
  for (int a = 0; a < k; ++a) {
    out.force[a] = -(G[a] * moment);
    out.stiffnessTimesVelocity[a] = GQ[a] * Jv;
    for (int b = 0; b < k; ++b) out.blocks[a * k + b] = weights.stiffness * (GQ[a] * G[b].transpose());
  }
  addAngleCurvatureBound(section, stencil, angles, moment, v, weights, out);
}

std::vector<JointBending> jointBendings(const PlateBending& bending) {
  std::vector<JointBending> joints(bending.joints().size());
  const std::vector<PlateBending::SectionForm>& sections = bending.sectionForms();
  for (int s = 0; s < static_cast<int>(sections.size()); ++s) {
    if (sections[s].held) continue;
    for (int r = 0; r < 3; ++r) {
      const int j = sections[s].joints[r];
      if (j < 0) continue;
      JointBending& joint = joints[j];
      const int at = joint.section[0] < 0 ? 0 : 1;
      joint.section[at] = s;
      joint.side[at] = r;
      const double scale = sections[s].scale[r];
      joint.stiffness += scale * scale * sections[s].form.row(r).cwiseAbs().sum();
    }
  }
  return joints;
}

Eigen::Vector3d bendingSectionForces(const PlateBending::SectionForm& section, const BendingStencil& stencil,
                                     const std::vector<JointAngle>& angles, const ElementOutput& out) {
  const int k = static_cast<int>(stencil.nodes.size());
  Vec3* force = out.force;
  for (int a = 0; a < k; ++a) force[a] = out.stiffnessTimesVelocity[a] = Vec3::Zero();
  if (section.held) return Eigen::Vector3d::Zero();
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  for (int r = 0; r < 3; ++r)
    if (section.joints[r] >= 0) d[r] = section.scale[r] * angles[section.joints[r]].change;
  const Eigen::Vector3d moment = section.form * d;
  for (int r = 0; r < 3; ++r) {
    if (section.joints[r] < 0) continue;
    const JointAngle& angle = angles[section.joints[r]];
    for (int corner = 0; corner < 4; ++corner)
      force[stencil.local[r][corner]] -= (section.scale[r] * moment[r]) * angle.gradient[corner];
  }
  return moment;
}

void jointBendingContribution(const JointBending& joint, const PlateBending& bending, const JointAngle& angle,
                              const std::vector<Eigen::Vector3d>& moments, const std::array<int, 4>& corners,
                              const std::vector<Vec3>& v, const SystemWeights& weights, const ElementOutput& out) {
  if (joint.section[0] < 0) {  // on no free section: a clamp's, or one left out as degenerate
    for (int a = 0; a < 4; ++a) out.force[a] = out.stiffnessTimesVelocity[a] = Vec3::Zero();
    for (int b = 0; b < 16; ++b) out.blocks[b].setZero();
    return;
  }
  double jointMoment = 0.0;  // for the curvature bound, as addAngleCurvatureBound's
  for (int at = 0; at < 2; ++at) {
    const int s = joint.section[at];
    if (s >= 0) jointMoment += std::abs(bending.sectionForms()[s].scale[joint.side[at]] * moments[s][joint.side[at]]);
  }
  double rate = 0.0;  // dtheta/dt
  for (int a = 0; a < 4; ++a) rate += angle.gradient[a].dot(v[corners[a]]);
  for (int a = 0; a < 4; ++a) {
    const double bound = kBound * jointMoment * angle.gradient[a].squaredNorm();
    out.force[a] = Vec3::Zero();
    out.stiffnessTimesVelocity[a] = (joint.stiffness * rate) * angle.gradient[a] + bound * v[corners[a]];
    for (int b = 0; b < 4; ++b)
      out.blocks[a * 4 + b] = (weights.stiffness * joint.stiffness) * (angle.gradient[a] * angle.gradient[b].transpose());
    out.blocks[a * 4 + a].diagonal().array() += weights.stiffness * bound;
  }
}

}  // namespace figment
