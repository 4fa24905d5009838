#pragma once
// SphereCollider: what the cloth simulation asks of a sphere (figment::Collider, from the
// installed sim/collision/Collider.h): is a point inside or near it, where is the
// nearest surface point and which way is out.

#include <sim/collision/Collider.h>

class SphereCollider : public figment::Collider {
 public:
  SphereCollider(const figment::Vec3& centre, double radius);

  // True when `p` lies inside the sphere or within `clearance` of its surface; `out`
  // then holds the nearest surface point, the outward normal there and p's signed
  // distance (negative inside). When false, out.distance is p's distance to the
  // surface (exact: a sphere need not bound it by `searchRadius`).
  bool contact(const figment::Vec3& p, double clearance, double searchRadius, figment::Contact& out) const override;

 private:
  figment::Vec3 centre_;
  double radius_;
};
