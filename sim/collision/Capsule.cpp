#include "sim/collision/Capsule.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "sim/collision/SurfaceProjection.h"
#include "sim/core/ParameterChecks.h"

namespace figment {

std::array<double, 12> CapsuleParameters::values() const {
  return {r1, r2, tx, tz, x, y, z, ox, oy, oz, theta, phi};
}

CapsuleParameters CapsuleParameters::fromValues(const std::array<double, 12>& v) {
  CapsuleParameters p;
  p.r1 = v[0], p.r2 = v[1], p.tx = v[2], p.tz = v[3], p.x = v[4], p.y = v[5], p.z = v[6];
  p.ox = v[7], p.oy = v[8], p.oz = v[9], p.theta = v[10], p.phi = v[11];
  return p;
}

void CapsuleParameters::tiltOnto(const Vec3& axis) {
  const Vec3 turn = Vec3::UnitY().cross(axis);
  theta = std::atan2(turn.norm(), Vec3::UnitY().dot(axis));
  phi = turn.norm() > 1e-12 ? std::atan2(turn.z(), turn.x()) : 0.0;
}

Eigen::Matrix3d CapsuleParameters::tilt() const {
  return Eigen::AngleAxisd(theta, Vec3(std::cos(phi), 0.0, std::sin(phi))).toRotationMatrix();
}

void CapsuleParameters::validate() const {
  const char* names[12] = {"r1", "r2", "tx", "tz", "x", "y", "z", "ox", "oy", "oz", "theta", "phi"};
  const std::array<double, 12> v = values();
  for (int i = 0; i < 12; ++i) requireFinite(names[i], v[i]);
  for (int i : {0, 1})
    if (v[i] < 0.0 || v[i] > 1.0)
      throw std::invalid_argument(std::string(names[i]) + " = " + formatNumber(v[i]) + " must be in [0, 1]");
  requireOpenRange("tx", tx, -2.0, 2.0);
  requireOpenRange("tz", tz, -2.0, 2.0);
  requirePositive("x", x);
  requirePositive("y", y);
  requirePositive("z", z);
}

Capsule::Capsule(const CapsuleParameters& parameters) : parameters_(parameters) {
  parameters_.validate();
  rotation_ = parameters_.tilt();
  inverseRotation_ = rotation_.transpose();
  bottom_ = -0.5 + 0.5 * parameters_.r1;
  top_ = 0.5 - 0.5 * parameters_.r2;
}

void Capsule::profile(double t, double& radius, double& height) const {
  if (t <= 1.0) {  // the bottom end: a quarter ellipse from the pole to the rim
    const double b = 0.5 * M_PI * t;
    radius = 0.5 * std::sin(b);
    height = bottom_ - 0.5 * parameters_.r1 * std::cos(b);
  } else if (t <= 2.0) {
    radius = 0.5;
    height = bottom_ + (t - 1.0) * (top_ - bottom_);
  } else {  // the top end, from the rim to the pole
    const double b = 0.5 * M_PI * (t - 2.0);
    radius = 0.5 * std::cos(b);
    height = top_ + 0.5 * parameters_.r2 * std::sin(b);
  }
}

Vec3 Capsule::fromUnit(const Vec3& u) const {
  const CapsuleParameters& c = parameters_;
  const Vec3 scaled(c.x * u.x() * (1.0 + c.tx * u.y()), c.y * u.y(), c.z * u.z() * (1.0 + c.tz * u.y()));
  return rotation_ * scaled + Vec3(c.ox, c.oy, c.oz);
}

Vec3 Capsule::toUnit(const Vec3& p) const {
  const CapsuleParameters& c = parameters_;
  const Vec3 q = inverseRotation_ * (p - Vec3(c.ox, c.oy, c.oz));
  const double y = q.y() / c.y;
  return {q.x() / c.x / (1.0 + c.tx * y), y, q.z() / c.z / (1.0 + c.tz * y)};
}

SurfaceSample Capsule::sample(double t, double a) const {
  // Profile and its derivative in t, then the unit point and its tangents, then the
  // taper and scale's Jacobian and the tilt.
  const CapsuleParameters& c = parameters_;
  double radius, height, dRadius, dHeight;
  if (t <= 1.0) {
    const double b = 0.5 * M_PI * t;
    radius = 0.5 * std::sin(b), height = bottom_ - 0.5 * c.r1 * std::cos(b);
    dRadius = 0.25 * M_PI * std::cos(b), dHeight = 0.25 * M_PI * c.r1 * std::sin(b);
  } else if (t <= 2.0) {
    radius = 0.5, height = bottom_ + (t - 1.0) * (top_ - bottom_);
    dRadius = 0.0, dHeight = top_ - bottom_;
  } else {
    const double b = 0.5 * M_PI * (t - 2.0);
    radius = 0.5 * std::cos(b), height = top_ + 0.5 * c.r2 * std::sin(b);
    dRadius = -0.25 * M_PI * std::sin(b), dHeight = 0.25 * M_PI * c.r2 * std::cos(b);
  }
  const double ca = std::cos(a), sa = std::sin(a);
  const Vec3 u(radius * ca, height, radius * sa);
  const Vec3 du(dRadius * ca, dHeight, dRadius * sa), dua(-radius * sa, 0.0, radius * ca);
  Eigen::Matrix3d jacobian;
  jacobian << c.x * (1.0 + c.tx * u.y()), c.x * c.tx * u.x(), 0.0, 0.0, c.y, 0.0, 0.0, c.z * c.tz * u.z(),
      c.z * (1.0 + c.tz * u.y());
  const Eigen::Matrix3d toWorld = rotation_ * jacobian;
  return {fromUnit(u), toWorld * du, toWorld * dua};
}

Vec3 Capsule::surface(double t, double a) const {
  double radius, height;
  profile(t, radius, height);
  return fromUnit(Vec3(radius * std::cos(a), height, radius * std::sin(a)));
}

bool Capsule::contains(const Vec3& p) const {
  return containsUnit(toUnit(p));
}

bool Capsule::containsUnit(const Vec3& u) const {
  if (std::abs(u.y()) > 0.5) return false;                       // beyond the ends (and where the taper flips)
  const double radial = (u.x() * u.x() + u.z() * u.z()) / 0.25;  // (rho / R)^2
  if (u.y() >= bottom_ && u.y() <= top_) return radial <= 1.0;
  const double capHeight = 0.5 * (u.y() < bottom_ ? parameters_.r1 : parameters_.r2);
  const double along = (u.y() < bottom_ ? bottom_ - u.y() : u.y() - top_) / capHeight;
  return radial + along * along <= 1.0;
}

Vec3 Capsule::unitProjection(const Vec3& u) const {
  const double r1 = parameters_.r1, r2 = parameters_.r2, bottom = bottom_, top = top_;
  const double rho = std::sqrt(u.x() * u.x() + u.z() * u.z());
  const Vec3 radial = rho > 1e-12 ? Vec3(u.x() / rho, 0.0, u.z() / rho) : Vec3::UnitX();
  const double h = u.y();
  auto end = [&](double centre, double rounding, double side) -> Vec3 {  // side: -1 bottom, +1 top
    if (rounding <= 0.0) return std::min(rho, 0.5) * radial + Vec3(0.0, centre, 0.0);
    const double along = (h - centre) / rounding;  // in the end's hemisphere space
    const double length = std::sqrt(rho * rho + along * along);
    if (length < 1e-12) return Vec3(0.0, centre + side * 0.5 * rounding, 0.0);
    return 0.5 * rho / length * radial + Vec3(0.0, centre + 0.5 * along / length * rounding, 0.0);
  };
  if (h < bottom) return end(bottom, r1, -1.0);
  if (h > top) return end(top, r2, 1.0);
  // Between the ends: the side, or a flat end when that is nearer (from inside).
  Vec3 best = 0.5 * radial + Vec3(0.0, h, 0.0);
  double gap = std::abs(0.5 - rho);
  if (r1 <= 0.0 && rho < 0.5 && h - bottom < gap) best = rho * radial + Vec3(0.0, bottom, 0.0), gap = h - bottom;
  if (r2 <= 0.0 && rho < 0.5 && top - h < gap) best = rho * radial + Vec3(0.0, top, 0.0);
  return best;
}

void Capsule::project(const Vec3& unit, double& t, double& a) const {
  // The parameters of the unit-space projection (the paper's path): the starting guess.
  const Vec3 q = unitProjection(unit);
  a = std::atan2(q.z(), q.x());
  const double rho = std::sqrt(q.x() * q.x() + q.z() * q.z()) / 0.5;  // 0 at the axis, 1 at the side
  const double r1 = parameters_.r1, r2 = parameters_.r2;
  // On an end, (rho, along) = (sin b, cos b) of the profile's angle; a flat end's disc
  // has along = sqrt(1 - rho^2) by the same parametrisation.
  const double flat = std::sqrt(std::max(0.0, 1.0 - rho * rho));
  if (q.y() < bottom_ || (q.y() == bottom_ && rho < 1.0 && r1 <= 0.0))
    t = std::atan2(rho, r1 > 0.0 ? (bottom_ - q.y()) / (0.5 * r1) : flat) / (0.5 * M_PI);
  else if (q.y() > top_ || (q.y() == top_ && rho < 1.0 && r2 <= 0.0))
    t = 2.0 + std::atan2(r2 > 0.0 ? (q.y() - top_) / (0.5 * r2) : flat, rho) / (0.5 * M_PI);
  else
    t = top_ > bottom_ ? 1.0 + (q.y() - bottom_) / (top_ - bottom_) : 1.5;
  t = std::clamp(t, 0.0, 3.0);
}

SurfacePoint Capsule::nearest(const Vec3& p) const {
  double t, a;
  project(toUnit(p), t, a);
  const auto side = [this](double ti, double ai) { return sample(ti, ai); };
  const Vec3 w = projectOntoSurface(side, p, 0.0, 3.0, t, a);
  SurfacePoint out;
  out.point = w;
  const bool inside = contains(p);
  const double gap = (p - w).norm();
  out.distance = inside ? -gap : gap;
  // The normal: along p - w for a point clearly outside (exact at the nearest point, and
  // the push direction at a flat end's rim); else from the surface's tangents.
  if (!inside && gap > 1e-6) {
    out.normal = (p - w) / gap;
    return out;
  }
  // Outward: away from the centre (the capsule is star-shaped about it); at a pole, the
  // axis.
  const Vec3 axis = rotation_ * Vec3::UnitY();
  out.normal = surfaceNormal(sample(t, a), w - fromUnit(Vec3::Zero()), t < 1.5 ? -axis : axis);
  return out;
}

SurfacePoint Capsule::nearestFast(const Vec3& p) const {
  double t, a;
  const Vec3 u = toUnit(p);  // once: the inside test and the starting guess share it
  project(u, t, a);
  const auto side = [this](double ti, double ai) { return sample(ti, ai); };
  SurfaceSample s = refineOnSurface(side, p, 0.0, 3.0, t, a, 2);
  SurfacePoint out;
  const bool inside = containsUnit(u);
  double gap = (p - s.w).norm();
  if (!inside && gap > 1e-6) {
    out.point = s.w, out.distance = gap, out.normal = (p - s.w) / gap;
    return out;
  }
  // Inside (or on the surface): the surface's normal, unless p does not lie along it (a
  // deep point's two steps stop short of the stationary point), when the push-out to
  // point + clearance normal would move p sideways: then the way out from p to the point.
  const Vec3 axis = rotation_.col(1), centre(parameters_.ox, parameters_.oy, parameters_.oz);
  out.normal = surfaceNormal(s, s.w - centre, t < 1.5 ? -axis : axis);
  if (gap > 1e-6 && sideways(p - s.w, out.normal) > kSideways) out.normal = (s.w - p) / gap;
  out.point = s.w;
  out.distance = inside ? -gap : gap;
  return out;
}

}  // namespace figment
