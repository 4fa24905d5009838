#include "sim/drape/DrapeMethod.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "sim/core/ParameterChecks.h"

namespace figment {

namespace {

constexpr std::array<std::pair<Integrator, const char*>, 4> kIntegrators{{{Integrator::ExplicitEuler, "EULER"},
                                                                          {Integrator::SymplecticEuler, "SYMPLECTIC"},
                                                                          {Integrator::Heun, "HEUN"},
                                                                          {Integrator::Implicit, "IMPLICIT"}}};
constexpr std::array<std::pair<AccelerationLimiter, const char*>, 3> kLimiters{
    {{AccelerationLimiter::None, "NONE"}, {AccelerationLimiter::Clamp, "CLAMP"}, {AccelerationLimiter::Tanh, "TANH"}}};
constexpr std::array<std::pair<ContactModel, const char*>, 2> kContactModels{
    {{ContactModel::Constraints, "CONSTRAINTS"}, {ContactModel::Penalty, "PENALTY"}}};

template <class Enum, size_t N>
const char* nameIn(const std::array<std::pair<Enum, const char*>, N>& names, Enum value) {
  for (const auto& [v, name] : names)
    if (v == value) return name;
  return "?";
}

// The value `word` names (case free), if any.
template <class Enum, size_t N>
std::optional<Enum> valueIn(const std::array<std::pair<Enum, const char*>, N>& names, const std::string& word) {
  std::string upper = word;
  std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return std::toupper(c); });
  for (const auto& [v, name] : names)
    if (upper == name) return v;
  return std::nullopt;
}

std::string lower(const char* name) {
  std::string s = name;
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

// The shortest text that reads back as `value`, as %g would write it ("0.00015", "1e-05").
std::string shortest(double value) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof text, value, std::chars_format::general);
  return error == std::errc() ? std::string(text, end) : std::to_string(value);
}

}  // namespace

DrapeMethod DrapeMethod::parse(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, ':');) parts.push_back(part);
  const auto bad = [&](const std::string& why) {
    return std::invalid_argument("method \"" + text + "\": " + why +
                                 " (expected INTEGRATOR[+CONTACTS]:DT[:MAX_DT | :LIMITER:LIMIT_G])");
  };
  if (parts.size() < 2 || parts.size() > 4) throw bad("wrong number of parts");
  const size_t plus = parts[0].find('+');
  const std::string integrator = parts[0].substr(0, plus);
  const std::string contacts = plus == std::string::npos ? "constraints" : parts[0].substr(plus + 1);
  DrapeMethod m;
  const std::optional<Integrator> i = valueIn(kIntegrators, integrator);
  if (!i) throw bad("no integrator " + integrator);
  m.integrator = *i;
  const std::optional<ContactModel> c = valueIn(kContactModels, contacts);
  if (!c) throw bad("no contact model " + contacts);
  m.contacts = *c;
  const auto number = [&](const std::string& part) {
    const std::optional<double> value = wholeNumber(part);
    if (!value) throw bad("\"" + part + "\" is not a number");
    return *value;
  };
  m.timeStep = number(parts[1]);
  if (parts.size() == 3) {
    if (m.integrator != Integrator::Implicit) throw bad("only an implicit step grows (MAX_DT)");
    m.maxTimeStep = number(parts[2]);
    if (!(m.maxTimeStep >= m.timeStep)) throw bad("the largest step must not be under the first");
  }
  if (parts.size() == 4) {
    const std::optional<AccelerationLimiter> l = valueIn(kLimiters, parts[2]);
    if (!l) throw bad("no limiter " + parts[2]);
    m.limiter = *l;
    m.limit = number(parts[3]);
  }
  if (!(m.timeStep > 0.0)) throw bad("the time step must be > 0");
  return m;
}

DrapeMethod DrapeMethod::of(const ClothParameters& p) {
  DrapeMethod m{p.integrator, p.implicitSolver.contacts, p.timeStep, p.accelerationLimiter, p.accelerationLimit};
  m.maxTimeStep = p.implicitSolver.maxTimeStep;
  return m;
}

void DrapeMethod::applyTo(ClothParameters& p) const {
  p.integrator = integrator;
  p.implicitSolver.contacts = contacts;
  p.timeStep = timeStep;
  p.implicitSolver.maxTimeStep = maxTimeStep;
  p.accelerationLimiter = limiter;
  if (limit) p.accelerationLimit = *limit;
}

std::string DrapeMethod::text() const {
  // Appended piece by piece: GCC 12 misreads `"+" + std::string` inlined here as an
  // overlapping memcpy (-Wrestrict), a warning in every build of it.
  std::string out = lower(fieldName(integrator));
  if (contacts != ContactModel::Constraints) out.append("+").append(lower(fieldName(contacts)));
  out.append(":").append(shortest(timeStep));
  if (integrator == Integrator::Implicit && maxTimeStep > 0.0) out.append(":").append(shortest(maxTimeStep));
  if (limiter != AccelerationLimiter::None)
    out.append(":").append(lower(fieldName(limiter))).append(":").append(shortest(limit.value_or(0.0)));
  return out;
}

const char* fieldName(Integrator integrator) {
  return nameIn(kIntegrators, integrator);
}

const char* fieldName(AccelerationLimiter limiter) {
  return nameIn(kLimiters, limiter);
}

const char* fieldName(ContactModel contacts) {
  return nameIn(kContactModels, contacts);
}

}  // namespace figment
