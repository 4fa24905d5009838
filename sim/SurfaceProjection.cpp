#include "SurfaceProjection.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace figment {

Vec3 projectOntoSurface(const SurfaceFunction& surface, const Vec3& p, double tMin, double tMax, double& t, double& a) {
  // Central differences in t (one-sided at the ends) and a; the damping also covers the
  // poles, where dW/da vanishes.
  const double kStep = 1e-6 * std::max(1.0, tMax - tMin);
  Vec3 w = surface(t, a);
  double lambda = 1e-3;
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double tHigh = std::min(t + kStep, tMax), tLow = std::max(t - kStep, tMin);
    Eigen::Matrix<double, 3, 2> J;
    J.col(0) = (surface(tHigh, a) - surface(tLow, a)) / (tHigh - tLow);
    J.col(1) = (surface(t, a + 1e-6) - surface(t, a - 1e-6)) / 2e-6;
    const Eigen::Matrix2d A = J.transpose() * J;
    const Eigen::Vector2d g = J.transpose() * (w - p);
    bool improved = false;
    double tNext = t, aNext = a;
    for (int attempt = 0; attempt < 12 && !improved; ++attempt) {
      Eigen::Matrix2d damped = A;
      damped.diagonal() += lambda * A.diagonal() + Eigen::Vector2d::Constant(1e-18);
      const Eigen::Vector2d step = damped.ldlt().solve(-g);
      tNext = std::clamp(t + step[0], tMin, tMax);
      aNext = a + step[1];
      const Vec3 wNext = surface(tNext, aNext);
      if ((wNext - p).squaredNorm() < (w - p).squaredNorm()) {
        improved = true;
        w = wNext;
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
  return w;
}

Vec3 surfaceNormal(const SurfaceFunction& surface, double tMin, double tMax, double t, double a,
                   const Vec3& outwardHint, const Vec3& fallback) {
  const double h = 1e-6 * std::max(1.0, tMax - tMin);
  const Vec3 dt = surface(std::min(t + h, tMax), a) - surface(std::max(t - h, tMin), a);
  const Vec3 da = surface(t, a + 1e-6) - surface(t, a - 1e-6);
  Vec3 n = da.norm() > 0.0 && dt.norm() > 0.0 ? Vec3(da.normalized().cross(dt.normalized())) : Vec3::Zero();
  if (n.norm() < 1e-6) return fallback.normalized();
  n.normalize();
  return n.dot(outwardHint) >= 0.0 ? n : -n;
}

}  // namespace figment
