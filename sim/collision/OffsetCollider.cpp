#include "sim/collision/OffsetCollider.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace figment {

OffsetCollider::OffsetCollider(std::shared_ptr<const Collider> inner, double offset)
    : inner_(std::move(inner)), offset_(offset) {
  if (!inner_) throw std::invalid_argument("offset collider: the inner collider is null");
  if (!(offset >= 0.0) || !std::isfinite(offset))
    throw std::invalid_argument("offset = " + std::to_string(offset) + " m must be finite and >= 0");
}

bool OffsetCollider::contact(const Vec3& p, double clearance, double searchRadius, Contact& out) const {
  const bool touching = inner_->contact(p, clearance + offset_, searchRadius + offset_, out);
  out.distance -= offset_;
  if (touching) out.surfacePoint += offset_ * out.normal;
  return touching;
}

std::shared_ptr<const Collider> OffsetCollider::focusedOn(const Eigen::AlignedBox3d& region, double reach) const {
  // What the inner collider leaves out lies `reach + offset` from the region: the moved
  // surface, `reach`.
  std::shared_ptr<const Collider> focused = inner_->focusedOn(region, reach + offset_);
  return focused ? std::make_shared<OffsetCollider>(std::move(focused), offset_) : nullptr;
}

}  // namespace figment
