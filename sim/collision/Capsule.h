#pragma once
// The paper's 12-parameter capsule (§3.1): a collision volume for one body part.
//
// The unit capsule stands on the y axis, y in [-1/2, 1/2], radius 1/2: a cylinder whose
// ends are half-ellipsoids of height r/2 (r = 1: a hemisphere, r = 0: a flat disc), r1
// at the bottom, r2 at the top. Then, in order:
//   taper   x *= 1 + tx y,  z *= 1 + tz y     (tx > 0 widens the top; |t| < 2)
//   scale   by the dimensions (x, y, z)        (m; 1 1 1 by default)
//   tilt    by theta about the horizontal axis (cos phi, 0, sin phi)
//           (phi = 0: the x axis, 90 degrees: the z axis)
//   offset  by (ox, oy, oz)                    (m)
// Queries follow the paper's path: the inverse transform and the inverse taper give a
// point in the unit capsule, where inside/outside is exact. The nearest surface point is
// then refined in world space (Gauss-Newton over the surface's two parameters from the
// unit-space projection), since scale and taper move the nearest point away from the
// unit-space one.

#include <array>

#include "sim/collision/SurfaceProjection.h"
#include "sim/core/TriangleMesh.h"

namespace figment {

struct CapsuleParameters {
  double r1 = 1.0, r2 = 1.0;            // rounding of the bottom and top ends, [0, 1]
  double tx = 0.0, tz = 0.0;            // taper in x and z, (-2, 2)
  double x = 1.0, y = 1.0, z = 1.0;     // dimensions, m, > 0
  double ox = 0.0, oy = 0.0, oz = 0.0;  // offset of the centre, m
  double theta = 0.0, phi = 0.0;        // tilt and the tilt axis's rotation about y, rad

  // The 12 values in the paper's order: r1 r2 tx tz x y z ox oy oz theta phi.
  std::array<double, 12> values() const;
  static CapsuleParameters fromValues(const std::array<double, 12>& v);
  // Sets the tilt (theta, phi) that takes the unit capsule's y axis onto the unit `axis`.
  void tiltOnto(const Vec3& axis);
  // The tilt as a rotation: by theta about (cos phi, 0, sin phi).
  Eigen::Matrix3d tilt() const;
  // Throws std::invalid_argument naming the parameter and value when out of range.
  void validate() const;
};

struct SurfacePoint {
  Vec3 point;       // m
  Vec3 normal;      // unit, outward
  double distance;  // signed distance of the query point along |p - point|, m (< 0 inside)
};

class Capsule {
 public:
  explicit Capsule(const CapsuleParameters& parameters);

  const CapsuleParameters& parameters() const { return parameters_; }
  bool contains(const Vec3& p) const;
  bool containsUnit(const Vec3& u) const;  // the same for a point already in unit coordinates
  // The nearest point of the surface to p (in world space), the outward normal there
  // and p's signed distance.
  SurfacePoint nearest(const Vec3& p) const;
  // The paper's fast path, for collision response: the unit-space projection (inverse
  // transform, inverse taper, cylinder or end) mapped back, then two Gauss-Newton steps
  // in world space to correct for scale and taper; no line search. Within a fraction of
  // a millimetre of nearest() on body-part capsules (tested), a few times faster. Inside,
  // where p does not lie along the surface normal (kSideways: the steps stopped short of
  // the stationary point), the normal is the way out from p to the point, so that a
  // push-out along it does not move p sideways.
  SurfacePoint nearestFast(const Vec3& p) const;

  // The surface in its two parameters: t in [0, 3] along the profile (0: bottom pole,
  // 1: bottom rim, 2: top rim, 3: top pole), a in radians about the axis.
  Vec3 surface(double t, double a) const;
  // The surface point and its tangents d/dt, d/da at (t, a), analytically.
  SurfaceSample sample(double t, double a) const;
  // World point -> unit-capsule coordinates (inverse offset, tilt, scale, taper) and back.
  Vec3 toUnit(const Vec3& p) const;
  Vec3 fromUnit(const Vec3& u) const;
  // The point of the unit capsule's surface that unit-space `u` projects onto: radially
  // from the axis at the side, from the end's centre on a rounded end, straight onto a
  // flat end (the paper's cylinder-or-hemisphere step; exact in unit space for the side
  // and hemispheres).
  Vec3 unitProjection(const Vec3& u) const;

 private:
  // Profile of the unit capsule: radius and height at t.
  void profile(double t, double& radius, double& height) const;
  // The (t, a) of the unit-space projection of p: the starting guess.
  void project(const Vec3& unit, double& t, double& a) const;

  CapsuleParameters parameters_;
  Eigen::Matrix3d rotation_;  // tilt
  Eigen::Matrix3d inverseRotation_;
  double bottom_, top_;  // unit-space y of the cylinder's ends
};

}  // namespace figment
