#include "sim/collision/PlaneCollider.h"

#include <cmath>
#include <stdexcept>

#include "sim/core/ParameterChecks.h"

namespace figment {

PlaneCollider::PlaneCollider(const Vec3& point, const Vec3& normal) : point_(point) {
  for (int axis = 0; axis < 3; ++axis) requireFinite("point", point[axis]);
  const double length = normal.norm();
  if (!(length > 0.0) || !std::isfinite(length))
    throw std::invalid_argument("normal = (" + formatNumber(normal.x()) + ", " + formatNumber(normal.y()) + ", " +
                                formatNumber(normal.z()) + ") must be a finite, nonzero vector");
  normal_ = normal / length;
}

bool PlaneCollider::contact(const Vec3& p, double clearance, double /*searchRadius*/, Contact& out) const {
  const double distance = normal_.dot(p - point_);
  out.distance = distance;
  out.surfacePoint = p - distance * normal_;
  out.normal = normal_;
  return distance < clearance;
}

}  // namespace figment
