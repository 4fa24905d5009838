#pragma once
// Bending at a joint between two cloth sections (paper §2, Fig. 2.1): a hinge on the
// shared edge (x0, x1) with the opposite corners x2 (section A) and x3 (section B).
//
// Based on: the discrete-shell hinge energy (Grinspun, Hirani, Desbrun & Schroeder,
// "Discrete Shells", SCA 2003) with the dihedral-angle gradients of Bridson, Marino &
// Fedkiw, "Simulation of clothing with folds and wrinkles", SCA 2003.
//
//   theta  = signed dihedral angle between the section normals (0 when flat)
//   W      = (3/2) D (theta - theta0)^2 |e0|^2 / (A0a + A0b)        (J)
// with D = E h^3 / 12(1 - nu^2) the plate bending stiffness and |e0|, A0 the rest edge
// length and section areas: the integrated mean curvature theta |e| / 2 over the
// hinge's third of the two sections gives the plate energy (D/2)(2H)^2 per area.
// Force on corner i: -dW/dx_i = -3 D (theta - theta0) |e0|^2 / (A0a + A0b) dtheta/dx_i.

#include "TriangleMesh.h"

#include <array>
#include <vector>

namespace figment {

class BendingJoint {
 public:
  // Corners: shared edge (e0, e1), opposite o2 of section A = (e0, e1, o2), o3 of B.
  BendingJoint(int e0, int e1, int o2, int o3, const std::vector<Vec3>& rest);

  bool valid() const { return weight_ > 0.0; }
  static double angle(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3);
  // dtheta/dx for the four corners x0..x3.
  static std::array<Vec3, 4> angleGradient(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3);

  double energy(const std::vector<Vec3>& x, double bendingStiffness) const;
  void addForces(const std::vector<Vec3>& x, double bendingStiffness, std::vector<Vec3>& force) const;

 private:
  std::array<int, 4> corners_;
  double restAngle_ = 0.0;
  double weight_ = 0.0;  // 3 |e0|^2 / (A0a + A0b), dimensionless
};

}  // namespace figment
