#pragma once
// Several colliders as one (the body beside a floor, a mannequin on a stand). A point
// is in contact when it is in contact with any part; the contact reported is the
// deepest one:
//
//   contact(p) = the part's contact with the smallest signed distance among the parts
//                in contact (ties: the part added first)
//   bound(p)   = min over parts of their lower bounds, when no part is in contact
//
// The minimum of lower bounds is a lower bound of the distance to the union's surface,
// so the solver's query skipping stays exact. The parts are shared and never modified.

#include <memory>
#include <vector>

#include "sim/collision/Collider.h"

namespace figment {

class CompositeCollider : public Collider {
 public:
  CompositeCollider() = default;
  // Throws std::invalid_argument when a part is null.
  explicit CompositeCollider(std::vector<std::shared_ptr<const Collider>> parts);

  // Appends a part; throws std::invalid_argument when it is null.
  void add(std::shared_ptr<const Collider> part);

  // With no parts: false, and out.distance = +infinity (there is nothing to touch).
  bool contact(const Vec3& p, double clearance, double searchRadius, Contact& out) const override;

  // Each part focused (or kept whole where it leaves nothing out); null when no part
  // leaves anything out.
  std::shared_ptr<const Collider> focusedOn(const Eigen::AlignedBox3d& region, double reach) const override;

  // Whether any part moves, and each part moved to `time`: a posed body in a group moves
  // into its pose as it does alone.
  bool moves() const override;
  void advanceTo(double time) const override;

  const std::vector<std::shared_ptr<const Collider>>& parts() const { return parts_; }

 private:
  std::vector<std::shared_ptr<const Collider>> parts_;
};

}  // namespace figment
