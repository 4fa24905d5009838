#include "serve/scene/DrapeState.h"

#include "nodes/cloth/ClothEngine.h"
#include "sim/cloth/DrapeVerdict.h"

namespace figment::serve {

std::vector<DrapeReport> drapeReports(const std::vector<ClothEngine*>& engines) {
  std::vector<DrapeReport> reports;
  for (const ClothEngine* engine : engines) reports.push_back(engine->lastRun());
  return reports;
}

std::string drapeState(const std::vector<DrapeReport>& reports) {
  std::string state = "rest";
  for (const DrapeReport& report : reports) {
    const DrapeVerdict verdict{report.run, report.maxTime};
    if (verdict.tore() || verdict.run.implicitCosts.failedSteps > 0) return "torn";
    if (!verdict.clean()) state = "restless";
  }
  return state;
}

}  // namespace figment::serve
