#pragma once
// The paper's radial depth volume (§3.2): a body part as cross sections along an axis,
// each section's radial depth a Fourier series in the angle about the axis.
//
//   axis     from `base` along the unit `direction` for `length` m; angle a measured
//            from the unit `reference` (perpendicular to the axis) towards direction x
//            reference
//   section  j at s_j = j length / (n - 1), j = 0 .. n-1:
//            r_j(a) = c_j0 + sum_k=1..K (c_j,2k-1 cos k a + c_j,2k sin k a)       (m)
//   between  sections the coefficients interpolate linearly in s;
//   ends     closed by flat caps at s = 0 and s = length.
// A point is inside when it projects onto [0, length] and lies within r(s, a) of the
// axis. The nearest surface point is found in world space (the side by
// Levenberg-Marquardt over (s, a) from the radial projection; the caps directly): the
// push-out follows the surface normal, not the radius, so cloth on a sloping shoulder
// is not pushed sideways.

#include <vector>

#include "sim/collision/Capsule.h"  // SurfacePoint
#include "sim/collision/SurfaceProjection.h"
#include "sim/core/TriangleMesh.h"

namespace figment {

struct RadialDepthParameters {
  Vec3 base = Vec3::Zero();
  Vec3 direction = Vec3::UnitY();
  Vec3 reference = Vec3::UnitX();
  double length = 1.0;                            // m
  int harmonics = 0;                              // K
  std::vector<std::vector<double>> coefficients;  // per section: 2K + 1 values, m

  // Throws std::invalid_argument naming the field when the axis, the length or the
  // coefficient table is unusable.
  void validate() const;
};

class RadialDepth {
 public:
  explicit RadialDepth(RadialDepthParameters parameters);

  const RadialDepthParameters& parameters() const { return parameters_; }
  double radius(double s, double a) const;         // m, at axis position s (m) and angle a
  Vec3 surface(double s, double a) const;          // the side's point at (s, a)
  SurfaceSample sample(double s, double a) const;  // ... and its tangents d/ds, d/da
  bool contains(const Vec3& p) const;
  SurfacePoint nearest(const Vec3& p) const;
  // The fast path for points near the surface (cloth nodes): from the radial projection,
  // up to three Gauss-Newton steps in world space (fewer once a step moves the point
  // less than 1 um); the caps as in nearest(). No atan2, no sin or cos: the angle is
  // carried as its cosine and sine, turned by each step. Inside, where p does not lie
  // along the side's normal (kSideways: the steps stopped short of the stationary point),
  // the normal is the way out from p to the point, so that a push-out along it does not
  // move p sideways.
  SurfacePoint nearestFast(const Vec3& p) const;
  // Axis coordinates of p: position along the axis s (m), angle a, distance from it (m).
  void toAxis(const Vec3& p, double& s, double& a, double& rho) const;

  // A lower bound of p's signed distance (m), without a search: for a cheap early-out.
  //   outside the slab 0 <= s <= length   its distance to the bounding cylinder (the axis
  //                                       segment, radius rMax());
  //   in it, outside (g = rho - r(s, a)   g / sqrt(1 + S^2 + (A / r)^2): were p's distance
  //   > 0)                                d < g, the segment from p to its nearest point
  //                                       would stay in the slab, outside (rho > r), at
  //                                       rho > rho(p) - d > r(s, a) and within g of s,
  //                                       where |grad g|^2 = 1 + (dr/ds)^2 + (dr/da / rho)^2
  //                                       <= 1 + S^2 + (A / r)^2, S the steepest slope of
  //                                       the spans [s - g, s + g] meets and A the largest
  //                                       |dr/da| of their sections; so d >= g / that;
  //   inside                              -min(s, length - s, r - rho): the cap or the
  //                                       side point straight out is no nearer.
  // S and A are bounded once, from a grid of angles plus the grid step times a bound of
  // the derivative.
  double distanceBound(const Vec3& p) const;
  // An upper bound of r over the whole volume (m).
  double rMax() const { return rMax_; }

 private:
  SurfacePoint closest(const Vec3& p, bool fast) const;
  SurfacePoint closestFast(const Vec3& p) const;
  // Axis coordinates with the angle as its cosine and sine (no atan2).
  void toAxis(const Vec3& p, double& s, double& cosA, double& sinA, double& rho) const;
  // r at (s, a) from cos a, sin a (the Fourier series by the angle-addition recurrence),
  // unclamped.
  double seriesAt(double s, double cosA, double sinA) const;
  SurfaceSample sampleAt(double s, double cosA, double sinA) const;

  RadialDepthParameters parameters_;
  Vec3 side_;                    // direction x reference: angle pi/2
  std::vector<double> table_;    // the coefficients, section after section (2K + 1 each)
  std::vector<double> slope_;    // per span: max over a of |dr/ds|
  std::vector<double> turning_;  // per section: max over a of |dr/da|, m/rad
  double rMax_ = 0.0;            // m
};

}  // namespace figment
