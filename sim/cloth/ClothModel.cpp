#include "sim/cloth/ClothModel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace figment {

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

namespace {

// The rest shape, checked as checkedGarment checks a mesh.
const RestShape& checkedRest(const RestShape& rest) {
  if (const TriangleMesh* mesh = rest.mesh()) checkedGarment(*mesh);
  if (rest.nodeCount() == 0 || rest.triangles().empty()) throw std::invalid_argument("the garment has no triangles");
  return rest;
}

// The garment's sections, leaving out the degenerate ones.
std::vector<MembraneElement> sectionsOf(const RestShape& rest) {
  std::vector<MembraneElement> sections;
  for (size_t s = 0; s < rest.triangles().size(); ++s) {
    const std::array<Vec3, 3>& c = rest.corners(s);
    MembraneElement section(rest.triangles()[s], c[0], c[1], c[2]);
    if (section.valid()) sections.push_back(section);
  }
  if (sections.empty()) throw std::invalid_argument("every garment triangle is degenerate (zero area)");
  return sections;
}
}  // namespace

ClothModel::ClothModel(const TriangleMesh& rest, const ClothParameters& parameters)
    : ClothModel(RestShape(checkedGarment(rest)), parameters) {}

ClothModel::ClothModel(const RestShape& rest, const ClothParameters& parameters, const SeamPull& seams)
    : parameters_(parameters),
      law_(parameters.material),
      sections_(sectionsOf(checkedRest(rest))),
      bending_(rest, parameters.material.bendingStiffness(), parameters.material.poissonRatio),
      nodes_(sections_, rest.nodeCount(), parameters),
      jointBound_(parameters.implicitSolver.bending == BendingStiffness::Joints) {
  if (!seams.seams.empty()) seams_ = SeamSprings(seams.seams, nodes_.masses(), seams.rate);
  planElements();
  forceSlots_.assign(plan_.vectorSlots(), Vec3::Zero());
  stiffnessVelocitySlots_.assign(plan_.vectorSlots(), Vec3::Zero());
  angleChanges_.resize(bending_.joints().size());
  angleGradients_.resize(bending_.joints().size());
  moments_.resize(bending_.sectionForms().size());
  clamped_.assign(sections_.size(), 0);
  diagonal_.resize(rest.nodeCount());
}

void ClothModel::planElements() {
  std::vector<std::vector<int>> nodes;
  std::vector<char> withBlocks;
  auto add = [&](std::vector<int> elementNodes, bool blocks) {
    nodes.push_back(std::move(elementNodes));
    withBlocks.push_back(blocks);
  };
  for (const MembraneElement& section : sections_) add({section.corners().begin(), section.corners().end()}, true);
  bendingSectionElements_ = static_cast<int>(nodes.size());
  if (!jointBound_)
    for (int s = 0; s < static_cast<int>(bending_.sectionForms().size()); ++s) add(bending_.stencilNodes(s), true);
  jointElements_ = static_cast<int>(nodes.size());
  for (const BendingJoint& joint : bending_.joints())
    add({joint.corners().begin(), joint.corners().end()}, jointBound_);
  if (nodes_.wind().blows()) {
    windElements_ = static_cast<int>(nodes.size());
    for (const MembraneElement& section : sections_) add({section.corners().begin(), section.corners().end()}, false);
  }
  if (!seams_.empty()) {
    seamElements_ = static_cast<int>(nodes.size());
    for (size_t s = 0; s < seams_.size(); ++s) add({seams_.nodes(s)[0], seams_.nodes(s)[1]}, true);
  }
  plan_ = AssemblyPlan(static_cast<int>(nodeCount()), nodes, withBlocks);
}

ElementOutput ClothModel::slots(int element, bool blocks) const {
  const int vector = plan_.vectorOffset(element);
  return {forceSlots_.data() + vector, stiffnessVelocitySlots_.data() + vector,
          blocks ? blockSlots_.data() + plan_.blockOffset(element) : nullptr};
}

void ClothModel::evaluate(const std::vector<Vec3>& x, const std::vector<Vec3>& v, double t, const Request& request,
                          Evaluation& out) const {
  if (request.system && blockSlots_.size() != static_cast<size_t>(plan_.blockSlots()))
    blockSlots_.resize(plan_.blockSlots());
  // Before the threads: Wind draws its phase changes lazily.
  const double pressure = request.external && windElements_ >= 0 ? nodes_.wind().pressure(t) : 0.0;
  // A backward Euler step's assembly runs in parallel, into the elements' slots. An
  // explicit step's forces, a hundred times less work and asked for at every step, run
  // on one thread and go straight into the sums (`scatter`), element by element in the
  // slots' order: the same sums, without a barrier between threads (which costs about
  // as much, far more on a busy machine) or a pass over the slots.
  const bool parallel = request.system != nullptr;
  std::vector<Vec3>* scatter = parallel ? nullptr : &out.forces;
  if (scatter) out.forces.assign(nodeCount(), Vec3::Zero());
#pragma omp parallel if (parallel)
  {
    evaluateSections(x, v, request, scatter);
    evaluateBending(x, v, request, scatter);
    evaluateWind(x, pressure, request, scatter);
    evaluateSeams(x, v, request, scatter);
  }
  out.clampedSections = std::count(clamped_.begin(), clamped_.end(), 1);
  if (!scatter) plan_.gatherVectors(forceSlots_, out.forces);
  addNodeTerms(v, request, out.forces);
  if (request.system) gatherSystem(request, out);
}

namespace {
// Adds an element's forces (its nodes' order) to the sums.
template <class Nodes>
void addForces(const Nodes& nodes, const Vec3* force, std::vector<Vec3>& sums) {
  for (size_t a = 0; a < nodes.size(); ++a) sums[nodes[a]] += force[a];
}
}  // namespace

void ClothModel::evaluateSections(const std::vector<Vec3>& x, const std::vector<Vec3>& v, const Request& request,
                                  std::vector<Vec3>* scatter) const {
  const MembraneRequest membrane{request.elastic, request.damping ? parameters_.strainRateDamping : 0.0,
                                 request.strainLimit};
  const bool any = membrane.elastic || membrane.damping > 0.0;
  const int count = static_cast<int>(sections_.size());
#pragma omp for schedule(static)
  for (int e = 0; e < count; ++e) {
    std::array<Vec3, 3> local;
    ElementOutput out = slots(e, request.system);
    if (scatter) out.force = local.data();
    clamped_[e] = any && sections_[e].evaluate(x, v, law_, membrane, request.system, out);
    if (!any) std::fill_n(out.force, 3, Vec3::Zero());
    if (scatter && any) addForces(sections_[e].corners(), local.data(), *scatter);
  }
}

void ClothModel::evaluateBending(const std::vector<Vec3>& x, const std::vector<Vec3>& v, const Request& request,
                                 std::vector<Vec3>* scatter) const {
  const int joints = static_cast<int>(angleChanges_.size()), forms = static_cast<int>(moments_.size());
  if (!request.elastic) {
    if (scatter) return;
#pragma omp for schedule(static)
    for (int j = 0; j < joints; ++j) std::fill_n(slots(jointElements_ + j, false).force, 4, Vec3::Zero());
    return;
  }
  // The stiffness needs every joint's gradient; the forces only those of joints that
  // bend, measured again where they are used (cheaper than keeping them all).
  const bool keepGradients = request.system != nullptr;
  const std::vector<BendingJoint>& jointList = bending_.joints();
#pragma omp for schedule(static)
  for (int j = 0; j < joints; ++j)
    angleChanges_[j] = keepGradients ? jointList[j].measure(x, angleGradients_[j]) : jointList[j].angleChange(x);
#pragma omp for schedule(static)
  for (int s = 0; s < forms; ++s) moments_[s] = bending_.sectionMoments(s, angleChanges_);
#pragma omp for schedule(static)
  for (int j = 0; j < joints; ++j) {
    const double moment = bending_.jointMoment(j, moments_);
    if (scatter) {
      if (moment == 0.0) continue;
      std::array<Vec3, 4> force;
      jointList[j].momentForces(moment, x, force.data());
      addForces(jointList[j].corners(), force.data(), *scatter);
    } else {
      BendingJoint::momentForces(moment, angleGradients_[j], slots(jointElements_ + j, false).force);
    }
  }
  if (request.system) evaluateBendingStiffness(v, *request.system);
}

void ClothModel::evaluateBendingStiffness(const std::vector<Vec3>& v, const SystemWeights& weights) const {
  const int joints = static_cast<int>(angleChanges_.size()), forms = static_cast<int>(moments_.size());
#pragma omp for schedule(static)
  for (int j = 0; j < joints; ++j) {
    const ElementOutput out = slots(jointElements_ + j, jointBound_);
    if (jointBound_)
      bending_.jointStiffness(j, angleGradients_[j], moments_, v, weights, out);
    else
      std::fill_n(out.stiffnessTimesVelocity, 4, Vec3::Zero());
  }
  if (jointBound_) return;
#pragma omp for schedule(static)
  for (int s = 0; s < forms; ++s) {
    const ElementOutput out = slots(bendingSectionElements_ + s, true);
    bending_.sectionStiffness(s, angleGradients_, moments_[s], v, weights, out);
  }
}

void ClothModel::evaluateWind(const std::vector<Vec3>& x, double pressure, const Request& request,
                              std::vector<Vec3>* scatter) const {
  if (windElements_ < 0 || (scatter && !request.external)) return;
  // F = p(t) A |n . w| w per section, a third to each corner (sim/cloth/Wind.h). Every
  // section feels the full wind (no shadowing).
  const int count = static_cast<int>(sections_.size());
#pragma omp for schedule(static)
  for (int e = 0; e < count; ++e) {
    const Vec3 cornerForce = request.external ? nodes_.windCornerForce(sections_[e], x, pressure) : Vec3::Zero();
    if (scatter)
      for (int i : sections_[e].corners()) (*scatter)[i] += cornerForce;
    else
      std::fill_n(slots(windElements_ + e, false).force, 3, cornerForce);
  }
}

void ClothModel::evaluateSeams(const std::vector<Vec3>& x, const std::vector<Vec3>& v, const Request& request,
                               std::vector<Vec3>* scatter) const {
  if (seamElements_ < 0) return;
  const int count = static_cast<int>(seams_.size());
#pragma omp for schedule(static)
  for (int s = 0; s < count; ++s) {
    std::array<Vec3, 2> local;
    ElementOutput out = slots(seamElements_ + s, request.system);
    if (scatter) out.force = local.data();
    seams_.evaluate(s, x, v, request.elastic, request.damping, request.system, out);
    if (scatter) addForces(seams_.nodes(s), local.data(), *scatter);
  }
}

void ClothModel::addNodeTerms(const std::vector<Vec3>& v, const Request& request, std::vector<Vec3>& forces) const {
  // Asked together (backward Euler), gravity and the air join the sum as one term,
  // m g - k A v, as that step has always added them: its drapes move with the forces'
  // last bits. The explicit integrators subtract the air alone and add g to f / m.
  for (size_t i = 0; i < forces.size(); ++i) {
    if (request.weight && request.external)
      forces[i] += nodes_.weight(i) - nodes_.drag(i, v[i]);
    else if (request.external)
      forces[i] -= nodes_.drag(i, v[i]);
    else if (request.weight)
      forces[i] += nodes_.weight(i);
  }
}

void ClothModel::gatherSystem(const Request& request, Evaluation& out) const {
  const SystemWeights& weights = *request.system;
  plan_.gatherVectors(stiffnessVelocitySlots_, out.stiffnessTimesVelocity);
  for (size_t i = 0; i < diagonal_.size(); ++i) {
    const double air = request.external ? nodes_.weightedDragRate(i, weights.damping) : 0.0;
    diagonal_[i] = weights.mass * nodes_.masses()[i] + air;
  }
  if (out.matrix.rows() != plan_.pattern().rows()) out.matrix = plan_.pattern();
  plan_.gatherBlocks(blockSlots_, diagonal_, out.matrix);
}

void ClothModel::accelerations(const std::vector<Vec3>& x, const std::vector<Vec3>& v, double t,
                               std::vector<Vec3>& a) const {
  const size_t n = nodeCount();
  const bool limited = parameters_.accelerationLimiter != AccelerationLimiter::None;
  ++counts_.evaluations;
  // With a limiter, the elastic pull (membrane and bending) is limited on its own and
  // the strain-rate damping, wind and air are added after it; without, one pass adds
  // all. Gravity is added as g, not as m g / m.
  Request request;
  request.damping = request.external = !limited;
  request.weight = false;
  request.strainLimit = parameters_.strainLimit;
  evaluate(x, v, t, request, explicitForces_);
  counts_.clampedSections += explicitForces_.clampedSections;
  const std::vector<Vec3>& force = explicitForces_.forces;
  a.assign(n, Vec3::Zero());
  if (limited) {
    for (size_t i = 0; i < n; ++i) a[i] = force[i] * nodes_.inverseMass(i);
    limitAccelerations(a);
    Request rest;
    rest.elastic = rest.weight = false;
    evaluate(x, v, t, rest, explicitForces_);
  }
  for (size_t i = 0; i < n; ++i) {
    if (nodes_.floats(i)) {
      a[i] = nodes_.gravity();
      continue;
    }
    a[i] += force[i] * nodes_.inverseMass(i) + nodes_.gravity();
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
