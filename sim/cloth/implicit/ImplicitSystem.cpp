#include "sim/cloth/implicit/ImplicitSystem.h"

#include <algorithm>


namespace figment {

namespace {
// The plan's elements: the membrane sections, the bending sections (with the `sections`
// form of the bending stiffness only: they carry its blocks), then the joints, which
// carry the bending forces and, in the `joints` form, the blocks.
AssemblyPlan assemblyPlan(const ClothModel& model, bool jointBound) {
  std::vector<std::vector<int>> nodes;
  std::vector<char> withBlocks;
  for (const MembraneElement& section : model.sections()) {
    nodes.push_back({section.corners()[0], section.corners()[1], section.corners()[2]});
    withBlocks.push_back(1);
  }
  const PlateBending& bending = model.bending();
  if (!jointBound)
    for (int s = 0; s < static_cast<int>(bending.sectionForms().size()); ++s) {
      nodes.push_back(bending.stencilNodes(s));
      withBlocks.push_back(1);
    }
  for (const BendingJoint& joint : bending.joints()) {
    nodes.push_back({joint.corners().begin(), joint.corners().end()});
    withBlocks.push_back(jointBound);
  }
  return AssemblyPlan(static_cast<int>(model.nodeCount()), nodes, withBlocks);
}
}  // namespace

ImplicitSystem::ImplicitSystem(const ClothModel& model, const ClothParameters& parameters)
    : model_(model), parameters_(parameters) {
  const PlateBending& bending = model.bending();
  jointBound_ = parameters.implicitSolver.bending == BendingStiffness::Joints;
  jointElements_ = static_cast<int>(model.sections().size() + (jointBound_ ? 0 : bending.sectionForms().size()));
  moments_.resize(bending.sectionForms().size());
  plan_ = assemblyPlan(model, jointBound_);
  matrix_ = plan_.pattern();
  angles_.resize(bending.joints().size());
  forceSlots_.resize(plan_.vectorSlots());
  stiffnessVelocitySlots_.resize(plan_.vectorSlots());
  blockSlots_.resize(plan_.blockSlots());
  diagonal_.resize(model.nodeCount());
}

ElementOutput ImplicitSystem::slots(int element) {
  // data() + offset: an element without blocks may sit at the end of blockSlots_.
  return {forceSlots_.data() + plan_.vectorOffset(element), stiffnessVelocitySlots_.data() + plan_.vectorOffset(element),
          blockSlots_.data() + plan_.blockOffset(element)};
}

void ImplicitSystem::computeElements(const std::vector<Vec3>& x, const std::vector<Vec3>& v, double t,
                                     const SystemWeights& weights) {
  const std::vector<MembraneElement>& sections = model_.sections();
  const PlateBending& bending = model_.bending();
  const int membranes = static_cast<int>(sections.size());
  const int joints = static_cast<int>(angles_.size());
  const NodeTerms& nodes = model_.nodes();
  const bool windBlows = nodes.wind().blows();
  const double pressure = windBlows ? nodes.wind().pressure(t) : 0.0;  // before the threads: Wind draws lazily
#pragma omp parallel
  {
#pragma omp for schedule(static)
    for (int e = 0; e < membranes; ++e) {
      const ElementOutput out = slots(e);
      sections[e].evaluate(x, v, model_.law(), {true, parameters_.strainRateDamping, 0.0}, &weights, out);
      if (!windBlows) continue;
      const Vec3 wind = nodes.windCornerForce(sections[e], x, pressure);
      for (int a = 0; a < 3; ++a) out.force[a] += wind;
    }
#pragma omp for schedule(static)
    for (int j = 0; j < joints; ++j) angles_[j] = bending.jointAngle(j, x);
    computeBending(v, weights);
  }
}

void ImplicitSystem::computeBending(const std::vector<Vec3>& v, const SystemWeights& weights) {
  // Called inside computeElements' parallel region: each loop shares out its elements.
  const PlateBending& bending = model_.bending();
  const int membranes = static_cast<int>(model_.sections().size());
  const int sections = static_cast<int>(moments_.size()), joints = static_cast<int>(angles_.size());
#pragma omp for schedule(static)
  for (int s = 0; s < sections; ++s) moments_[s] = bending.sectionMoments(s, angles_);
#pragma omp for schedule(static)
  for (int j = 0; j < joints; ++j) {
    const ElementOutput out = slots(jointElements_ + j);
    PlateBending::jointForces(bending.jointMoment(j, moments_), angles_[j], out.force);
    if (jointBound_) bending.jointStiffness(j, angles_[j], moments_, v, weights, out);
    else std::fill(out.stiffnessTimesVelocity, out.stiffnessTimesVelocity + 4, Vec3::Zero());
  }
  if (jointBound_) return;
#pragma omp for schedule(static)
  for (int s = 0; s < sections; ++s) {
    const ElementOutput out = slots(membranes + s);
    std::fill(out.force, out.force + bending.stencilNodes(s).size(), Vec3::Zero());
    bending.sectionStiffness(s, angles_, moments_[s], v, weights, out);
  }
}

void ImplicitSystem::assemble(const std::vector<Vec3>& x, const std::vector<Vec3>& v, double t,
                              const SystemWeights& weights) {
  computeElements(x, v, t, weights);
  plan_.gatherVectors(forceSlots_, force_);
  plan_.gatherVectors(stiffnessVelocitySlots_, stiffnessVelocity_);
  const NodeTerms& nodes = model_.nodes();
  for (size_t i = 0; i < force_.size(); ++i) {
    force_[i] += nodes.weight(i) - nodes.drag(i, v[i]);
    diagonal_[i] = weights.mass * nodes.masses()[i] + nodes.weightedDragRate(i, weights.damping);
  }
  plan_.gatherBlocks(blockSlots_, diagonal_, matrix_);
}

}  // namespace figment
