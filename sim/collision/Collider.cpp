#include "sim/collision/Collider.h"

namespace figment {

std::shared_ptr<const Collider> Collider::focusedOn(const Eigen::AlignedBox3d&, double) const {
  return nullptr;
}

}  // namespace figment
