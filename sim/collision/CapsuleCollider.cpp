#include "sim/collision/CapsuleCollider.h"

#include <algorithm>

namespace figment {

CapsuleCollider::CapsuleCollider(const CapsuleParameters& parameters)
    : capsule_(parameters), centre_(capsule_.fromUnit(Vec3::Zero())) {
  // The taper is bilinear in (x, y) and (z, y): the image of the unit box lies in the
  // convex hull of its corners' images, so the farthest corner bounds the capsule.
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 u(corner & 1 ? 0.5 : -0.5, corner & 2 ? 0.5 : -0.5, corner & 4 ? 0.5 : -0.5);
    radius_ = std::max(radius_, (capsule_.fromUnit(u) - centre_).norm());
  }
}

bool CapsuleCollider::contact(const Vec3& p, double clearance, double /*searchRadius*/, Contact& out) const {
  const double outside = (p - centre_).norm() - radius_;
  if (outside > clearance) {
    out.distance = outside;
    return false;
  }
  const SurfacePoint s = capsule_.nearestFast(p);
  out = {s.point, s.normal, s.distance};
  return s.distance < clearance;
}

}  // namespace figment
