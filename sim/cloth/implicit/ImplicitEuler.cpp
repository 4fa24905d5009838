#include "sim/cloth/implicit/ImplicitEuler.h"

#include <algorithm>
#include <chrono>

namespace figment {

ImplicitEuler::ImplicitEuler(const ClothModel& model, const ClothParameters& parameters,
                             std::shared_ptr<const Collider> body, EdgeStretch edges)
    : parameters_(parameters),
      model_(model),
      contacts_(parameters.implicitSolver.contacts == ContactModel::Constraints ? body : nullptr, parameters,
                model.nodeCount()),
      stop_{parameters.implicitSolver.tolerance, parameters.implicitSolver.maxIterations} {
  system_.matrix = model.matrixPattern();
  if (parameters.implicitSolver.preconditioner == Preconditioner::TwoLevel) pcg_ = FilteredPcg(system_.matrix);
  if (parameters.implicitSolver.contacts == ContactModel::Penalty)
    penalties_ = std::make_unique<ContactPenalty>(std::move(body), parameters, model.nodeCount());
  edges_ = std::move(edges);
}

void ImplicitEuler::fixNodes(const std::vector<char>& pinned, double dt) {
  const NodeTerms& nodes = model_.nodes();
  filter_.reset(pinned.size());
  for (size_t i = 0; i < pinned.size(); ++i) {
    if (pinned[i]) {
      filter_.kind[i] = NodeFilter::Fixed;  // keeps its (zero) velocity
    } else if (nodes.floats(i)) {
      filter_.kind[i] = NodeFilter::Fixed;  // moved by gravity alone
      filter_.prescribed[i] = dt * nodes.gravity();
    }
  }
}

PcgStart ImplicitEuler::start(int solve) const {
  // A solve after the first starts from the last one's answer (the same matrix, a few
  // nodes' contacts changed); a step's first from the last step's velocity change,
  // which change_ still holds, scaled along itself (PcgStart::Guess).
  if (solve > 0) return PcgStart::Again;
  return parameters_.implicitSolver.warmStart ? PcgStart::Guess : PcgStart::Zero;
}

void ImplicitEuler::solveWithFriction(const std::vector<Vec3>& v) {
  const size_t n = v.size();
  const std::vector<Vec3>& friction = contacts_.friction();
  b_.resize(n);
  double total = 0.0;  // N s: the step's impulses, summed over the nodes
  for (size_t i = 0; i < n; ++i) total += rhs_[i].norm();
  for (int solve = 0;; ++solve) {
    for (size_t i = 0; i < n; ++i) b_[i] = rhs_[i] + friction[i];
    lastSolve_ = pcg_.solve(system_.matrix, b_, filter_, stop_, change_, start(solve),
                            solve > 0 ? CoarseMatrix::Keep : CoarseMatrix::Build);
    costs_.solverIterations += lastSolve_.iterations;
    costs_.unconvergedSolves += lastSolve_.converged ? 0 : 1;
    // The constraints' impulses: what the solve added beyond the forces and the friction.
    system_.matrix.multiply(change_, impulse_);
    for (size_t i = 0; i < n; ++i) impulse_[i] -= b_[i];
    const double changed = contacts_.update(impulse_, v, change_, model_.masses(), filter_);
    if (changed <= kResolveShare * total || solve + 1 >= kMaxSolves) break;
  }
}

void ImplicitEuler::solveWithPenalties(const std::vector<Vec3>& v, double dt) {
  for (int solve = 0;; ++solve) {
    lastSolve_ = pcg_.solve(system_.matrix, rhs_, filter_, stop_, change_, start(solve),
                            solve > 0 ? CoarseMatrix::Keep : CoarseMatrix::Build);
    costs_.solverIterations += lastSolve_.iterations;
    costs_.unconvergedSolves += lastSolve_.converged ? 0 : 1;
    if (solve + 1 >= kMaxSolves || !penalties_->update(v, change_, dt, system_.matrix, rhs_)) break;
  }
}

namespace {
using Clock = std::chrono::steady_clock;
// Seconds since `since`, and `since` moved on to now.
double lap(Clock::time_point& since) {
  const Clock::time_point now = Clock::now();
  const double seconds = std::chrono::duration<double>(now - since).count();
  since = now;
  return seconds;
}
}  // namespace

void ImplicitEuler::advance(std::vector<Vec3>& x, std::vector<Vec3>& v, double t, double dt,
                            const std::vector<char>& pinned) {
  Clock::time_point clock = Clock::now();
  const size_t n = x.size();
  const bool firstStep = steps_++ == 0;
  xStart_ = x;
  vStart_ = v;
  // The stop is relative to the right-hand side, dt f: a step longer than the scene's
  // (a growing step, ClothSolver.h) stops in proportion tighter, so that the velocity's
  // error stays what it is at the scene's step. At 0.4 s and the 1 % stop a drape's nodes
  // otherwise jitter at 1 to 2 cm/s, above the rest speed, and never rest.
  stop_.relative = parameters_.implicitSolver.tolerance * std::min(1.0, parameters_.timeStep / dt);
  fixNodes(pinned, dt);
  contacts_.constrain(x, v, dt, firstStep, filter_);
  costs_.contactSeconds += lap(clock);
  const SystemWeights weights{1.0, dt, dt * dt};
  ClothModel::Request request;
  request.system = &weights;
  model_.evaluate(x, v, t, request, system_);
  costs_.assemblySeconds += lap(clock);
  rhs_.resize(n);
  const std::vector<Vec3>& f = system_.forces;
  const std::vector<Vec3>& Kv = system_.stiffnessTimesVelocity;
  for (size_t i = 0; i < n; ++i) rhs_[i] = dt * (f[i] - dt * Kv[i]);
  if (penalties_) {
    penalties_->add(x, v, model_.masses(), dt, firstStep, system_.matrix, rhs_);
    costs_.contactSeconds += lap(clock);
    solveWithPenalties(v, dt);
  } else {
    solveWithFriction(v);
  }
  costs_.solveSeconds += lap(clock);
  ++costs_.steps;
  for (size_t i = 0; i < n; ++i) v[i] += change_[i];
  for (size_t i = 0; i < n; ++i)
    if (!pinned[i]) x[i] += dt * v[i];
  if (penalties_)
    penalties_->finish(xStart_, dt, firstStep, x, v);
  else
    contacts_.finish(filter_, xStart_, vStart_, dt, firstStep, x, v);
  costs_.contactSeconds += lap(clock);
}

void ImplicitEuler::step(std::vector<Vec3>& x, std::vector<Vec3>& v, double t, const std::vector<char>& pinned) {
  controlledStep(x, v, t, parameters_.timeStep, 0, pinned);
}

void ImplicitEuler::step(std::vector<Vec3>& x, std::vector<Vec3>& v, double t, double dt,
                         const std::vector<char>& pinned) {
  controlledStep(x, v, t, dt, 0, pinned);
}

void ImplicitEuler::controlledStep(std::vector<Vec3>& x, std::vector<Vec3>& v, double t, double dt, int halvings,
                                   const std::vector<char>& pinned) {
  if (edges_.edgeCount() == 0) return advance(x, v, t, dt, pinned);
  // What a failed step goes back to: one slot is enough, since nothing else is kept
  // between a step's start and the test of its end.
  xTried_ = x;
  vTried_ = v;
  contactsTried_ = contacts_;
  if (penalties_) penaltiesTried_ = *penalties_;
  stepsTried_ = steps_;
  advance(x, v, t, dt, pinned);
  if (!edges_.jumped(xTried_, x, kFailStretch, kFailGrowth)) return;
  if (halvings == kMaxHalvings) {
    ++costs_.failedSteps;  // kept: a smaller step is not tried
    return;
  }
  if (halvings == 0) ++costs_.halvedSteps;
  x = xTried_;
  v = vTried_;
  contacts_ = *contactsTried_;
  if (penalties_) *penalties_ = *penaltiesTried_;
  steps_ = stepsTried_;
  controlledStep(x, v, t, 0.5 * dt, halvings + 1, pinned);
  controlledStep(x, v, t + 0.5 * dt, 0.5 * dt, halvings + 1, pinned);
}

}  // namespace figment
