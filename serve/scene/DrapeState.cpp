#include "serve/scene/DrapeState.h"

#include "sim/cloth/DrapeVerdict.h"

namespace figment::serve {

std::string drapeState(const std::vector<session::EngineDrape>& drapes) {
  std::string state = "rest";
  for (const session::EngineDrape& drape : drapes) {
    const DrapeVerdict verdict{drape.report.run, drape.report.maxTime};
    if (verdict.tore() || verdict.run.implicitCosts.failedSteps > 0) return "torn";
    if (!verdict.clean()) state = "restless";
  }
  return state;
}

}  // namespace figment::serve
