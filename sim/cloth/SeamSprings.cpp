#include "sim/cloth/SeamSprings.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace figment {

SeamSprings::SeamSprings(std::vector<std::array<int, 2>> seams, const std::vector<double>& masses, double rate)
    : seams_(std::move(seams)) {
  if (!(rate > 0.0) || !std::isfinite(rate))
    throw std::invalid_argument("seam rate = " + std::to_string(rate) + " 1/s^2 must be > 0");
  const int n = static_cast<int>(masses.size());
  for (const auto& [a, b] : seams_) {
    if (a < 0 || a >= n || b < 0 || b >= n)
      throw std::invalid_argument("seam (" + std::to_string(a) + ", " + std::to_string(b) +
                                  ") names a node out of [0, " + std::to_string(n) + ")");
    if (a == b)
      throw std::invalid_argument("seam (" + std::to_string(a) + ", " + std::to_string(b) + ") joins a node to itself");
    const double m = 0.5 * (masses[a] + masses[b]);
    stiffness_.push_back(rate * m);
    damping_.push_back(2.0 * std::sqrt(rate) * m);
  }
}

void SeamSprings::evaluate(size_t seam, const std::vector<Vec3>& x, const std::vector<Vec3>& v, bool elastic,
                           bool damping, const SystemWeights* weights, const ElementOutput& out) const {
  const auto [a, b] = seams_[seam];
  const double k = elastic ? stiffness_[seam] : 0.0, c = damping ? damping_[seam] : 0.0;
  out.force[0] = k * (x[b] - x[a]) + c * (v[b] - v[a]);
  out.force[1] = -out.force[0];
  if (!weights) return;
  out.stiffnessTimesVelocity[0] = k * (v[a] - v[b]);
  out.stiffnessTimesVelocity[1] = -out.stiffnessTimesVelocity[0];
  const double w = weights->damping * c + weights->stiffness * k;
  out.blocks[0] = w * Block3::Identity();
  out.blocks[1] = -w * Block3::Identity();
  out.blocks[2] = -w * Block3::Identity();
  out.blocks[3] = w * Block3::Identity();
}

void SeamSprings::strengthen(double factor) {
  if (!(factor > 0.0) || !std::isfinite(factor))
    throw std::invalid_argument("seam strengthening factor = " + std::to_string(factor) + " must be > 0");
  for (double& k : stiffness_) k *= factor;
  // Critical damping of the pair scales with sqrt(k).
  for (double& c : damping_) c *= std::sqrt(factor);
}

double SeamSprings::largestGap(const std::vector<Vec3>& x) const {
  double largest = 0.0;
  for (const auto& [a, b] : seams_) largest = std::max(largest, (x[a] - x[b]).norm());
  return largest;
}

}  // namespace figment
