#include "sim/cloth/ClothParameters.h"

#include <cmath>
#include <stdexcept>

#include "sim/core/ParameterChecks.h"

namespace figment {

const char* integratorName(Integrator integrator) {
  switch (integrator) {
    case Integrator::ExplicitEuler:
      return "explicit Euler";
    case Integrator::SymplecticEuler:
      return "symplectic Euler";
    case Integrator::Heun:
      return "improved Euler (Heun)";
    case Integrator::Implicit:
      return "implicit";
  }
  return "unknown";
}

double ClothParameters::accelerationLimitSI() const {
  const double g = gravity.norm();
  return accelerationLimit * (g > 0.0 ? g : 9.81);
}

void ClothParameters::validate() const {
  material.validate();
  requirePositive("timeStep", timeStep);
  requirePositive("maxTime", maxTime);
  requireNonNegative("restSpeed", rest.speedThreshold);
  requireNonNegative("restWindow", rest.window);
  for (int axis = 0; axis < 3; ++axis) requireFinite("gravity", gravity[axis]);
  requireNonNegative("airResistance", airResistance);
  requireNonNegative("friction", friction);
  requireNonNegative("clearance", clearance);
  requireNonNegative("strainRateDamping", strainRateDamping);
  requireNonNegative("strainLimit", strainLimit);
  requirePositive("accelerationLimit", accelerationLimit);
  wind.validate();
  requireOpenRange("implicitTolerance", implicitSolver.tolerance, 0.0, 1.0);
  requirePositive("implicitMaxIterations", implicitSolver.maxIterations);
  requirePositive("penaltyRate", implicitSolver.penaltyRate);
  requirePositive("stickSpeed", implicitSolver.stickSpeed);
  requireNonNegative("maxTimeStep", implicitSolver.maxTimeStep);
  if (implicitSolver.maxTimeStep > 0.0 && integrator != Integrator::Implicit)
    throw std::invalid_argument("maxTimeStep = " + formatNumber(implicitSolver.maxTimeStep) +
                                " needs integrator IMPLICIT (an explicit step's bound is its stability)");
  if (implicitSolver.maxTimeStep > 0.0 && implicitSolver.maxTimeStep < timeStep)
    throw std::invalid_argument("maxTimeStep = " + formatNumber(implicitSolver.maxTimeStep) +
                                " must not be under timeStep = " + formatNumber(timeStep) + " (0: no growth)");
  if (implicitSolver.contacts == ContactModel::Penalty && integrator != Integrator::Implicit)
    throw std::invalid_argument("contactModel PENALTY needs integrator IMPLICIT");
  if (timeStep > maxTime)
    throw std::invalid_argument("timeStep = " + formatNumber(timeStep) +
                                " must not exceed maxTime = " + formatNumber(maxTime));
  // A step too small for the run is a slip of the exponent, not a drape anyone waits for.
  if (maxTime / timeStep > kMaxSteps)
    throw std::invalid_argument("timeStep = " + formatNumber(timeStep) + " would take " +
                                formatNumber(maxTime / timeStep) + " steps to maxTime = " + formatNumber(maxTime) +
                                ", more than " + formatNumber(kMaxSteps));
}

}  // namespace figment
