#pragma once
// A capsule (sim/Capsule.h) as a collider: one body part's collision volume.

#include "Capsule.h"
#include "Collider.h"

namespace figment {

class CapsuleCollider : public Collider {
 public:
  explicit CapsuleCollider(const CapsuleParameters& parameters) : capsule_(parameters) {}

  // True when p is inside or within `clearance` of the surface, by Capsule::nearestFast
  // (the paper's path with a world-space correction). It answers at any distance, so
  // `searchRadius` is not needed: when it returns false, out.distance is p's distance
  // (to the fast path's accuracy). `out` is filled in either case.
  bool contact(const Vec3& p, double clearance, double searchRadius, Contact& out) const override;

  const Capsule& capsule() const { return capsule_; }

 private:
  Capsule capsule_;
};

}  // namespace figment
