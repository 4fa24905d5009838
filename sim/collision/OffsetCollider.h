#pragma once
// A collider's surface moved out along its normal by a fixed distance: an inner garment's
// draped surface with the thickness of its cloth on it, for a garment draped over it
// (paper §6's layers). For a query at p:
//
//   contact(p, clearance) = the inner collider's contact with clearance + offset, its
//                           surface point moved `offset` out along the normal and its
//                           distance less `offset`
//   bound (no contact)    = the inner bound less `offset` (a surface moved out by
//                           `offset` is at most that much nearer)

#include <memory>

#include "sim/collision/Collider.h"

namespace figment {

class OffsetCollider : public Collider {
 public:
  // Throws std::invalid_argument when `inner` is null or `offset` negative or not finite.
  OffsetCollider(std::shared_ptr<const Collider> inner, double offset);

  bool contact(const Vec3& p, double clearance, double searchRadius, Contact& out) const override;
  std::shared_ptr<const Collider> focusedOn(const Eigen::AlignedBox3d& region, double reach) const override;

  // The inner collider's motion, passed on (a moving surface moves its offset too).
  bool moves() const override { return inner_->moves(); }
  void advanceTo(double time) const override { inner_->advanceTo(time); }

  double offset() const { return offset_; }

 private:
  std::shared_ptr<const Collider> inner_;
  double offset_;
};

}  // namespace figment
