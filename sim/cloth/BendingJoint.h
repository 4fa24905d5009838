#pragma once
// A joint between two cloth sections (paper §2, Fig. 2.1): the hinge on the shared edge
// (x0, x1) with the opposite corners x2 (section A = x0 x1 x2) and x3 (section B). Its
// dihedral angle measures the curvature across the edge; sim/cloth/PlateBending.h turns the
// angles around each section into the section's curvature and the plate's energy.
//
// Angle gradients: Bridson, Marino & Fedkiw, "Simulation of clothing with folds and
// wrinkles", SCA 2003.

#include <array>
#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

// dtheta/dx of a joint's angle at its four corners (1/m).
using AngleGradient = std::array<Vec3, 4>;

class BendingJoint {
 public:
  // Corners: shared edge (e0, e1), opposite o2 of section A = (e0, e1, o2), o3 of B.
  BendingJoint(int e0, int e1, int o2, int o3, const std::vector<Vec3>& rest);
  // The same corners, resting as the four points `hinge` have them (sim/cloth/RestShape.h:
  // a sewn garment's joints rest flat, unfolded about their edge).
  BendingJoint(const std::array<int, 4>& corners, const std::array<Vec3, 4>& hinge);

  bool valid() const { return valid_; }
  const std::array<int, 4>& corners() const { return corners_; }
  double restAngle() const { return restAngle_; }

  // theta - theta0 at x, wrapped into (-pi, pi] (the shortest way back to rest).
  double angleChange(const std::vector<Vec3>& x) const;
  // The angle change at x, and its gradient into `gradient`, from one look at the hinge.
  double measure(const std::vector<Vec3>& x, AngleGradient& gradient) const;
  // dtheta/dx at x for the four corners.
  AngleGradient gradient(const std::vector<Vec3>& x) const;

  // The forces of a moment M = dW/dtheta about the joint, f = -M dtheta/dx, corner order:
  // from the gradient, or measuring it at x. Zeros where M = 0, without the gradient
  // (it is not needed there, nor always finite).
  static void momentForces(double moment, const AngleGradient& gradient, Vec3* force) {
    for (int k = 0; k < 4; ++k) force[k] = moment != 0.0 ? Vec3(-(moment * gradient[k])) : Vec3::Zero();
  }
  void momentForces(double moment, const std::vector<Vec3>& x, Vec3* force) const;

  // Signed dihedral angle between the section normals: 0 when flat, > 0 when the sections
  // fold towards A's normal; the same whichever section is A when the winding agrees.
  static double angle(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3);
  // dtheta/dx for the four corners x0..x3. A section flatter than kMinHeightShare of the
  // edge (its opposite corner within that of the edge's line) counts as that high: a
  // section collapsed onto its edge has no normal, and 1/height would grow without bound
  // (a T-shirt warm-started onto a larger size's drape had one at 1e-17 of its edge: forces
  // of 1e10 N, which the contacts held still, and a fit map of 1e8 kPa at the underbust).
  static std::array<Vec3, 4> angleGradient(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3);

  static constexpr double kMinHeightShare = 1e-3;

 private:
  void setRest(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3);

  std::array<int, 4> corners_;
  double restAngle_ = 0.0;
  bool valid_ = false;
};

}  // namespace figment
