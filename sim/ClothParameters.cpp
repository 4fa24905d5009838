#include "ClothParameters.h"

#include "Validation.h"

#include <cmath>
#include <stdexcept>

namespace figment {

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
  if (timeStep > maxTime)
    throw std::invalid_argument("timeStep = " + formatNumber(timeStep) + " must not exceed maxTime = " +
                                formatNumber(maxTime));
}

}  // namespace figment
