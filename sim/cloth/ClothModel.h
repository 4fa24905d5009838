#pragma once
// The FIGMENT physical model of one garment (paper §2): triangular sections with
// stretch/shear stresses (sim/cloth/MembraneElement.h), plate bending from the angles
// at the joints between them (sim/cloth/PlateBending.h), and the node terms
// (sim/cloth/NodeTerms.h): gravity, air resistance and wind (sim/cloth/Wind.h), acting
// on nodes whose masses are lumped from the sections (rho h A / 3 per corner).
// Collisions and friction are contact events, handled by the solver after each step.
//
// Every integrator asks this one model (evaluate): the explicit ones for the forces
// (through accelerations, with the paper's stability measures), backward Euler for the
// forces with their derivatives, K v and the matrix of its step. Each element writes
// its terms into slots of its own (for backward Euler in parallel: OpenMP,
// OMP_NUM_THREADS threads; for the explicit integrators on one thread, straight into
// the sums); the slots are summed per node in one fixed order, element by element
// (AssemblyPlan.h):
// the membrane sections, the bending sections (only with the `sections` form of the
// bending stiffness: they carry its blocks), the joints (the bending forces), the wind
// on each section (only when a wind blows), the seams being sewn (only while a pattern's
// panels are pulled together); then the air's resistance and gravity. The
// result does not depend on the thread count.

#include <vector>

#include "sim/cloth/AssemblyPlan.h"
#include "sim/cloth/ClothParameters.h"
#include "sim/cloth/MembraneElement.h"
#include "sim/cloth/NodeTerms.h"
#include "sim/cloth/PlateBending.h"
#include "sim/cloth/RestShape.h"
#include "sim/cloth/SeamSprings.h"
#include "sim/core/TriangleMesh.h"

namespace figment {

// The garment, once checked: it has triangles and they index its vertices. Throws
// std::invalid_argument("coordIndex = 99 is out of range [0, 8]") otherwise; whatever
// reads a garment's triangles (ClothModel, the solver's EdgeStretch) checks it first.
const TriangleMesh& checkedGarment(const TriangleMesh& rest);

class ClothModel {
 public:
  // Throws std::invalid_argument for an empty garment, an index out of range or a
  // garment whose sections are all degenerate.
  ClothModel(const TriangleMesh& rest, const ClothParameters& parameters);
  // The same from a rest shape (sim/cloth/RestShape.h: a sewn garment's flat pieces), with
  // seams being sewn (sim/cloth/SeamSprings.h), an element each, after the wind.
  ClothModel(const RestShape& rest, const ClothParameters& parameters, const SeamPull& seams = {});

  // What an integrator asks of the model at (x, v, t).
  struct Request {
    bool elastic = true;       // the membrane's stress of the strain, and the bending
    bool damping = true;       // the membrane's strain-rate damping
    bool external = true;      // the wind and the air's resistance
    bool weight = true;        // gravity as the force m g (accelerations adds g to f / m)
    double strainLimit = 0.0;  // > 0: the paper's strain clamping (explicit integrators)
    // With weights (and elastic): K v and the matrix of a backward Euler step as well.
    const SystemWeights* system = nullptr;
  };
  // The answer: forces per node (N); with system weights also K v per node (N/s) and
  // A = w_mass M + w_damping D + w_stiffness K, K = -df/dx (projected to stay positive
  // semi-definite), D = -df/dv (strain-rate damping and air); the wind's derivatives
  // are left out.
  struct Evaluation {
    std::vector<Vec3> forces, stiffnessTimesVelocity;
    BlockSparseMatrix matrix;       // set to matrixPattern() by the first evaluation
    long long clampedSections = 0;  // sections whose strain was clamped
  };
  void evaluate(const std::vector<Vec3>& x, const std::vector<Vec3>& v, double t, const Request& request,
                Evaluation& out) const;
  // A matrix with the pattern evaluate() fills (every block zero).
  const BlockSparseMatrix& matrixPattern() const { return plan_.pattern(); }

  // a = F(x, v, t) / m for every node (m/s^2) at simulated time t (s), with the
  // paper's stability measures for the explicit integrators: the strain clamping
  // (parameters' strainLimit) and the acceleration limiter. With a limiter, the elastic
  // part (membrane and bending) of each node's acceleration is limited before gravity,
  // air, wind and the strain-rate damping are added: cutting the damping too let Heun
  // amplify the fast membrane modes, and a sliding skirt shredded. Only the wind
  // depends on t.
  void accelerations(const std::vector<Vec3>& x, const std::vector<Vec3>& v, double t, std::vector<Vec3>& a) const;

  // Held (pinned) nodes: sections between them are clamps that do not bend.
  void hold(const std::vector<char>& heldNodes) { bending_.hold(heldNodes); }

  // How often the stability measures engaged in accelerations() since construction:
  // sections whose strain was clamped and nodes whose acceleration was limited.
  struct LimiterCounts {
    long long evaluations = 0, clampedSections = 0, limitedNodes = 0;
  };
  const LimiterCounts& limiterCounts() const { return counts_; }

  const std::vector<double>& masses() const { return nodes_.masses(); }  // kg
  const std::vector<MembraneElement>& sections() const { return sections_; }
  const PlaneStressLaw& law() const { return law_; }
  const PlateBending& bending() const { return bending_; }
  const NodeTerms& nodes() const { return nodes_; }
  const SeamSprings& seams() const { return seams_; }
  SeamSprings& seams() { return seams_; }
  size_t nodeCount() const { return nodes_.masses().size(); }

  // The wind's total force on the garment at positions x and time t, N: the sum of
  // every section's p(t) A |n . w| w (what the integrators apply; zero when no wind
  // blows). For reports and charts (figment-view --wind-force).
  Vec3 totalWindForce(const std::vector<Vec3>& x, double t) const;
  const Wind& wind() const { return nodes_.wind(); }

 private:
  void planElements();  // plan_ and the first elements of each kind
  ElementOutput slots(int element, bool blocks) const;
  // The element passes, each inside evaluate()'s parallel region: into the elements'
  // slots, or (scatter, on one thread) straight into the force sums.
  void evaluateSections(const std::vector<Vec3>& x, const std::vector<Vec3>& v, const Request& request,
                        std::vector<Vec3>* scatter) const;
  void evaluateBending(const std::vector<Vec3>& x, const std::vector<Vec3>& v, const Request& request,
                       std::vector<Vec3>* scatter) const;
  void evaluateBendingStiffness(const std::vector<Vec3>& v, const SystemWeights& weights) const;
  void evaluateWind(const std::vector<Vec3>& x, double pressure, const Request& request,
                    std::vector<Vec3>* scatter) const;
  void evaluateSeams(const std::vector<Vec3>& x, const std::vector<Vec3>& v, const Request& request,
                     std::vector<Vec3>* scatter) const;
  void addNodeTerms(const std::vector<Vec3>& v, const Request& request, std::vector<Vec3>& forces) const;
  void gatherSystem(const Request& request, Evaluation& out) const;
  void limitAccelerations(std::vector<Vec3>& a) const;

  ClothParameters parameters_;
  PlaneStressLaw law_;
  std::vector<MembraneElement> sections_;
  PlateBending bending_;
  NodeTerms nodes_;
  SeamSprings seams_;
  bool jointBound_;  // the `joints` form of the bending stiffness (else `sections`)
  int bendingSectionElements_ = 0, jointElements_ = 0, windElements_ = -1,
      seamElements_ = -1;  // first elements; -1: none
  AssemblyPlan plan_;
  // Scratch of an evaluation: the elements' slots, the joints' angle changes and
  // gradients, the bending sections' moments, the sections' clamp flags, the matrix's
  // diagonal.
  mutable std::vector<Vec3> forceSlots_, stiffnessVelocitySlots_;
  mutable std::vector<Block3> blockSlots_;  // sized at the first evaluation with weights
  mutable std::vector<double> angleChanges_;
  mutable std::vector<AngleGradient> angleGradients_;  // kept for the stiffness only
  mutable std::vector<Eigen::Vector3d> moments_;
  mutable std::vector<char> clamped_;
  mutable std::vector<double> diagonal_;
  mutable Evaluation explicitForces_;  // accelerations()'
  mutable LimiterCounts counts_;
};

}  // namespace figment
