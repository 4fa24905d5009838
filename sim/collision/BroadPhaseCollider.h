#pragma once
// The broad phase: body parts far from the garment are never tested. A collider that
// follows the garment's bounds (follow(), between steps) and answers each query from the
// body focused on them (Collider::focusedOn: the parts within `reach` of the box around
// the garment, grown by `slack`), falling back to the whole body wherever the focus
// cannot vouch for the answer:
//
//   p outside the box                      the whole body
//   nothing touches p                      the focused answer, its lower bound capped at
//                                          `reach` (every part left out is that far)
//   touching, target within reach - clear  the focused answer (a part left out is more
//                                          than the clearance from the target)
//   touching, target farther               the whole body
//
// So every answer is the whole body's (the bounds may differ; they stay lower bounds of
// the distance, which is all the solver's query skipping needs) and a drape is the same
// with or without it. The box moves only when a node leaves it, so the focus is rebuilt a
// few times a drape. contact() is const and safe from several threads; follow() must not
// run beside it.

#include <memory>
#include <vector>

#include "sim/collision/Collider.h"

namespace figment {

class BroadPhaseCollider : public Collider {
 public:
  static constexpr double kDefaultSlack = 0.05;  // m the box grows beyond the garment
  static constexpr double kDefaultReach = 0.10;  // m from the box beyond which parts are left out

  // Throws std::invalid_argument when `body` is null, or slack or reach is not positive
  // (or reach not above twice any clearance it will be asked with: checked per query).
  explicit BroadPhaseCollider(std::shared_ptr<const Collider> body, double slack = kDefaultSlack,
                              double reach = kDefaultReach);

  // Focuses on the box around `nodes` (grown by the slack) unless every node still lies in
  // the current one.
  void follow(const std::vector<Vec3>& nodes);

  bool contact(const Vec3& p, double clearance, double searchRadius, Contact& out) const override;

  const Collider& whole() const { return *whole_; }
  // The body as focused now: null before the first follow() or when the focus leaves
  // nothing out.
  const Collider* focused() const { return focused_.get(); }
  const Eigen::AlignedBox3d& region() const { return region_; }
  int refocusCount() const { return refocusCount_; }

 private:
  std::shared_ptr<const Collider> whole_, focused_;
  Eigen::AlignedBox3d region_;  // empty until the first follow()
  double slack_, reach_;
  int refocusCount_ = 0;
};

}  // namespace figment
