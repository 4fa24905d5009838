#pragma once
// The nearest point of a parametric surface W(t, a) to a point p, in world space:
// Levenberg-Marquardt on |W(t, a) - p|^2 over t in [tMin, tMax] and the angle a,
// from a starting (t, a) near the answer. Shared by the collision volumes (sim/collision/Capsule.h,
// sim/collision/RadialDepth.h), whose scale, taper and varying radius move the nearest point
// away from a radial projection.

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "sim/core/TriangleMesh.h"

namespace figment {

// The surface's point and its two tangents dW/dt, dW/da at one (t, a).
struct SurfaceSample {
  Vec3 w, dt, da;
};

// `sample(t, a)` returns a SurfaceSample. Refines (t, a) in place; returns W(t, a).
template <typename Sample>
Vec3 projectOntoSurface(const Sample& sample, const Vec3& p, double tMin, double tMax, double& t, double& a) {
  SurfaceSample s = sample(t, a);
  double lambda = 1e-3;  // the damping also covers the poles, where dW/da vanishes
  for (int iteration = 0; iteration < 50; ++iteration) {
    Eigen::Matrix<double, 3, 2> J;
    J << s.dt, s.da;
    const Eigen::Matrix2d A = J.transpose() * J;
    const Eigen::Vector2d g = J.transpose() * (s.w - p);
    bool improved = false;
    double tNext = t, aNext = a;
    for (int attempt = 0; attempt < 12 && !improved; ++attempt) {
      Eigen::Matrix2d damped = A;
      damped.diagonal() += lambda * A.diagonal() + Eigen::Vector2d::Constant(1e-18);
      const Eigen::Vector2d step = damped.ldlt().solve(-g);
      tNext = std::clamp(t + step[0], tMin, tMax);
      aNext = a + step[1];
      const SurfaceSample next = sample(tNext, aNext);
      if ((next.w - p).squaredNorm() < (s.w - p).squaredNorm()) {
        improved = true;
        s = next;
        lambda = std::max(lambda * 0.3, 1e-9);
      } else {
        lambda *= 10.0;
      }
    }
    const bool converged = std::abs(tNext - t) < 1e-12 && std::abs(aNext - a) < 1e-12;
    if (!improved) break;
    t = tNext, a = aNext;
    if (converged) break;
  }
  return s.w;
}

// The Gauss-Newton step (dt, da) for |W - p|^2 from sample s: the 2x2 normal equations
// (J^T J + eps I) delta = -J^T (W - p), J = [dW/dt dW/da], eps = 1e-12 (trace + 1e-12)
// keeping them regular at a pole, solved in closed form.
inline Eigen::Vector2d gaussNewtonStep(const SurfaceSample& s, const Vec3& p) {
  const Vec3 r = s.w - p;
  double a11 = s.dt.squaredNorm(), a22 = s.da.squaredNorm();
  const double a12 = s.dt.dot(s.da), eps = 1e-12 * (a11 + a22 + 1e-12);
  a11 += eps, a22 += eps;
  const double g1 = s.dt.dot(r), g2 = s.da.dot(r), inverse = 1.0 / (a11 * a22 - a12 * a12);
  return {(a12 * g2 - a22 * g1) * inverse, (a12 * g1 - a11 * g2) * inverse};
}

// cos and sin of a small angle step `delta` (rad), applied to a direction's (c, s) =
// (cos a, sin a): the angle-addition recurrence, with a polynomial for |delta| <= 1/4
// (error below 1e-16) instead of the library's sin and cos.
inline void rotateAngle(double delta, double& c, double& s) {
  double cd, sd;
  if (std::abs(delta) <= 0.25) {
    // Taylor series to d^12 and d^11, Horner's rule (constant factors: no division).
    const double d2 = delta * delta;
    cd = 1.0 + d2 * (-1.0 / 2 +
                     d2 * (1.0 / 24 + d2 * (-1.0 / 720 + d2 * (1.0 / 40320 + d2 * (-1.0 / 3628800 + d2 / 479001600)))));
    sd = delta * (1.0 + d2 * (-1.0 / 6 + d2 * (1.0 / 120 + d2 * (-1.0 / 5040 + d2 * (1.0 / 362880 - d2 / 39916800)))));
  } else {
    cd = std::cos(delta), sd = std::sin(delta);
  }
  const double next = c * cd - s * sd;
  s = s * cd + c * sd, c = next;
}

// A few Gauss-Newton steps with backtracking (the full step, a half or a quarter), no
// damping: the fast path for points near the surface, from a good start. Refines (t, a)
// and returns the sample there.
template <typename Sample>
SurfaceSample refineOnSurface(const Sample& sample, const Vec3& p, double tMin, double tMax, double& t, double& a,
                              int steps = 3) {
  SurfaceSample s = sample(t, a);
  for (int step = 0; step < steps; ++step) {
    const Eigen::Vector2d delta = gaussNewtonStep(s, p);
    bool moved = false;
    for (double scale = 1.0; scale > 0.2 && !moved; scale *= 0.5) {
      const double tNext = std::clamp(t + scale * delta[0], tMin, tMax), aNext = a + scale * delta[1];
      const SurfaceSample next = sample(tNext, aNext);
      if ((next.w - p).squaredNorm() < (s.w - p).squaredNorm()) t = tNext, a = aNext, s = next, moved = true;
    }
    if (!moved) break;
  }
  return s;
}

// How far p - w (r) leans off the unit normal n: its part across n (m). A nearest point's
// is zero; a push-out from p to w + clearance n moves p sideways by this much.
inline double sideways(const Vec3& r, const Vec3& n) {
  return (r - r.dot(n) * n).norm();
}
// The sideways part a fast path may leave before it searches on (m): a contact response
// that takes the push-out into velocity turns it into 1e-6 m / dt (7 mm/s at a 0.15 ms
// step, under a drape's 10 mm/s at-rest threshold).
constexpr double kSideways = 1e-6;

// The unit outward normal of a sample from its tangents, or `fallback` where they are
// parallel (a pole); `outwardHint` is any vector pointing out of the volume there.
inline Vec3 surfaceNormal(const SurfaceSample& s, const Vec3& outwardHint, const Vec3& fallback) {
  Vec3 n = s.da.norm() > 0.0 && s.dt.norm() > 0.0 ? Vec3(s.da.normalized().cross(s.dt.normalized())) : Vec3::Zero();
  if (n.norm() < 1e-6) return fallback.normalized();
  n.normalize();
  return n.dot(outwardHint) >= 0.0 ? n : -n;
}

}  // namespace figment
