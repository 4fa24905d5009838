#include "sim/cloth/NodeTerms.h"

namespace figment {

NodeTerms::NodeTerms(const std::vector<MembraneElement>& sections, size_t nodeCount, const ClothParameters& parameters)
    : masses_(nodeCount, 0.0),
      inverseMasses_(nodeCount, 0.0),
      areas_(nodeCount, 0.0),
      gravity_(parameters.gravity),
      airResistance_(parameters.airResistance),
      wind_(parameters.wind) {
  const double arealDensity = parameters.material.arealDensity();
  for (const MembraneElement& section : sections)
    for (int i : section.corners()) {
      areas_[i] += section.restArea() / 3.0;
      masses_[i] += arealDensity * section.restArea() / 3.0;
    }
  for (size_t i = 0; i < nodeCount; ++i) inverseMasses_[i] = masses_[i] > 0.0 ? 1.0 / masses_[i] : 0.0;
}

Vec3 NodeTerms::windCornerForce(const MembraneElement& section, const std::vector<Vec3>& x, double pressure) const {
  const Triangle& c = section.corners();
  return figment::windCornerForce(x[c[0]], x[c[1]], x[c[2]], pressure, wind_.direction());
}

}  // namespace figment
