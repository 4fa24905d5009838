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

}  // namespace figment
