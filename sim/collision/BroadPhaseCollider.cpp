#include "sim/collision/BroadPhaseCollider.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace figment {

BroadPhaseCollider::BroadPhaseCollider(std::shared_ptr<const Collider> body, double slack, double reach)
    : whole_(std::move(body)), slack_(slack), reach_(reach) {
  if (!whole_) throw std::invalid_argument("broad phase: the body is null");
  if (!(slack > 0.0) || !(reach > 0.0))
    throw std::invalid_argument("broad phase: slack = " + std::to_string(slack) +
                                " m and reach = " + std::to_string(reach) + " m must be positive");
}

void BroadPhaseCollider::follow(const std::vector<Vec3>& nodes) {
  if (nodes.empty()) return;
  Eigen::AlignedBox3d bounds;
  for (const Vec3& x : nodes) bounds.extend(x);
  if (!region_.isEmpty() && region_.contains(bounds)) return;
  const Vec3 grow = Vec3::Constant(slack_);
  region_ = Eigen::AlignedBox3d(bounds.min() - grow, bounds.max() + grow);
  focused_ = whole_->focusedOn(region_, reach_);
  ++refocusCount_;
}

bool BroadPhaseCollider::contact(const Vec3& p, double clearance, double searchRadius, Contact& out) const {
  if (focused_ && region_.contains(p) && 2.0 * clearance < reach_) {
    Contact focused;
    if (!focused_->contact(p, clearance, searchRadius, focused)) {
      out = focused;
      out.distance = std::min(out.distance, reach_);
      return false;
    }
    const Vec3 target = focused.surfacePoint + clearance * focused.normal;
    if ((target - p).norm() <= reach_ - clearance) {
      out = focused;
      return true;
    }
  }
  return whole_->contact(p, clearance, searchRadius, out);
}

}  // namespace figment
