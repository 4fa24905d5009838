#include "CapsuleCollider.h"

namespace figment {

bool CapsuleCollider::contact(const Vec3& p, double clearance, double /*searchRadius*/, Contact& out) const {
  const SurfacePoint s = capsule_.nearestFast(p);
  out = {s.point, s.normal, s.distance};
  return s.distance < clearance;
}

}  // namespace figment
