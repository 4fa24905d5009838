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
// kMaxSolves times, warm-started). One Newton step of the implicit equations: stable
// for any step (the matrix is positive definite: K projected, C >= 0), first order in
// time, and at rest it leaves exactly the explicit model's equilibrium f = 0.

#include "sim/cloth/implicit/ContactConstraints.h"
#include "sim/cloth/implicit/ContactPenalty.h"
#include "sim/cloth/implicit/FilteredPcg.h"
#include "sim/cloth/implicit/ImplicitStepCosts.h"
#include "sim/cloth/ClothModel.h"

#include <memory>
#include <vector>

namespace figment {

class ImplicitEuler {
 public:
  ImplicitEuler(const ClothModel& model, const ClothParameters& parameters, std::shared_ptr<const Collider> body);

  // Advances x and v by one step from time t. Nodes with pinned[i] != 0 stay.
  void step(std::vector<Vec3>& x, std::vector<Vec3>& v, double t, const std::vector<char>& pinned);

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
};

}  // namespace figment
