#pragma once
// A capsule (sim/collision/Capsule.h) as a collider: one body part's collision volume.

#include "sim/collision/Capsule.h"
#include "sim/collision/Collider.h"

namespace figment {

class CapsuleCollider : public Collider {
 public:
  explicit CapsuleCollider(const CapsuleParameters& parameters);

  // True when p is inside or within `clearance` of the surface, by Capsule::nearestFast
  // (the paper's path with a world-space correction). A point farther than `clearance`
  // from the capsule's bounding sphere is answered from the sphere alone: false, with
  // out.distance = its distance to the sphere (a lower bound of its distance to the
  // capsule). Otherwise out is filled from the fast path; when it returns false,
  // out.distance is p's distance (to the fast path's accuracy).
  bool contact(const Vec3& p, double clearance, double searchRadius, Contact& out) const override;

  const Capsule& capsule() const { return capsule_; }

 private:
  Capsule capsule_;
  Vec3 centre_;          // of the bounding sphere: the capsule's centre
  double radius_ = 0.0;  // m: the farthest corner of the tapered, scaled, tilted unit box
};

}  // namespace figment
