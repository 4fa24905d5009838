#pragma once
// A drape's method as one value: the integrator and its step, the implicit step's contact
// model, the explicit steps' acceleration limiter. The studies, the tradeoff table and
// figment-bench spell it INTEGRATOR[+CONTACTS]:DT[:MAX_DT | :LIMITER:LIMIT_G], case free
// ("implicit:0.05", "implicit:0.05:0.4" (a step growing from 0.05 s to 0.4 s),
// "implicit+penalty:0.05", "heun:1.5e-4:clamp:30"); a scene writes the
// same choice in ClothEngine's fields, whose enum names fieldName() gives.

#include <optional>
#include <string>

#include "sim/cloth/ClothParameters.h"

namespace figment {

struct DrapeMethod {
  Integrator integrator = Integrator::Implicit;
  ContactModel contacts = ContactModel::Constraints;  // Integrator::Implicit's
  double timeStep = 0.05;                             // s
  AccelerationLimiter limiter = AccelerationLimiter::None;
  // The limiter's cap, multiples of |g|; unset: the parameters' own (ClothParameters'
  // accelerationLimit) is kept.
  std::optional<double> limit;
  // An implicit step's largest, s, as it grows (ImplicitSolverParameters::maxTimeStep);
  // 0: every step is timeStep.
  double maxTimeStep = 0.0;

  // Throws std::invalid_argument naming the text and what is wrong in it.
  static DrapeMethod parse(const std::string& text);
  // The method `p` drapes by (its limit always set).
  static DrapeMethod of(const ClothParameters& p);

  // Onto `p`: integrator, contacts, time step, limiter and, when set, its limit.
  void applyTo(ClothParameters& p) const;
  // As the studies spell it, lower case: "implicit:0.05", "heun:0.00015:clamp:30".
  std::string text() const;

  bool operator==(const DrapeMethod&) const = default;
};

// The names a scene writes a method's fields with ("IMPLICIT", "CLAMP", "PENALTY").
const char* fieldName(Integrator integrator);
const char* fieldName(AccelerationLimiter limiter);
const char* fieldName(ContactModel contacts);

}  // namespace figment
