#pragma once
// Drapes one garment: the FIGMENT physical model (paper §2) integrated with improved
// Euler (Heun) or, for comparison, explicit or symplectic Euler; collisions against a
// Collider; until the cloth is at rest or maxTime.
//
// One step, in order:
//  1. forces -> accelerations (ClothModel) at the step's time t (Heun's second
//     evaluation, of the predicted state, at t + dt; only the wind depends on time):
//     strain clamping acts inside each section's force, the acceleration limiter on
//     each node's elastic acceleration; with Heun both happen at each of its two
//     evaluations;
//  2. the integrator advances positions and velocities (pinned nodes stay);
//  3. contact response: nodes inside the body or within the clearance are put on the
//     surface + clearance, their velocity becomes the motion they made, the velocity
//     into the body is removed and friction acts on the tangential velocity;
//  4. blow-up check (non-finite values, speed > kBlowUpSpeed), then the at-rest rule.
// Integrator::Implicit replaces steps 1-3 with one backward Euler step whose solve holds
// the contacts (sim/cloth/implicit/ImplicitEuler.h), under its step control (a step
// that stretched an edge to breaking is taken again as halves); its at-rest speed is
// |x' - x| / dt. Its step may grow while the cloth is quiet (ImplicitSolverParameters::
// maxTimeStep): the run then ends at maxTime of simulated time, its last step cut to it.
//
// A run ends with what its verdict needs (sim/cloth/DrapeVerdict.h): at rest or not,
// the fastest node, the most stretched edge, whether a stability measure still acted
// in the last step, what the step control did.

#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

#include "sim/cloth/ClothModel.h"
#include "sim/cloth/ClothParameters.h"
#include "sim/cloth/DrapeResult.h"
#include "sim/cloth/EdgeStretch.h"
#include "sim/collision/BroadPhaseCollider.h"
#include "sim/collision/Collider.h"
#include "sim/core/TriangleMesh.h"

namespace figment {

class ImplicitEuler;

struct DrapeProgress {
  int iterations;
  double simulatedTime;  // s
  double maxSpeed;       // m/s, fastest node now
};

// Thrown when the simulation blows up (non-finite values): names step, dt and method.
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ClothSolver {
 public:
  // `garment` is the rest (unstressed) shape and also the starting placement, in the
  // same frame as the collider (the scene's world frame). `body` may be null.
  ClothSolver(const TriangleMesh& garment, const ClothParameters& parameters, std::shared_ptr<const Collider> body);
  // A garment whose rest shape is not where it starts (sim/cloth/RestShape.h: a sewn
  // garment's flat panels), starting at `start` (one position per node), with seams being
  // sewn (sim/cloth/SeamSprings.h; none by default). Throws std::invalid_argument when
  // `start` does not have one position per node.
  ClothSolver(const std::vector<Vec3>& start, const RestShape& rest, const ClothParameters& parameters,
              std::shared_ptr<const Collider> body, const SeamPull& seams = {});
  ~ClothSolver();

  // Holds a node where it is (a pin): it keeps its position and never moves.
  void pin(int node);
  // Continues a drape from another solver's state (a progressive mesh's next level,
  // sim/progressive/ProgressiveDrape.h): positions and velocities, one per node, the
  // time and the steps taken so far. The at-rest rule starts over.
  void resume(const std::vector<Vec3>& x, const std::vector<Vec3>& v, double time, int iterations);

  // Advances one time step (see the steps above). Throws SimulationError when a
  // position or velocity stops being finite or a node exceeds kBlowUpSpeed.
  void step();
  static constexpr double kBlowUpSpeed = 100.0;  // m/s: far beyond any draping motion
  // Runs until at rest or maxTime; `progress` (optional) is called about every
  // `progressInterval` seconds of wall time (checked every 64 steps; 0: every 64 steps).
  DrapeResult run(const std::function<void(const DrapeProgress&)>& progress = {}, double progressInterval = 1.0);

  // Called by run() once before its first step and after every step, with the solver
  // (its time, positions and model): to record the cloth's state at chosen times, or
  // the forces on it, along a run. Empty (the default): nothing is called.
  using StepObserver = std::function<void(const ClothSolver&)>;
  void setStepObserver(StepObserver observer) { stepObserver_ = std::move(observer); }

  bool atRest() const;
  const ClothModel& model() const { return *model_; }
  // The seams being sewn, to pull harder (sim/pattern/Sewing.h).
  SeamSprings& seams() { return model_->seams(); }
  const std::vector<Vec3>& positions() const;
  const std::vector<Vec3>& velocities() const;
  double time() const;
  int iterations() const;
  double maxSpeed() const;
  // How the cloth is now, as a run ends: at rest or not, the fastest node, the most stretched
  // edge, the shares the stability measures held in the last step (the rest of a
  // DrapeResult, the run's own counts, is zero).
  DrapeResult ending() const;
  // The shares of the sections clamped and of the nodes limited in the last step (per
  // force evaluation; zeros for the implicit integrator).
  double lastStepClampedShare() const { return lastStepClampedShare_; }
  double lastStepLimitedShare() const { return lastStepLimitedShare_; }
  // Integrator::Implicit's costs since construction (zeros for the others).
  ImplicitStepCosts implicitCosts() const;
  // The broad phase in front of the body (null without a body or with it off).
  const BroadPhaseCollider* broadPhase() const { return broadPhase_.get(); }

 private:
  std::unique_ptr<ClothModel> model_;
  ClothParameters parameters_;
  std::shared_ptr<const Collider> body_;
  std::shared_ptr<BroadPhaseCollider> broadPhase_;  // body_ itself, when parameters_.broadPhase
  EdgeStretch edges_;                               // the garment's, at rest
  std::vector<Vec3> x_, v_;
  double lastStepClampedShare_ = 0.0, lastStepLimitedShare_ = 0.0;
  double time_ = 0.0;
  int iterations_ = 0;
  double restSince_ = -1.0;    // time the cloth became slower than the threshold; -1: moving
  double implicitStep_ = 0.0;  // a growing implicit step's next size, s (set in the constructor)
  // The last implicit step's fastest node, m/s; 0 before the first (no step is quiet then).
  double lastFastest_ = 0.0;
  std::vector<char> pinned_;
  StepObserver stepObserver_;
  // Per node, a lower bound of its distance to the body, kept down to date by the
  // distance it moved since the last query: while it exceeds the clearance the node
  // cannot touch the body and needs no query (exact, since the body does not move).
  std::vector<double> bodyDistanceBound_;
  void integrate(double dt);
  void stepImplicit();                                // Integrator::Implicit's step
  void checkFinite(size_t node, double speed) const;  // throws SimulationError
  void endStep(double fastest, double dt);            // the clock and the at-rest rule
  // Integrator::Implicit with a growing step (ImplicitSolverParameters::maxTimeStep).
  bool growing() const;
  double implicitStepSize() const;           // the next implicit step's dt
  std::unique_ptr<ImplicitEuler> implicit_;  // set for Integrator::Implicit only

  std::vector<Vec3> xStart_, a0_, a1_, xPredicted_, vPredicted_;  // a step's scratch
};

}  // namespace figment
