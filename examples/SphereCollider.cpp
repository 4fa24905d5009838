#include "SphereCollider.h"

SphereCollider::SphereCollider(const figment::Vec3& centre, double radius) : centre_(centre), radius_(radius) {}

bool SphereCollider::contact(const figment::Vec3& p, double clearance, double /*searchRadius*/,
                             figment::Contact& out) const {
  const figment::Vec3 fromCentre = p - centre_;
  const double r = fromCentre.norm();
  out.distance = r - radius_;
  if (out.distance >= clearance) return false;
  // At the very centre every direction is nearest: pick one, the same every time.
  out.normal = r > 1e-12 ? figment::Vec3(fromCentre / r) : figment::Vec3::UnitY();
  out.surfacePoint = centre_ + radius_ * out.normal;
  return true;
}
