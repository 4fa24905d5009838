#include "sim/cloth/ClothModel.h"

#include <algorithm>
#include <array>
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

// The garment's sections, leaving out the degenerate ones.
std::vector<MembraneElement> sectionsOf(const TriangleMesh& rest) {
  std::vector<MembraneElement> sections;
  for (const Triangle& t : rest.triangles) {
    MembraneElement section(t, rest.vertices[t[0]], rest.vertices[t[1]], rest.vertices[t[2]]);
    if (section.valid()) sections.push_back(section);
  }
  if (sections.empty()) throw std::invalid_argument("every garment triangle is degenerate (zero area)");
  return sections;
}
}  // namespace

ClothModel::ClothModel(const TriangleMesh& rest, const ClothParameters& parameters)
    : parameters_(parameters),
      law_(parameters.material),
      sections_(sectionsOf(checkedGarment(rest))),
      bending_(rest, parameters.material.bendingStiffness(), parameters.material.poissonRatio),
      nodes_(sections_, rest.vertices.size(), parameters) {
  force_.resize(rest.vertices.size());
}

void ClothModel::accelerations(const std::vector<Vec3>& x, const std::vector<Vec3>& v, double t,
                               std::vector<Vec3>& a) const {
  const size_t n = nodeCount();
  const bool limited = parameters_.accelerationLimiter != AccelerationLimiter::None;
  std::fill(force_.begin(), force_.end(), Vec3::Zero());
  ++counts_.evaluations;
  // With a limiter, the elastic pull (membrane and bending) is limited on its own and
  // the strain-rate damping is added after it; without, one pass adds both.
  const double damping = limited ? 0.0 : parameters_.strainRateDamping;
  for (const MembraneElement& section : sections_)
    counts_.clampedSections += addSectionForces(section, x, v, {true, damping, parameters_.strainLimit});
  bending_.addForces(x, force_);
  a.assign(n, Vec3::Zero());
  if (limited) {
    for (size_t i = 0; i < n; ++i) a[i] = force_[i] * nodes_.inverseMass(i);
    limitAccelerations(a);
    std::fill(force_.begin(), force_.end(), Vec3::Zero());
    if (parameters_.strainRateDamping > 0.0)
      for (const MembraneElement& section : sections_)
        addSectionForces(section, x, v, {false, parameters_.strainRateDamping, 0.0});
  }
  if (nodes_.wind().blows()) addWindForces(x, t);
  for (size_t i = 0; i < n; ++i) {
    if (nodes_.floats(i)) {
      a[i] = nodes_.gravity();
      continue;
    }
    force_[i] -= nodes_.drag(i, v[i]);
    a[i] += force_[i] * nodes_.inverseMass(i) + nodes_.gravity();
  }
}

bool ClothModel::addSectionForces(const MembraneElement& section, const std::vector<Vec3>& x,
                                  const std::vector<Vec3>& v, const MembraneRequest& request) const {
  std::array<Vec3, 3> f;
  const bool clamped = section.evaluate(x, v, law_, request, nullptr, {f.data(), nullptr, nullptr});
  for (int a = 0; a < 3; ++a) force_[section.corners()[a]] += f[a];
  return clamped;
}

void ClothModel::addWindForces(const std::vector<Vec3>& x, double t) const {
  // F = p(t) A |n . w| w per section, a third to each corner (sim/cloth/Wind.h). Every
  // section feels the full wind (no shadowing).
  const double pressure = nodes_.wind().pressure(t);
  for (const MembraneElement& section : sections_) {
    const Vec3 cornerForce = nodes_.windCornerForce(section, x, pressure);
    for (int i : section.corners()) force_[i] += cornerForce;
  }
}

Vec3 ClothModel::totalWindForce(const std::vector<Vec3>& x, double t) const {
  Vec3 total = Vec3::Zero();
  if (!nodes_.wind().blows()) return total;
  const double pressure = nodes_.wind().pressure(t);
  for (const MembraneElement& section : sections_) total += 3.0 * nodes_.windCornerForce(section, x, pressure);
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
