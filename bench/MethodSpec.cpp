#include "MethodSpec.h"

#include <Inventor/SbName.h>

#include <cstdio>
#include <stdexcept>

#include "sim/drape/MethodTable.h"

namespace figment::bench {

Method parseMethod(const std::string& text) {
  return Method{text, DrapeMethod::parse(text)};
}

void configure(ClothEngine& engine, const Method& m) {
  // The fields' enum names are the method's (test_ClothEngineInputs checks them).
  engine.integrator.setValue(SbName(fieldName(m.drape.integrator)));
  engine.contactModel.setValue(SbName(fieldName(m.drape.contacts)));
  engine.accelerationLimiter.setValue(SbName(fieldName(m.drape.limiter)));
  if (m.drape.limit) engine.accelerationLimit.setValue(*m.drape.limit);
  engine.timeStep.setValue(m.drape.timeStep);
  engine.maxTimeStep.setValue(m.drape.maxTimeStep);
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
