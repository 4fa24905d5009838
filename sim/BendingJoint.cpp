#include "BendingJoint.h"

#include <cmath>

namespace figment {

BendingJoint::BendingJoint(int e0, int e1, int o2, int o3, const std::vector<Vec3>& rest)
    : corners_{e0, e1, o2, o3} {
  const Vec3 &x0 = rest[e0], &x1 = rest[e1], &x2 = rest[o2], &x3 = rest[o3];
  const double areaA = 0.5 * (x1 - x0).cross(x2 - x0).norm();
  const double areaB = 0.5 * (x1 - x0).cross(x3 - x0).norm();
  if (!(areaA > 0.0 && areaB > 0.0)) return;
  restAngle_ = angle(x0, x1, x2, x3);
  weight_ = 3.0 * (x1 - x0).squaredNorm() / (areaA + areaB);
}

// Section A = (x0, x1, x2) has normal nA = (x1-x0) x (x2-x0); section B = (x1, x0, x3)
// (the same orientation across the shared edge) has nB = (x0-x1) x (x3-x1)... written
// below with edge vector e = x1 - x0. theta > 0 when the sections fold towards nA.
double BendingJoint::angle(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3) {
  const Vec3 e = x1 - x0;
  const Vec3 nA = e.cross(x2 - x0);
  const Vec3 nB = (x3 - x0).cross(e);
  const double sine = nA.cross(nB).dot(e) / e.norm();
  return std::atan2(sine, nA.dot(nB));
}

std::array<Vec3, 4> BendingJoint::angleGradient(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3) {
  const Vec3 e = x1 - x0;
  const double length = e.norm();
  const Vec3 nA = e.cross(x2 - x0);
  const Vec3 nB = (x3 - x0).cross(e);
  const Vec3 uA = nA / nA.squaredNorm();
  const Vec3 uB = nB / nB.squaredNorm();
  // Opposite corners move the angle along their section's normal, scaled by 1/height.
  const Vec3 g2 = -length * uA;
  const Vec3 g3 = -length * uB;
  // Edge corners: the lever of each opposite corner's projection along the edge.
  const double sA0 = (x2 - x0).dot(e) / (length * length), sB0 = (x3 - x0).dot(e) / (length * length);
  const Vec3 g1 = -(sA0 * g2 + sB0 * g3);
  const Vec3 g0 = -(g1 + g2 + g3);
  return {g0, g1, g2, g3};
}

double BendingJoint::energy(const std::vector<Vec3>& x, double bendingStiffness) const {
  const double d = angle(x[corners_[0]], x[corners_[1]], x[corners_[2]], x[corners_[3]]) - restAngle_;
  return 0.5 * bendingStiffness * weight_ * d * d;
}

void BendingJoint::addForces(const std::vector<Vec3>& x, double bendingStiffness, std::vector<Vec3>& force) const {
  const Vec3 &x0 = x[corners_[0]], &x1 = x[corners_[1]], &x2 = x[corners_[2]], &x3 = x[corners_[3]];
  double d = angle(x0, x1, x2, x3) - restAngle_;
  d = std::remainder(d, 2.0 * M_PI);  // the shortest way back across +-pi
  const auto gradient = angleGradient(x0, x1, x2, x3);
  const double scale = -bendingStiffness * weight_ * d;
  for (int k = 0; k < 4; ++k) force[corners_[k]] += scale * gradient[k];
}

}  // namespace figment
