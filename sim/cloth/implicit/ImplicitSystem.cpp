#include "sim/cloth/implicit/ImplicitSystem.h"

#include "sim/cloth/implicit/MembraneHessian.h"

namespace figment {

namespace {
// The plan's elements: the membrane sections, the bending sections, then (with the
// joint-wise bound) the joints, which carry the bending blocks instead of the sections.
AssemblyPlan assemblyPlan(const ClothModel& model, const std::vector<BendingStencil>& stencils, bool jointBound) {
  std::vector<std::vector<int>> nodes;
  std::vector<char> withBlocks;
  for (const MembraneElement& section : model.sections()) {
    nodes.push_back({section.corners()[0], section.corners()[1], section.corners()[2]});
    withBlocks.push_back(1);
  }
  for (const BendingStencil& stencil : stencils) {
    nodes.push_back(stencil.nodes);
    withBlocks.push_back(!jointBound);
  }
  if (jointBound)
    for (const BendingJoint& joint : model.bending().joints()) {
      nodes.push_back({joint.corners().begin(), joint.corners().end()});
      withBlocks.push_back(1);
    }
  return AssemblyPlan(static_cast<int>(model.nodeCount()), nodes, withBlocks);
}
}  // namespace

ImplicitSystem::ImplicitSystem(const ClothModel& model, const ClothParameters& parameters)
    : model_(model), parameters_(parameters) {
  const PlateBending& bending = model.bending();
  for (const PlateBending::SectionForm& section : bending.sectionForms())
    stencils_.push_back(bendingStencil(bending, section));
  const int n = static_cast<int>(model.nodeCount());
  jointBound_ = parameters.implicitSolver.bending == BendingStiffness::Joints;
  if (jointBound_) joints_ = jointBendings(bending);
  moments_.resize(stencils_.size());
  plan_ = assemblyPlan(model, stencils_, jointBound_);
  matrix_ = plan_.pattern();
  angles_.resize(bending.joints().size());
  forceSlots_.resize(plan_.vectorSlots());
  stiffnessVelocitySlots_.resize(plan_.vectorSlots());
  blockSlots_.resize(plan_.blockSlots());
  diagonal_.resize(n);
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
  const int bendingSections = static_cast<int>(stencils_.size());
  const NodeTerms& nodes = model_.nodes();
  const bool windBlows = nodes.wind().blows();
  const double pressure = windBlows ? nodes.wind().pressure(t) : 0.0;  // before the threads: Wind draws lazily
#pragma omp parallel
  {
#pragma omp for schedule(static)
    for (int e = 0; e < membranes; ++e) {
      const ElementOutput out = slots(e);
      membraneContribution(sections[e], x, v, model_.law(), parameters_.strainRateDamping, weights, out);
      if (!windBlows) continue;
      const Vec3 wind = nodes.windCornerForce(sections[e], x, pressure);
      for (int a = 0; a < 3; ++a) out.force[a] += wind;
    }
#pragma omp for schedule(static)
    for (int j = 0; j < joints; ++j) angles_[j] = jointAngle(bending.joints()[j], x);
    if (jointBound_) {
#pragma omp for schedule(static)
      for (int s = 0; s < bendingSections; ++s)
        moments_[s] = bendingSectionForces(bending.sectionForms()[s], stencils_[s], angles_, slots(membranes + s));
#pragma omp for schedule(static)
      for (int j = 0; j < joints; ++j) {
        const ElementOutput out = slots(membranes + bendingSections + j);
        jointBendingContribution(joints_[j], bending, angles_[j], moments_, bending.joints()[j].corners(), v, weights, out);
      }
    } else {
#pragma omp for schedule(static)
      for (int s = 0; s < bendingSections; ++s)
        bendingContribution(bending.sectionForms()[s], stencils_[s], angles_, v, weights, slots(membranes + s));
    }
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
