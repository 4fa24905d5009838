#pragma once
// The plate bending's force and Gauss-Newton stiffness for the implicit integrator.
// sim/cloth/PlateBending.h gives each section an energy W = d^T Q d / 2, a constant
// quadratic form Q (positive semi-definite for -1 < nu < 1/2) in d_r = scale_r
// (theta_r - theta0_r) over its joints r. With J = dd/dx (rows: scale_r dtheta_r/dx,
// from BendingJoint::angleGradient) over the section's stencil (its corners and the
// opposite corners across its joints, up to 6 nodes):
//   force     f = -J^T Q d
//   stiffness K =  J^T Q J          (Gauss-Newton: the angles' second derivatives
//                                   times Q d are left out; positive semi-definite,
//                                   exact at rest, where d = 0 on a flat rest shape)

#include "sim/cloth/PlateBending.h"
#include "sim/cloth/implicit/ElementOutput.h"

#include <array>
#include <vector>

namespace figment {

// The nodes a bending section acts on, and where each of its joints' corners sits
// among them.
struct BendingStencil {
  std::vector<int> nodes;                   // up to 6
  std::array<std::array<int, 4>, 3> local;  // per joint (-1: none), its corners' local index
};
BendingStencil bendingStencil(const PlateBending& bending, const PlateBending::SectionForm& section);

// One joint's angle change theta - theta0 and its gradient at its four corners.
struct JointAngle {
  double change = 0.0;
  std::array<Vec3, 4> gradient;
};
JointAngle jointAngle(const BendingJoint& joint, const std::vector<Vec3>& x);

// Writes the section's forces, K v and weighted blocks (stencil order) into `out`
// (zeros for a clamp). `angles`: every joint's, at x.
void bendingContribution(const PlateBending::SectionForm& section, const BendingStencil& stencil,
                         const std::vector<JointAngle>& angles, const std::vector<Vec3>& v,
                         const SystemWeights& weights, const ElementOutput& out);

// The joint-wise bound of the same stiffness: with u_r = scale_r dtheta_r/dx . dx,
//   u^T Q u <= sum_r q_r u_r^2,   q_r = sum_t |Q_rt|   (|u_r u_t| <= (u_r^2 + u_t^2) / 2),
// so K <= sum over joints of w_j g_j g_j^T, w_j = sum over the joint's two sections of
// scale_r^2 q_r: a 4-node stencil per joint instead of 6 per section. The matrix keeps
// the membrane's 1-ring pattern plus one block per joint's opposite corners (about 13
// blocks a row instead of 19): cheaper to assemble and to multiply, stiffer than exact
// by at most the form's off-diagonal share (the equilibrium, f = 0, is the same).
struct JointBending {
  std::array<int, 2> section{-1, -1};  // the sections it joins (-1: none, or a clamp)
  std::array<int, 2> side{0, 0};       // the joint's index r in each
  double stiffness = 0.0;              // w_j
};
std::vector<JointBending> jointBendings(const PlateBending& bending);
// The section's forces alone (stencil order; its K v slots zero, it has no blocks), as
// bendingContribution's; returns its moments Q d (zero for a clamp).
Eigen::Vector3d bendingSectionForces(const PlateBending::SectionForm& section, const BendingStencil& stencil,
                                     const std::vector<JointAngle>& angles, const ElementOutput& out);
// The joint's K v and weighted blocks (corner order) into `out`; `moments`: every section's.
void jointBendingContribution(const JointBending& joint, const PlateBending& bending, const JointAngle& angle,
                              const std::vector<Eigen::Vector3d>& moments, const std::array<int, 4>& corners,
                              const std::vector<Vec3>& v, const SystemWeights& weights, const ElementOutput& out);

}  // namespace figment
