#pragma once
// The garment's node terms (paper §2): the masses lumped from the sections and the
// forces that act on the nodes from outside the cloth, each written once for every
// integrator:
//
//   mass     m_i = sum over node i's sections of rho h A / 3                        kg
//   area     A_i = sum over node i's sections of A / 3      (its share of cloth)    m^2
//   gravity  m_i g                                                                  N
//   air      -k A_i v_i, k the air resistance (N s/m^3); its damping -df/dv = k A_i I
//   wind     p(t) A |n . w| w / 3 on each corner of every section (sim/cloth/Wind.h)
//
// A node that only degenerate (zero-area) sections touch has no mass: nothing acts on it
// but gravity, and it floats (floats(i)); the integrators move it with g alone.

#include <vector>

#include "sim/cloth/ClothParameters.h"
#include "sim/cloth/MembraneElement.h"
#include "sim/cloth/Wind.h"

namespace figment {

class NodeTerms {
 public:
  // `sections`: the garment's valid sections, over `nodeCount` nodes.
  NodeTerms(const std::vector<MembraneElement>& sections, size_t nodeCount, const ClothParameters& parameters);

  const std::vector<double>& masses() const { return masses_; }     // kg
  double inverseMass(size_t i) const { return inverseMasses_[i]; }  // 1/kg; 0 for a floating node
  bool floats(size_t i) const { return inverseMasses_[i] == 0.0; }
  const Vec3& gravity() const { return gravity_; }               // g, m/s^2
  Vec3 weight(size_t i) const { return masses_[i] * gravity_; }  // m_i g, N

  // The air's drag k A_i v_i on node i moving at v (N): the air resistance is its negative.
  Vec3 drag(size_t i, const Vec3& v) const { return airResistance_ * areas_[i] * v; }
  // w k A_i: the drag's derivative in v, weighted by w (a backward Euler step's dt).
  double weightedDragRate(size_t i, double w) const { return w * airResistance_ * areas_[i]; }

  const Wind& wind() const { return wind_; }
  // The wind's force on each corner of `section` at positions x and pressure p(t) (N).
  Vec3 windCornerForce(const MembraneElement& section, const std::vector<Vec3>& x, double pressure) const;

 private:
  std::vector<double> masses_, inverseMasses_;
  std::vector<double> areas_;  // m^2
  Vec3 gravity_;
  double airResistance_;  // k, N s/m^3
  Wind wind_;
};

}  // namespace figment
