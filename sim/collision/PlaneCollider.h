#pragma once
// An infinite plane as a collider (paper §3's simplest body): a floor, an inclined
// plane, a table top. Everything behind the plane (opposite its normal) is inside.
//
//   signed distance   d(p) = n . (p - o)        m, negative behind the plane
//   surface point     s(p) = p - d(p) n         the projection of p onto the plane
//   normal            n                         unit, the outward normal everywhere
//
// with o a point on the plane (m) and n its unit outward normal.

#include "sim/collision/Collider.h"

namespace figment {

class PlaneCollider : public Collider {
 public:
  // `point` lies on the plane (m); `normal` points out of the solid side, any length but
  // zero (it is normalised). Throws std::invalid_argument naming `normal` when it is
  // zero or not finite.
  PlaneCollider(const Vec3& point, const Vec3& normal);

  // True when d(p) < clearance. The plane is found at any distance, so `searchRadius`
  // is not needed: when it returns false, out.distance is d(p) itself, an exact (hence
  // valid lower) bound. `out` is filled in either case.
  bool contact(const Vec3& p, double clearance, double searchRadius, Contact& out) const override;

  const Vec3& point() const { return point_; }
  const Vec3& normal() const { return normal_; }

 private:
  Vec3 point_;
  Vec3 normal_;
};

}  // namespace figment
