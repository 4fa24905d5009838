#pragma once
// The FIGMENT physical model of one garment (paper §2): triangular sections with
// stretch/shear stresses, plate bending from the angles at the joints between them
// (sim/cloth/PlateBending.h), and the node terms (sim/cloth/NodeTerms.h): gravity, air
// resistance and wind (sim/cloth/Wind.h), acting on nodes whose masses are lumped from
// the sections (rho h A / 3 per corner).
// Collisions and friction are contact events, handled by the solver after each step.

#include "sim/cloth/ClothParameters.h"
#include "sim/cloth/MembraneElement.h"
#include "sim/cloth/NodeTerms.h"
#include "sim/cloth/PlateBending.h"
#include "sim/core/TriangleMesh.h"

#include <vector>

namespace figment {

class ClothModel {
 public:
  // Throws std::invalid_argument for an empty garment, an index out of range or a
  // garment whose sections are all degenerate.
  ClothModel(const TriangleMesh& rest, const ClothParameters& parameters);

  // a = F(x, v, t) / m for every node (m/s^2) at simulated time t (s). With an
  // acceleration limiter, the elastic part (membrane and bending) of each node's
  // acceleration is limited before gravity, air, wind and the strain-rate damping are
  // added: cutting the damping too let Heun amplify the fast membrane modes, and a
  // sliding skirt shredded. Only the wind depends on t.
  void accelerations(const std::vector<Vec3>& x, const std::vector<Vec3>& v, double t, std::vector<Vec3>& a) const;

  // Held (pinned) nodes: sections between them are clamps that do not bend.
  void hold(const std::vector<char>& heldNodes) { bending_.hold(heldNodes); }

  // How often the stability measures engaged since construction: sections whose strain
  // was clamped and nodes whose acceleration was limited, counted per force evaluation.
  struct LimiterCounts {
    long long evaluations = 0, clampedSections = 0, limitedNodes = 0;
  };
  const LimiterCounts& limiterCounts() const { return counts_; }

  const std::vector<double>& masses() const { return nodes_.masses(); }  // kg
  const std::vector<MembraneElement>& sections() const { return sections_; }
  const PlaneStressLaw& law() const { return law_; }
  const PlateBending& bending() const { return bending_; }
  const NodeTerms& nodes() const { return nodes_; }
  size_t nodeCount() const { return nodes_.masses().size(); }

  // The wind's total force on the garment at positions x and time t, N: the sum of
  // every section's p(t) A |n . w| w (what the integrators apply; zero when no wind
  // blows). For reports and charts (figment-view --wind-force).
  Vec3 totalWindForce(const std::vector<Vec3>& x, double t) const;
  const Wind& wind() const { return nodes_.wind(); }

 private:
  // Adds a section's forces; returns whether its strain was clamped.
  bool addSectionForces(const MembraneElement& section, const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                        const MembraneRequest& request) const;
  void addWindForces(const std::vector<Vec3>& x, double t) const;
  void limitAccelerations(std::vector<Vec3>& a) const;

  ClothParameters parameters_;
  PlaneStressLaw law_;
  std::vector<MembraneElement> sections_;
  PlateBending bending_;
  NodeTerms nodes_;
  mutable std::vector<Vec3> force_;
  mutable LimiterCounts counts_;
};

}  // namespace figment
