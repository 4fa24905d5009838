#include "sim/cloth/ClothModel.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace figment {

namespace {
// The garment, once checked: triangles that index its vertices.
const TriangleMesh& checkedGarment(const TriangleMesh& rest) {
  const int n = static_cast<int>(rest.vertices.size());
  if (n == 0 || rest.triangles.empty()) throw std::invalid_argument("the garment has no triangles");
  for (const Triangle& t : rest.triangles)
    for (int i : t)
      if (i < 0 || i >= n)
        throw std::invalid_argument("coordIndex = " + std::to_string(i) + " is out of range [0, " +
                                    std::to_string(n - 1) + "]");
  return rest;
}
}  // namespace

ClothModel::ClothModel(const TriangleMesh& rest, const ClothParameters& parameters)
    : parameters_(parameters),
      bending_(checkedGarment(rest), parameters.material.bendingStiffness(), parameters.material.poissonRatio),
      wind_(parameters.wind) {
  const int n = static_cast<int>(rest.vertices.size());
  masses_.assign(n, 0.0);
  areas_.assign(n, 0.0);
  const double arealDensity = parameters.material.arealDensity();
  for (const Triangle& t : rest.triangles) {
    MembraneElement section(t, rest.vertices[t[0]], rest.vertices[t[1]], rest.vertices[t[2]]);
    if (!section.valid()) continue;
    for (int i : t) {
      areas_[i] += section.restArea() / 3.0;
      masses_[i] += arealDensity * section.restArea() / 3.0;
    }
    sections_.push_back(section);
  }
  if (sections_.empty()) throw std::invalid_argument("every garment triangle is degenerate (zero area)");
  inverseMasses_.resize(n);
  for (int i = 0; i < n; ++i) inverseMasses_[i] = masses_[i] > 0.0 ? 1.0 / masses_[i] : 0.0;
  force_.resize(n);
}

void ClothModel::accelerations(const std::vector<Vec3>& x, const std::vector<Vec3>& v, double t,
                               std::vector<Vec3>& a) const {
  const size_t n = masses_.size();
  const bool limited = parameters_.accelerationLimiter != AccelerationLimiter::None;
  std::fill(force_.begin(), force_.end(), Vec3::Zero());
  ++counts_.evaluations;
  // With a limiter, the elastic pull (membrane and bending) is limited on its own and
  // the strain-rate damping is added after it; without, one pass adds both.
  const double damping = limited ? 0.0 : parameters_.strainRateDamping;
  for (const MembraneElement& section : sections_)
    counts_.clampedSections +=
        section.addForces(x, v, parameters_.material, damping, parameters_.strainLimit, force_);
  bending_.addForces(x, force_);
  a.assign(n, Vec3::Zero());
  if (limited) {
    for (size_t i = 0; i < n; ++i) a[i] = force_[i] * inverseMasses_[i];
    limitAccelerations(a);
    std::fill(force_.begin(), force_.end(), Vec3::Zero());
    for (const MembraneElement& section : sections_)
      section.addDampingForces(x, v, parameters_.material, parameters_.strainRateDamping, force_);
  }
  if (wind_.blows()) addWindForces(x, t);
  for (size_t i = 0; i < n; ++i) {
    if (inverseMasses_[i] == 0.0) {  // a node of degenerate sections only: it floats with gravity
      a[i] = parameters_.gravity;
      continue;
    }
    // Air resistance opposes the node's velocity, in proportion to its share of cloth area.
    force_[i] -= parameters_.airResistance * areas_[i] * v[i];
    a[i] += force_[i] * inverseMasses_[i] + parameters_.gravity;
  }
}

void ClothModel::addWindForces(const std::vector<Vec3>& x, double t) const {
  // F = p(t) A |n . w| w per section, a third to each corner (sim/cloth/Wind.h). Every
  // section feels the full wind (no shadowing).
  const double pressure = wind_.pressure(t);
  const Vec3& w = wind_.direction();
  for (const MembraneElement& section : sections_) {
    const Triangle& c = section.corners();
    const Vec3 cornerForce = windCornerForce(x[c[0]], x[c[1]], x[c[2]], pressure, w);
    for (int i : c) force_[i] += cornerForce;
  }
}

Vec3 ClothModel::totalWindForce(const std::vector<Vec3>& x, double t) const {
  Vec3 total = Vec3::Zero();
  if (!wind_.blows()) return total;
  const double pressure = wind_.pressure(t);
  for (const MembraneElement& section : sections_) {
    const Triangle& c = section.corners();
    total += 3.0 * windCornerForce(x[c[0]], x[c[1]], x[c[2]], pressure, wind_.direction());
  }
  return total;
}

void ClothModel::limitAccelerations(std::vector<Vec3>& a) const {
  if (parameters_.accelerationLimiter == AccelerationLimiter::None) return;
  const double limit = parameters_.accelerationLimitSI();
  for (Vec3& ai : a) {
    const double magnitude = ai.norm();
    if (magnitude == 0.0) continue;
    if (parameters_.accelerationLimiter == AccelerationLimiter::Clamp) {
      if (magnitude > limit) ai *= limit / magnitude, ++counts_.limitedNodes;
    } else {
      // Smooth: every acceleration shrinks a little; count those cut by over 1 %.
      const double factor = limit * std::tanh(magnitude / limit) / magnitude;
      counts_.limitedNodes += factor < 0.99;
      ai *= factor;
    }
  }
}

}  // namespace figment
