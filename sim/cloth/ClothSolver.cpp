#include "sim/cloth/ClothSolver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "sim/cloth/ContactResponse.h"
#include "sim/cloth/implicit/ImplicitEuler.h"
#include "sim/core/ParameterChecks.h"

namespace figment {

ClothSolver::ClothSolver(const TriangleMesh& garment, const ClothParameters& parameters,
                         std::shared_ptr<const Collider> body)
    : ClothSolver(garment.vertices, RestShape(checkedGarment(garment)), parameters, std::move(body)) {}

namespace {
const RestShape& startingAt(const std::vector<Vec3>& start, const RestShape& rest) {
  if (start.size() != rest.nodeCount())
    throw std::invalid_argument("the garment starts with " + std::to_string(start.size()) + " positions for " +
                                std::to_string(rest.nodeCount()) + " nodes");
  if (const TriangleMesh* mesh = rest.mesh()) checkedGarment(*mesh);
  return rest;
}
}  // namespace

ClothSolver::ClothSolver(const std::vector<Vec3>& start, const RestShape& rest, const ClothParameters& parameters,
                         std::shared_ptr<const Collider> body, const SeamPull& seams)
    : parameters_(parameters), body_(std::move(body)), edges_(startingAt(start, rest)) {
  parameters_.validate();
  implicitStep_ = parameters_.timeStep;
  model_ = std::make_unique<ClothModel>(rest, parameters_, seams);
  x_ = start;
  v_.assign(x_.size(), Vec3::Zero());
  pinned_.assign(x_.size(), 0);
  bodyDistanceBound_.assign(x_.size(), 0.0);
  if (body_ && parameters_.broadPhase) {
    broadPhase_ = std::make_shared<BroadPhaseCollider>(body_);
    broadPhase_->follow(x_);
    body_ = broadPhase_;
  }
  if (parameters_.integrator == Integrator::Implicit)
    implicit_ = std::make_unique<ImplicitEuler>(*model_, parameters_, body_, edges_);
}

ClothSolver::~ClothSolver() = default;

void ClothSolver::pin(int node) {
  pinned_.at(node) = 1;
  model_->hold(pinned_);
}

void ClothSolver::resume(const std::vector<Vec3>& x, const std::vector<Vec3>& v, double time, int iterations) {
  if (x.size() != x_.size() || v.size() != v_.size())
    throw std::invalid_argument("resume: " + std::to_string(x.size()) + " positions and " + std::to_string(v.size()) +
                                " velocities for " + std::to_string(x_.size()) + " nodes");
  x_ = x;
  v_ = v;
  time_ = time;
  iterations_ = iterations;
  restSince_ = -1.0;
  implicitStep_ = parameters_.timeStep;
  lastFastest_ = 0.0;
}

const std::vector<Vec3>& ClothSolver::positions() const {
  return x_;
}
const std::vector<Vec3>& ClothSolver::velocities() const {
  return v_;
}
double ClothSolver::time() const {
  return time_;
}
int ClothSolver::iterations() const {
  return iterations_;
}

ImplicitStepCosts ClothSolver::implicitCosts() const {
  return implicit_ ? implicit_->costs() : ImplicitStepCosts{};
}

double ClothSolver::maxSpeed() const {
  double fastest = 0.0;
  for (const Vec3& v : v_) fastest = std::max(fastest, v.norm());
  return fastest;
}

bool ClothSolver::atRest() const {
  return restSince_ >= 0.0 && time_ - restSince_ >= parameters_.rest.window - 1e-12;
}

namespace {
constexpr double kContactSearchMargin = 0.02;  // m beyond clearance and motion a query looks

}  // namespace

void ClothSolver::integrate(double dt) {
  const size_t n = x_.size();
  xStart_ = x_;
  // Pinned nodes do not accelerate: zero at every evaluation, so a predicted state
  // (Heun) does not give them a velocity their neighbours would feel.
  auto holdPins = [&](std::vector<Vec3>& a) {
    for (size_t i = 0; i < n; ++i)
      if (pinned_[i]) a[i].setZero();
  };
  model_->accelerations(x_, v_, time_, a0_);
  holdPins(a0_);
  switch (parameters_.integrator) {
    case Integrator::ExplicitEuler:
      for (size_t i = 0; i < n; ++i) {
        x_[i] += dt * v_[i];
        v_[i] += dt * a0_[i];
      }
      break;
    case Integrator::SymplecticEuler:
      for (size_t i = 0; i < n; ++i) {
        v_[i] += dt * a0_[i];
        x_[i] += dt * v_[i];
      }
      break;
    case Integrator::Heun:
      // Predictor: explicit Euler; corrector: the mean of the slopes at t and at the
      // predicted state.
      xPredicted_.resize(n);
      vPredicted_.resize(n);
      for (size_t i = 0; i < n; ++i) {
        xPredicted_[i] = x_[i] + dt * v_[i];
        vPredicted_[i] = v_[i] + dt * a0_[i];
      }
      model_->accelerations(xPredicted_, vPredicted_, time_ + dt, a1_);
      holdPins(a1_);
      for (size_t i = 0; i < n; ++i) {
        x_[i] += 0.5 * dt * (v_[i] + vPredicted_[i]);
        v_[i] += 0.5 * dt * (a0_[i] + a1_[i]);
      }
      break;
    case Integrator::Implicit:  // stepImplicit(): never here
      break;
  }
}

void ClothSolver::step() {
  if (broadPhase_) broadPhase_->follow(x_);
  if (implicit_) return stepImplicit();
  const double dt = parameters_.timeStep;
  const size_t n = x_.size();
  const ClothModel::LimiterCounts before = model_->limiterCounts();
  integrate(dt);
  const ClothModel::LimiterCounts& after = model_->limiterCounts();
  const double evaluations = static_cast<double>(after.evaluations - before.evaluations);
  if (evaluations > 0.0) {
    lastStepClampedShare_ =
        (after.clampedSections - before.clampedSections) / (evaluations * model_->sections().size());
    lastStepLimitedShare_ = (after.limitedNodes - before.limitedNodes) / (evaluations * model_->nodeCount());
  }
  double fastest = 0.0;
  for (size_t i = 0; i < n; ++i) {
    if (pinned_[i]) continue;  // held: no acceleration, no velocity
    const Vec3& previous = xStart_[i];
    if (body_) {
      const double moved = (x_[i] - previous).norm();
      double& bound = bodyDistanceBound_[i];
      bound -= moved;
      if (bound <= parameters_.clearance) {
        // Look well beyond this step's motion so that the bound then lets the next
        // steps skip the query; on the first step look everywhere, since a garment may
        // start roughly placed with nodes inside the body (paper §3.3).
        const double searchRadius = iterations_ == 0 ? std::numeric_limits<double>::infinity()
                                                     : parameters_.clearance + 2.0 * moved + kContactSearchMargin;
        Contact contact;
        if (body_->contact(x_[i], parameters_.clearance, searchRadius, contact)) {
          respondToContact(contact, parameters_.clearance, parameters_.friction, dt, previous, x_[i], v_[i]);
          bound = parameters_.clearance;
        } else {
          bound = contact.distance;
        }
      }
    }
    const double speed = v_[i].norm();
    checkFinite(i, speed);
    fastest = std::max(fastest, speed);
  }
  endStep(fastest, dt);
}

void ClothSolver::checkFinite(size_t i, double speed) const {
  if (!std::isfinite(speed) || !x_[i].allFinite() || speed > kBlowUpSpeed)
    throw SimulationError("simulation blew up at step " + std::to_string(iterations_ + 1) +
                          " (t = " + formatNumber(time_ + parameters_.timeStep) + " s): node " + std::to_string(i) +
                          " speed " + formatNumber(speed) + " m/s; timeStep = " + formatNumber(parameters_.timeStep) +
                          " s, method " + integratorName(parameters_.integrator));
}

void ClothSolver::endStep(double fastest, double dt) {
  time_ += dt;
  ++iterations_;
  if (fastest < parameters_.rest.speedThreshold) {
    if (restSince_ < 0.0) restSince_ = time_;
  } else {
    restSince_ = -1.0;
  }
}

double ClothSolver::implicitStepSize() const {
  if (!growing()) return parameters_.timeStep;
  // The last step ends at maxTime, not past it.
  return std::min(implicitStep_, parameters_.maxTime - time_);
}

bool ClothSolver::growing() const {
  return parameters_.implicitSolver.maxTimeStep > parameters_.timeStep;
}

void ClothSolver::stepImplicit() {
  const double dt = implicitStepSize();
  xStart_ = x_;
  const long halvedBefore = implicit_->costs().halvedSteps;
  implicit_->step(x_, v_, time_, dt, pinned_);
  // The at-rest rule's speed is displacement per simulated second, |x' - x| / dt: the
  // velocity itself in backward Euler (x' = x + dt v') except where a contact moved the
  // node, and a speed at any step size (never a displacement per step, which would let
  // a large step's creep pass for rest).
  double fastest = 0.0;
  for (size_t i = 0; i < x_.size(); ++i) {
    const double speed = std::max(v_[i].norm(), (x_[i] - xStart_[i]).norm() / dt);
    checkFinite(i, speed);
    fastest = std::max(fastest, (x_[i] - xStart_[i]).norm() / dt);
  }
  if (growing()) {
    // Quiet: kept whole by the step control and slower than the step before (none is
    // before the first: a garment let go is not quiet). A garment still sliding, or its
    // contacts chattering, goes back towards the scene's step.
    const bool quiet = implicit_->costs().halvedSteps == halvedBefore && fastest < lastFastest_;
    const double next = quiet ? ImplicitSolverParameters::kStepGrowth * implicitStep_ : 0.5 * implicitStep_;
    implicitStep_ = std::clamp(next, parameters_.timeStep, parameters_.implicitSolver.maxTimeStep);
    lastFastest_ = fastest;
  }
  endStep(fastest, dt);
}

DrapeResult ClothSolver::run(const std::function<void(const DrapeProgress&)>& progress, double progressInterval) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto lastReport = start;
  const int firstIteration = iterations_;
  const ClothModel::LimiterCounts before = model_->limiterCounts();
  const ImplicitStepCosts costsBefore = implicit_ ? implicit_->costs() : ImplicitStepCosts{};
  // Stop at maxTime, counted in steps so that rounding never adds or drops one.
  const int totalSteps = static_cast<int>(std::ceil(parameters_.maxTime / parameters_.timeStep - 1e-9));
  if (stepObserver_) stepObserver_(*this);
  // A growing step stops at maxTime itself (its last step cut to end there).
  auto timeLeft = [&] { return !growing() || time_ < parameters_.maxTime - 1e-9; };
  while (iterations_ < totalSteps && timeLeft() && !atRest()) {
    step();
    if (stepObserver_) stepObserver_(*this);
    if (progress && (iterations_ & 63) == 0) {
      const auto now = Clock::now();
      if (std::chrono::duration<double>(now - lastReport).count() >= progressInterval) {
        progress({iterations_, time_, maxSpeed()});
        lastReport = now;
      }
    }
  }
  DrapeResult result = ending();
  result.iterations = iterations_ - firstIteration;
  result.simulatedTime = time_;
  result.wallSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (implicit_) result.implicitCosts = implicit_->costs().since(costsBefore);
  const ClothModel::LimiterCounts& after = model_->limiterCounts();
  const double evaluations = static_cast<double>(after.evaluations - before.evaluations);
  if (evaluations > 0.0) {
    result.clampedSectionShare =
        (after.clampedSections - before.clampedSections) / (evaluations * model_->sections().size());
    result.limitedNodeShare = (after.limitedNodes - before.limitedNodes) / (evaluations * model_->nodeCount());
  }
  return result;
}

DrapeResult ClothSolver::ending() const {
  DrapeResult result;
  result.atRest = atRest();
  result.maxSpeed = maxSpeed();
  result.maxStretch = edges_.largest(x_);  // the most stretched edge (EdgeStretch::largest)
  result.clampedSectionShareAtEnd = lastStepClampedShare_;
  result.limitedNodeShareAtEnd = lastStepLimitedShare_;
  return result;
}

}  // namespace figment
