#include "sim/cloth/implicit/ImplicitSystem.h"

#include "sim/cloth/implicit/MembraneHessian.h"

namespace figment {

namespace {
std::vector<std::vector<int>> elementNodes(const ClothModel& model, const std::vector<BendingStencil>& stencils) {
  std::vector<std::vector<int>> nodes;
  for (const MembraneElement& section : model.sections())
    nodes.push_back({section.corners()[0], section.corners()[1], section.corners()[2]});
  for (const BendingStencil& stencil : stencils) nodes.push_back(stencil.nodes);
  return nodes;
}
}  // namespace

ImplicitSystem::ImplicitSystem(const ClothModel& model, const ClothParameters& parameters)
    : model_(model), parameters_(parameters), wind_(parameters.wind) {
  const PlateBending& bending = model.bending();
  for (const PlateBending::SectionForm& section : bending.sectionForms())
    stencils_.push_back(bendingStencil(bending, section));
  const int n = static_cast<int>(model.nodeCount());
  plan_ = AssemblyPlan(n, elementNodes(model, stencils_));
  matrix_ = plan_.pattern();
  nodeArea_.assign(n, 0.0);
  for (const MembraneElement& section : model.sections())
    for (int i : section.corners()) nodeArea_[i] += section.restArea() / 3.0;
  angles_.resize(bending.joints().size());
  forceSlots_.resize(plan_.vectorSlots());
  stiffnessVelocitySlots_.resize(plan_.vectorSlots());
  blockSlots_.resize(plan_.blockSlots());
  diagonal_.resize(n);
}

ElementOutput ImplicitSystem::slots(int element) {
  return {&forceSlots_[plan_.vectorOffset(element)], &stiffnessVelocitySlots_[plan_.vectorOffset(element)],
          &blockSlots_[plan_.blockOffset(element)]};
}

void ImplicitSystem::computeElements(const std::vector<Vec3>& x, const std::vector<Vec3>& v, double t,
                                     const SystemWeights& weights) {
  const std::vector<MembraneElement>& sections = model_.sections();
  const PlateBending& bending = model_.bending();
  const int membranes = static_cast<int>(sections.size());
  const int joints = static_cast<int>(angles_.size());
  const int bendingSections = static_cast<int>(stencils_.size());
  const bool windBlows = wind_.blows();
  const double pressure = windBlows ? wind_.pressure(t) : 0.0;  // before the threads: Wind draws lazily
#pragma omp parallel
  {
#pragma omp for schedule(static)
    for (int e = 0; e < membranes; ++e) {
      const ElementOutput out = slots(e);
      membraneContribution(sections[e], x, v, parameters_.material, parameters_.strainRateDamping, weights, out);
      if (!windBlows) continue;
      const Triangle& c = sections[e].corners();
      const Vec3 wind = windCornerForce(x[c[0]], x[c[1]], x[c[2]], pressure, wind_.direction());
      for (int a = 0; a < 3; ++a) out.force[a] += wind;
    }
#pragma omp for schedule(static)
    for (int j = 0; j < joints; ++j) angles_[j] = jointAngle(bending.joints()[j], x);
#pragma omp for schedule(static)
    for (int s = 0; s < bendingSections; ++s)
      bendingContribution(bending.sectionForms()[s], stencils_[s], angles_, v, weights, slots(membranes + s));
  }
}

void ImplicitSystem::assemble(const std::vector<Vec3>& x, const std::vector<Vec3>& v, double t,
                              const SystemWeights& weights) {
  computeElements(x, v, t, weights);
  plan_.gatherVectors(forceSlots_, force_);
  plan_.gatherVectors(stiffnessVelocitySlots_, stiffnessVelocity_);
  const std::vector<double>& m = model_.masses();
  const double k = parameters_.airResistance;
  for (size_t i = 0; i < force_.size(); ++i) {
    // Gravity, and air resistance on the node's share of cloth area.
    force_[i] += m[i] * parameters_.gravity - k * nodeArea_[i] * v[i];
    diagonal_[i] = weights.mass * m[i] + weights.damping * k * nodeArea_[i];
  }
  plan_.gatherBlocks(blockSlots_, diagonal_, matrix_);
}

}  // namespace figment
