#pragma once
// What the implicit integrator's steps cost, for the benchmarks' breakdown of a step, and
// what its step control did.

namespace figment {

// Where the implicit steps' time went, summed over the steps since construction.
struct ImplicitStepCosts {
  // `this` less `earlier`: the costs of the steps in between.
  ImplicitStepCosts since(const ImplicitStepCosts& earlier) const {
    return {steps - earlier.steps,
            solverIterations - earlier.solverIterations,
            unconvergedSolves - earlier.unconvergedSolves,
            assemblySeconds - earlier.assemblySeconds,
            solveSeconds - earlier.solveSeconds,
            contactSeconds - earlier.contactSeconds,
            halvedSteps - earlier.halvedSteps,
            failedSteps - earlier.failedSteps};
  }

  ImplicitStepCosts& operator+=(const ImplicitStepCosts& more) {
    steps += more.steps, solverIterations += more.solverIterations, unconvergedSolves += more.unconvergedSolves;
    assemblySeconds += more.assemblySeconds, solveSeconds += more.solveSeconds, contactSeconds += more.contactSeconds;
    halvedSteps += more.halvedSteps, failedSteps += more.failedSteps;
    return *this;
  }

  long steps = 0;
  long solverIterations = 0;     // PCG iterations
  long unconvergedSolves = 0;    // solves stopped by maxIterations
  double assemblySeconds = 0.0;  // forces, K v and the matrix A
  double solveSeconds = 0.0;     // filtered PCG
  double contactSeconds = 0.0;   // constraints before, friction and push-out after
  // The step control's (ImplicitEuler.h): steps taken again as halves, and steps kept at
  // the smallest size though they failed (`steps` counts every step taken, halves and
  // failed tries included).
  long halvedSteps = 0;
  long failedSteps = 0;
};

}  // namespace figment
