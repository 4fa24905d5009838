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

}  // namespace figment
