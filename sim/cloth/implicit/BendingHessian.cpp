#include "sim/cloth/implicit/BendingHessian.h"

#include <algorithm>

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
}

}  // namespace figment
