#pragma once
// What a run of the cloth solver did (sim/cloth/ClothSolver.h): how long, whether it came to
// rest, and how it ended, which is what its verdict reads (sim/cloth/DrapeVerdict.h).

#include "sim/cloth/implicit/ImplicitStepCosts.h"

namespace figment {

struct DrapeResult {
  int iterations = 0;
  double simulatedTime = 0.0;  // s
  double wallSeconds = 0.0;
  bool atRest = false;
  // Share of section force evaluations whose strain was clamped, and of node
  // accelerations the limiter cut (sim/cloth/ClothModel.h), over this run.
  double clampedSectionShare = 0.0;
  double limitedNodeShare = 0.0;
  ImplicitStepCosts implicitCosts;  // Integrator::Implicit's steps; zeros for the others
  // At the run's end: the fastest node (m/s), the largest edge stretch (length over rest
  // length, EdgeStretch.h), and the shares of the sections whose strain was clamped and
  // of the nodes whose acceleration the limiter cut in the last step (the explicit
  // integrators'; the shape it ended in is then held by a stability measure, not by the
  // model's forces alone).
  double maxSpeed = 0.0;
  double maxStretch = 1.0;
  double clampedSectionShareAtEnd = 0.0;
  double limitedNodeShareAtEnd = 0.0;
};

}  // namespace figment
