#pragma once
// Backward Euler for the garment, linearised once per step (Baraff & Witkin, "Large
// steps in cloth simulation", SIGGRAPH 1998): with K = -df/dx, C = -df/dv at the step's
// start (ClothModel::evaluate, the explicit integrators' model without their stability
// measures: strain clamping, acceleration limiting), the velocity change y solves
//
//   (M + dt C + dt^2 K) y = dt (f(x, v, t) - dt K v),   v' = v + y,   x' = x + dt v'
//
// by filtered PCG (FilteredPcg.h), with pinned nodes fixed and the body's contacts either
// as constraints with Coulomb friction in the right-hand side (ContactConstraints.h) or
// as penalty springs and friction forces in the system (ContactPenalty.h); when
// contacts switch between sticking and sliding the same system is solved again (up to
// kMaxSolves times, warm-started); a step's first solve may start from the last step's
// velocity change (ImplicitSolverParameters::warmStart, off by default). One Newton step
// of the implicit equations: stable for any step (the matrix is positive definite: K
// projected, C >= 0), first order in time, and at rest it leaves exactly the explicit
// model's equilibrium f = 0.
//
// Step control (Baraff & Witkin 1998, §5: a step that changes a triangle's stretch too
// much is rejected and taken again at half the size): one linearisation is all a step
// makes, and at too large a step for the garment (the default dress at 0.2 s) it
// overshoots, stretching edges to many times their length. A step after which an edge
// ends stretched past kFailStretch of its rest length, having grown by more than
// kFailGrowth of it within the step (or a position is not finite), failed: x, v and the
// contacts' state go back to the step's start and it is taken as two steps of half the
// size, each controlled alike, down to dt / 2^kMaxHalvings; a step that fails at that
// size is kept and counted (costs().failedSteps). A step that does not fail is the step
// as it was without control, bit for bit.

#include <memory>
#include <optional>
#include <vector>

#include "sim/cloth/ClothModel.h"
#include "sim/cloth/DrapeVerdict.h"
#include "sim/cloth/EdgeStretch.h"
#include "sim/cloth/implicit/ContactConstraints.h"
#include "sim/cloth/implicit/ContactPenalty.h"
#include "sim/cloth/implicit/FilteredPcg.h"
#include "sim/cloth/implicit/ImplicitStepCosts.h"

namespace figment {

class ImplicitEuler {
 public:
  // `edges`: the garment's edges at rest, which the step control reads (none: no control).
  ImplicitEuler(const ClothModel& model, const ClothParameters& parameters, std::shared_ptr<const Collider> body,
                EdgeStretch edges = {});

  // Advances x and v by one step (parameters' timeStep) from time t, under the step
  // control. Nodes with pinned[i] != 0 stay.
  void step(std::vector<Vec3>& x, std::vector<Vec3>& v, double t, const std::vector<char>& pinned);
  // The same for a step of dt (a growing step's, ClothSolver.h).
  void step(std::vector<Vec3>& x, std::vector<Vec3>& v, double t, double dt, const std::vector<char>& pinned);

  static constexpr double kFailStretch = DrapeVerdict::kTearStretch;  // the drape verdict's tear bound
  // Dimensionless, of the rest length. Measured: an edge of the shipped drapes grows by
  // at most 0.74 in a step; one of a garment placed cutting into the body by up to 2.8 in
  // its first steps, as the contacts push it out (the same at any step size: halving
  // there only changed the drape); a failed step of the dress at 0.2 s grows one by 27,
  // at 0.5 s by 10.
  static constexpr double kFailGrowth = 3.0;
  static constexpr int kMaxHalvings = 4;

  const PcgReport& lastSolve() const { return lastSolve_; }
  const ImplicitStepCosts& costs() const { return costs_; }

 private:
  void fixNodes(const std::vector<char>& pinned, double dt);
  // Solves for change_ from rhs_ and the contacts' friction, again while the contacts
  // that change between sticking and sliding (ContactConstraints.h) change more than
  // kResolveShare of the step's impulses, kMaxSolves times at most. Changes below that
  // (a few nodes at the friction cone's edge) act from the next step.
  void solveWithFriction(const std::vector<Vec3>& v);
  // The same with penalty contacts: solves again while nodes switch between sticking
  // and sliding, kMaxSolves times at most.
  void solveWithPenalties(const std::vector<Vec3>& v, double dt);

  // One step of dt, controlled, after `halvings` halvings of the scene's step.
  void controlledStep(std::vector<Vec3>& x, std::vector<Vec3>& v, double t, double dt, int halvings,
                      const std::vector<char>& pinned);
  // One step of dt as it is linearised, uncontrolled.
  void advance(std::vector<Vec3>& x, std::vector<Vec3>& v, double t, double dt, const std::vector<char>& pinned);

  // Where the step's `solve`th solve (from 0) starts.
  PcgStart start(int solve) const;
  static constexpr int kMaxSolves = 3;
  static constexpr double kResolveShare = 0.03;

  ClothParameters parameters_;
  const ClothModel& model_;  // kept by reference
  ClothModel::Evaluation system_;
  ContactConstraints contacts_;
  std::unique_ptr<ContactPenalty> penalties_;  // instead of contacts_ where the parameters say so
  FilteredPcg pcg_;
  PcgStop stop_;
  NodeFilter filter_;
  PcgReport lastSolve_;
  ImplicitStepCosts costs_;
  int steps_ = 0;
  std::vector<Vec3> xStart_, vStart_, rhs_, b_, change_, impulse_;
  // The step control's: the edges, and what a failed step goes back to (x, v, the
  // contacts' state and the step count at its start).
  EdgeStretch edges_;
  std::vector<Vec3> xTried_, vTried_;
  std::optional<ContactConstraints> contactsTried_;
  std::optional<ContactPenalty> penaltiesTried_;
  int stepsTried_ = 0;
};

}  // namespace figment
