#include "sim/body/GirthBlend.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace figment {

GirthBlend::GirthBlend(const Skeleton& skeleton, const Sizing& sizing, double length) : length_(length) {
  sizing.validate();
  if (!(length > 0.0)) throw std::invalid_argument("girth blend length = " + std::to_string(length) + " must be > 0");
  const size_t n = skeleton.parts.size();
  std::vector<std::optional<double>> girth(n);
  for (size_t k = 0; k < n; ++k) girth[k] = girthFactor(skeleton.parts[k], sizing);
  own_.assign(n, 1.0);
  joints_.assign(n, {});
  for (size_t k = 0; k < n; ++k) {
    if (!girth[k]) continue;
    own_[k] = *girth[k];
    const BodyPart& part = skeleton.parts[k];
    const Vec3 from = skeleton.joints[part.from].position, to = skeleton.joints[part.to].position;
    if (!((to - from).norm() > 0.0)) continue;
    for (size_t m = 0; m < n; ++m) {
      if (m == k || !girth[m] || !(*girth[m] > *girth[k])) continue;
      const BodyPart& other = skeleton.parts[m];
      for (const int j : {part.from, part.to})
        if (j == other.from || j == other.to)
          joints_[k].push_back(
              {skeleton.joints[j].position, (j == part.from ? to - from : from - to).normalized(), *girth[m]});
    }
  }
}

double GirthBlend::growth(int part, const Vec3& restPoint) const {
  if (part < 0 || part >= static_cast<int>(own_.size())) return 1.0;
  double factor = own_[part];
  for (const Joint& j : joints_[part]) {
    const double depth = (restPoint - j.position).dot(j.inward);  // into the part from the joint's plane
    const double weight = std::clamp(1.0 - depth / length_, 0.0, 1.0);
    factor = std::max(factor, own_[part] + weight * (j.factor - own_[part]));
  }
  return factor / own_[part];
}

}  // namespace figment
