#pragma once
// Bending of the cloth as a thin plate (paper §2: bending at the joints between sections,
// from the curvature approximated there), with the plate bending stiffness
// D = E h^3 / 12(1 - nu^2).
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
//   W = (D/2) A [ nu (tr dS)^2 + (1 - nu) |dS|^2 ]              (J)
//
// a constant quadratic form in the three angle changes. Unlike an energy per joint
// (theta^2 |e|^2 / area), this gives D kappa^2 / 2 per area for a cylindrical bend on a
// grid of right triangles as on equilateral ones, in any direction, so a cantilever
// droops as q L^4 / 8D predicts. A boundary edge contributes no angle (a free edge
// carries no moment). A section whose corners are all held (pinned) is a clamp: it does
// not bend, and the free section on a joint to it takes the whole angle (its mid-edge
// normal is the clamp's, so the edge is clamped to second order, not first).

#include "sim/cloth/BendingJoint.h"
#include "sim/core/TriangleMesh.h"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace figment {

class PlateBending {
 public:
  // Joints on every edge shared by exactly two sections (none on non-manifold edges).
  // `stiffness` = D, N*m; Poisson's ratio nu couples the curvatures in two directions.
  PlateBending(const TriangleMesh& rest, double stiffness, double poissonRatio);

  // Marks the sections whose three corners are held (heldNodes[i] != 0) as clamps.
  void hold(const std::vector<char>& heldNodes);

  double energy(const std::vector<Vec3>& x) const;
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
    Eigen::Matrix3d form;           // W = 1/2 d^T form d, d_i = scale_i (theta_i - theta0_i)
  };
  // Every section with a joint; the implicit integrator's Hessian reads them.
  const std::vector<SectionForm>& sectionForms() const { return sections_; }

 private:
  void measureAngles(const std::vector<Vec3>& x) const;
  Eigen::Vector3d angleChanges(const SectionForm& s) const;

  std::vector<BendingJoint> joints_;
  std::vector<SectionForm> sections_;
  std::vector<Triangle> triangles_;
  mutable std::vector<double> angleChange_, moment_;  // per joint: theta - theta0, dW/dtheta
};

}  // namespace figment
