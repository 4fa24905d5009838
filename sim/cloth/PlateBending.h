#pragma once
// Bending of the cloth as a thin plate (paper §2: bending at the joints between sections,
// from the curvature approximated there), with the plate bending stiffness
// D = E h^3 / 12(1 - nu^2): its energy, force and stiffness from one derivation.
//
// Each section's curvature is the shape operator built from the dihedral angles at its
// three joints (the mid-edge construction of Grinspun, Gingold, Reisman & Zorin,
// "Computing discrete shape operators on general meshes", Eurographics 2006):
//
//   dS = sum_i (l_i / 2A) (theta_i - theta0_i) t_i t_i^T        (1/m, 2x2 in the section)
//
// with l_i the rest length of edge i, t_i its in-plane unit normal and A the section's rest
// area; the section's energy is Kirchhoff's plate energy
//
//   W = (D/2) A [ nu (tr dS)^2 + (1 - nu) |dS|^2 ] = d^T Q d / 2    (J)
//
// a constant quadratic form Q (positive semi-definite for -1 < nu < 1/2) in the angle
// changes d_r = scale_r (theta_r - theta0_r) of its joints r. Unlike an energy per joint
// (theta^2 |e|^2 / area), this gives D kappa^2 / 2 per area for a cylindrical bend on a
// grid of right triangles as on equilateral ones, in any direction, so a cantilever
// droops as q L^4 / 8D predicts. A boundary edge contributes no angle (a free edge
// carries no moment). A section whose corners are all held (pinned) is a clamp: it does
// not bend, and the free section on a joint to it takes the whole angle (its mid-edge
// normal is the clamp's, so the edge is clamped to second order, not first).
//
// One evaluation, in three passes that each run over independent elements:
//   angles    per joint j: theta_j - theta0_j and g_j = dtheta_j/dx (BendingJoint)
//   moments   per section: m = Q d = dW/dd (zero for a clamp)
//   forces    per joint: M_j = sum over its sections of scale_r m_r = dW/dtheta_j,
//             f = -M_j g_j on its four corners (BendingJoint::momentForces)
// and, for an implicit step, the stiffness K = -df/dx in one of two forms:
//   sections  K = J^T Q J over the section's stencil (its corners and the opposite
//             corners across its joints, up to 6 nodes), J = dd/dx: Gauss-Newton, the
//             angles' second derivatives times Q d left out (positive semi-definite,
//             exact at rest, where d = 0 on a flat rest shape)
//   joints    the joint-wise bound of the same: with u_r = scale_r g_r . dx,
//             u^T Q u <= sum_r q_r u_r^2, q_r = sum_t |Q_rt| (|u_r u_t| <= (u_r^2 + u_t^2)/2),
//             so K <= sum over joints of w_j g_j g_j^T, w_j = sum over the joint's free
//             sections of scale_r^2 q_r: a 4-node stencil per joint instead of 6 per
//             section (about 13 blocks a matrix row instead of 19), stiffer than exact
//             by at most the form's off-diagonal share, with the same forces.
// Both add a bound of what Gauss-Newton leaves out (addAngleCurvatureBound in the source).
//
// Based on: the angle gradients of Bridson, Marino & Fedkiw, "Simulation of clothing with
// folds and wrinkles", SCA 2003; the Gauss-Newton form as in Baraff & Witkin 1998.

#include <Eigen/Core>
#include <array>
#include <vector>

#include "sim/cloth/BendingJoint.h"
#include "sim/cloth/ElementOutput.h"
#include "sim/cloth/RestShape.h"
#include "sim/core/TriangleMesh.h"

namespace figment {

class PlateBending {
 public:
  // Joints on every edge shared by exactly two sections (none on non-manifold edges).
  // `stiffness` = D, N*m; Poisson's ratio nu couples the curvatures in two directions.
  PlateBending(const TriangleMesh& rest, double stiffness, double poissonRatio);
  // The same from a rest shape (sim/cloth/RestShape.h): a sewn garment's flat pieces.
  PlateBending(const RestShape& rest, double stiffness, double poissonRatio);

  // Marks the sections whose three corners are held (heldNodes[i] != 0) as clamps.
  void hold(const std::vector<char>& heldNodes);

  double energy(const std::vector<Vec3>& x) const;
  // Adds the forces at x to `force` (the three passes, one after another, on one
  // thread; ClothModel runs them for the integrators).
  void addForces(const std::vector<Vec3>& x, std::vector<Vec3>& force) const;

  const std::vector<BendingJoint>& joints() const { return joints_; }

  // A section's quadratic form over the angle changes of its (up to three) joints.
  struct SectionForm {
    int triangle;                   // index in the rest mesh
    std::array<int, 3> joints;      // -1: a boundary edge
    std::array<int, 3> neighbours;  // the section across each joint
    std::array<double, 3> sign;     // +-1: the joint's angle as this section sees its curvature
    std::array<double, 3> scale;    // sign, doubled on a joint to a clamp
    bool held = false;              // a clamp: all corners held
    Eigen::Matrix3d form;           // Q: W = 1/2 d^T Q d, d_i = scale_i (theta_i - theta0_i)
  };
  // Every section with a joint.
  const std::vector<SectionForm>& sectionForms() const { return sections_; }
  // The nodes of section s's stencil (its Gauss-Newton blocks' order), up to 6.
  const std::vector<int>& stencilNodes(int s) const { return stencils_[s].nodes; }

  // The passes, one element each (independent: any order, any thread).
  // (The angles: joints()[j].angleChange, .measure.) `changes`: every joint's.
  Eigen::Vector3d sectionMoments(int s, const std::vector<double>& changes) const;
  double jointMoment(int j, const std::vector<Eigen::Vector3d>& moments) const;

  // Stiffness, `sections` form: section s's K v and weighted blocks, stencil order.
  void sectionStiffness(int s, const std::vector<AngleGradient>& gradients, const Eigen::Vector3d& moments,
                        const std::vector<Vec3>& v, const SystemWeights& weights, const ElementOutput& out) const;
  // Stiffness, `joints` form: joint j's K v and weighted blocks, corner order.
  void jointStiffness(int j, const AngleGradient& gradient, const std::vector<Eigen::Vector3d>& moments,
                      const std::vector<Vec3>& v, const SystemWeights& weights, const ElementOutput& out) const;

 private:
  // Where each of a section's joints' corners sits among its stencil's nodes.
  struct Stencil {
    std::vector<int> nodes;                   // up to 6
    std::array<std::array<int, 4>, 3> local;  // per joint (-1: none), its corners' local index
  };
  // The free sections a joint joins (in section order) and its bound's weight w_j.
  struct JointSections {
    std::array<int, 2> section{-1, -1};     // -1: none
    std::array<int, 2> side{0, 0};          // the joint's index r in each
    std::array<double, 2> scale{0.0, 0.0};  // each section's scale_r (kept here: read at every evaluation)
    double stiffness = 0.0;                 // w_j, N*m
  };
  Stencil stencilOf(const SectionForm& section) const;
  void linkJoints();  // jointSections_ from the sections' forms and clamps
  void addAngleCurvatureBound(int s, const std::vector<AngleGradient>& gradients, const Eigen::Vector3d& moments,
                              const std::vector<Vec3>& v, const SystemWeights& weights, const ElementOutput& out) const;

  std::vector<BendingJoint> joints_;
  std::vector<SectionForm> sections_;
  std::vector<Stencil> stencils_;
  std::vector<JointSections> jointSections_;
  std::vector<Triangle> triangles_;
};

// The passes run for every joint and section at every force evaluation: inline.

inline Eigen::Vector3d PlateBending::sectionMoments(int s, const std::vector<double>& changes) const {
  const SectionForm& section = sections_[s];
  if (section.held) return Eigen::Vector3d::Zero();
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k)
    if (section.joints[k] >= 0) d[k] = section.scale[k] * changes[section.joints[k]];
  return section.form * d;
}

inline double PlateBending::jointMoment(int j, const std::vector<Eigen::Vector3d>& moments) const {
  const JointSections& joint = jointSections_[j];
  double moment = 0.0;
  for (int at = 0; at < 2; ++at) {
    const int s = joint.section[at];
    if (s >= 0) moment += joint.scale[at] * moments[s][joint.side[at]];
  }
  return moment;
}

}  // namespace figment
