#include "sim/cloth/BendingJoint.h"

#include <algorithm>
#include <cmath>

namespace figment {

BendingJoint::BendingJoint(int e0, int e1, int o2, int o3, const std::vector<Vec3>& rest) : corners_{e0, e1, o2, o3} {
  setRest(rest[e0], rest[e1], rest[o2], rest[o3]);
}

BendingJoint::BendingJoint(const std::array<int, 4>& corners, const std::array<Vec3, 4>& hinge) : corners_(corners) {
  setRest(hinge[0], hinge[1], hinge[2], hinge[3]);
}

void BendingJoint::setRest(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3) {
  const double areaA = 0.5 * (x1 - x0).cross(x2 - x0).norm();
  const double areaB = 0.5 * (x1 - x0).cross(x3 - x0).norm();
  if (!(areaA > 0.0 && areaB > 0.0)) return;
  restAngle_ = angle(x0, x1, x2, x3);
  valid_ = true;
}

namespace {
// What the angle and its gradient share: the edge and the two (unnormalised) section
// normals, nA = e x (x2 - x0) for section A = (x0, x1, x2) and nB = (x3 - x0) x e for B.
// theta > 0 when the sections fold towards nA.
struct Hinge {
  Vec3 e, nA, nB;
  double length, inverseLength;
  Hinge(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3)
      : e(x1 - x0), nA(e.cross(x2 - x0)), nB((x3 - x0).cross(e)), length(e.norm()), inverseLength(1.0 / length) {}
  double angle() const { return std::atan2(nA.cross(nB).dot(e) * inverseLength, nA.dot(nB)); }
  // Reciprocals taken once: this runs for every joint at every force evaluation.
  std::array<Vec3, 4> gradient(const Vec3& x0, const Vec3& x2, const Vec3& x3) const {
    // Opposite corners move the angle along their section's normal, by 1/height, the
    // height no less than BendingJoint::kMinHeightShare of the edge (|n| = height * length).
    const double floor = BendingJoint::kMinHeightShare * length * length;
    const double floorSquared = floor * floor;
    const Vec3 g2 = (-length / std::max(nA.squaredNorm(), floorSquared)) * nA;
    const Vec3 g3 = (-length / std::max(nB.squaredNorm(), floorSquared)) * nB;
    // Edge corners: each opposite corner's lever, its projection along the edge.
    const double inverseSquared = inverseLength * inverseLength;
    const Vec3 g1 = -(((x2 - x0).dot(e) * inverseSquared) * g2 + ((x3 - x0).dot(e) * inverseSquared) * g3);
    return {-(g1 + g2 + g3), g1, g2, g3};
  }
};
}  // namespace

double BendingJoint::angle(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3) {
  return Hinge(x0, x1, x2, x3).angle();
}

std::array<Vec3, 4> BendingJoint::angleGradient(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3) {
  return Hinge(x0, x1, x2, x3).gradient(x0, x2, x3);
}

namespace {
// theta - theta0 wrapped into (-pi, pi].
double wrapped(double d) {
  if (d > M_PI) d -= 2.0 * M_PI;
  if (d < -M_PI) d += 2.0 * M_PI;
  return d;
}
}  // namespace

double BendingJoint::angleChange(const std::vector<Vec3>& x) const {
  return wrapped(angle(x[corners_[0]], x[corners_[1]], x[corners_[2]], x[corners_[3]]) - restAngle_);
}

AngleGradient BendingJoint::gradient(const std::vector<Vec3>& x) const {
  return angleGradient(x[corners_[0]], x[corners_[1]], x[corners_[2]], x[corners_[3]]);
}

void BendingJoint::momentForces(double moment, const std::vector<Vec3>& x, Vec3* force) const {
  if (moment == 0.0) {  // no gradient needed (nor made: Eigen leaves a default vector unset)
    for (int k = 0; k < 4; ++k) force[k] = Vec3::Zero();
    return;
  }
  const Vec3 &x0 = x[corners_[0]], &x2 = x[corners_[2]], &x3 = x[corners_[3]];
  momentForces(moment, Hinge(x0, x[corners_[1]], x2, x3).gradient(x0, x2, x3), force);
}

double BendingJoint::measure(const std::vector<Vec3>& x, AngleGradient& gradient) const {
  const Vec3 &x0 = x[corners_[0]], &x2 = x[corners_[2]], &x3 = x[corners_[3]];
  const Hinge hinge(x0, x[corners_[1]], x2, x3);
  gradient = hinge.gradient(x0, x2, x3);
  return wrapped(hinge.angle() - restAngle_);
}

}  // namespace figment
