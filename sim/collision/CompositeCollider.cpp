#include "sim/collision/CompositeCollider.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace figment {

CompositeCollider::CompositeCollider(std::vector<std::shared_ptr<const Collider>> parts) {
  for (auto& part : parts) add(std::move(part));
}

void CompositeCollider::add(std::shared_ptr<const Collider> part) {
  if (!part) throw std::invalid_argument("collider part " + std::to_string(parts_.size()) + " is null");
  parts_.push_back(std::move(part));
}

std::shared_ptr<const Collider> CompositeCollider::focusedOn(const Eigen::AlignedBox3d& region, double reach) const {
  auto focused = std::make_shared<CompositeCollider>();
  bool narrower = false;
  for (const auto& part : parts_) {
    std::shared_ptr<const Collider> f = part->focusedOn(region, reach);
    narrower = narrower || f;
    focused->add(f ? std::move(f) : part);
  }
  return narrower ? focused : nullptr;
}

bool CompositeCollider::moves() const {
  return std::any_of(parts_.begin(), parts_.end(), [](const auto& part) { return part->moves(); });
}

void CompositeCollider::advanceTo(double time) const {
  for (const auto& part : parts_) part->advanceTo(time);
}

bool CompositeCollider::contact(const Vec3& p, double clearance, double searchRadius, Contact& out) const {
  bool touching = false;
  double bound = std::numeric_limits<double>::infinity();
  for (const auto& part : parts_) {
    Contact candidate;
    if (part->contact(p, clearance, searchRadius, candidate)) {
      // Strictly deeper only, so that of equally deep contacts the first part wins.
      if (!touching || candidate.distance < out.distance) out = candidate;
      touching = true;
    } else if (!touching) {
      bound = std::min(bound, candidate.distance);
    }
  }
  if (!touching) out.distance = bound;
  return touching;
}

}  // namespace figment
