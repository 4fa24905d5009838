// Based on: the paper's §2 wind (sinusoid with phase changes at random moments, force
// by section orientation, no shadowing); the phase changes as a Poisson process,
// sampled by inverting the exponential distribution's CDF.
#include "sim/cloth/Wind.h"

#include <algorithm>
#include <cmath>

#include "sim/core/ParameterChecks.h"

namespace figment {

void WindParameters::validate() const {
  for (int axis = 0; axis < 3; ++axis) requireFinite("windDirection", direction[axis]);
  requireNonNegative("windAmplitude", amplitude);
  requireNonNegative("windFrequency", frequency);
  requireNonNegative("windPhaseInterval", meanPhaseInterval);
}

Wind::Wind(const WindParameters& parameters) : parameters_(parameters), random_(parameters.seed) {
  parameters_.validate();
  const double length = parameters_.direction.norm();
  direction_ = length > 0.0 ? Vec3(parameters_.direction / length) : Vec3::Zero();
  blows_ = parameters_.amplitude > 0.0 && length > 0.0;
}

double Wind::uniform() const {
  return static_cast<double>(random_() >> 11) * 0x1.0p-53;
}

void Wind::drawChangesUntil(double t) const {
  if (parameters_.meanPhaseInterval == 0.0) return;
  double last = changeTimes_.empty() ? 0.0 : changeTimes_.back();
  while (last <= t) {
    // Two draws per change, always in this order: the interval, then the phase.
    last += -parameters_.meanPhaseInterval * std::log(1.0 - uniform());
    changeTimes_.push_back(last);
    changePhases_.push_back(2.0 * M_PI * uniform());
  }
}

double Wind::phase(double t) const {
  drawChangesUntil(t);
  // The last change at or before t; before the first one the phase is 0.
  const auto after = std::upper_bound(changeTimes_.begin(), changeTimes_.end(), t);
  return after == changeTimes_.begin() ? 0.0 : changePhases_[after - changeTimes_.begin() - 1];
}

double Wind::pressure(double t) const {
  return parameters_.amplitude * std::sin(2.0 * M_PI * parameters_.frequency * t + phase(t));
}

}  // namespace figment
