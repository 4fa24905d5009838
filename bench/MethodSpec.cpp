#include "MethodSpec.h"

#include <Inventor/SbName.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "io/TradeoffTable.h"

namespace figment::bench {

namespace {

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
  return s;
}

// Sets `field` to the value named `name`; false when it has no such value.
bool setByName(SoSFEnum& field, const std::string& name) {
  for (int i = 0; i < field.getNumEnums(); ++i) {
    SbName candidate;
    const int value = field.getEnum(i, candidate);
    if (name == candidate.getString()) {
      field.setValue(value);
      return true;
    }
  }
  return false;
}

}  // namespace

Method parseMethod(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, ':');) parts.push_back(part);
  if (parts.size() != 2 && parts.size() != 4)
    throw std::invalid_argument("method \"" + text + "\": expected INTEGRATOR[+CONTACTS]:DT[:LIMITER:LIMIT_G]");
  Method m{text, upper(parts[0])};
  if (const size_t plus = m.integrator.find('+'); plus != std::string::npos) {  // IMPLICIT+PENALTY
    m.contactModel = m.integrator.substr(plus + 1);
    m.integrator.resize(plus);
  }
  try {
    m.timeStep = std::stod(parts[1]);
    if (parts.size() == 4) m.limiter = upper(parts[2]), m.limit = std::stod(parts[3]);
  } catch (const std::exception&) {
    throw std::invalid_argument("method \"" + text + "\": a time step or limit is not a number");
  }
  return m;
}

std::string configure(ClothEngine& engine, const Method& m) {
  if (!setByName(engine.integrator, m.integrator)) return "method \"" + m.text + "\": no integrator " + m.integrator;
  if (!setByName(engine.contactModel, m.contactModel))
    return "method \"" + m.text + "\": no contact model " + m.contactModel;
  if (!setByName(engine.accelerationLimiter, m.limiter))
    return "method \"" + m.text + "\": no acceleration limiter " + m.limiter;
  engine.accelerationLimit.setValue(m.limit);
  engine.timeStep.setValue(m.timeStep);
  return "";
}

Schedule parseSchedule(const std::string& text) {
  const ScheduleText s = parseScheduleText(text);
  return Schedule{text, s.beginShare, s.rate};
}

bool parsesOrReports(const std::function<void()>& parse) {
  try {
    parse();
    return true;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "figment-bench: %s\n", e.what());
    return false;
  }
}

}  // namespace figment::bench
