#include "serve/scene/DrapeState.h"

#include "sim/cloth/DrapeVerdict.h"

namespace figment::serve {

std::string drapeState(const std::vector<session::EngineDrape>& drapes) {
  std::string state = "rest";
  for (const session::EngineDrape& drape : drapes) {
    DrapeVerdict verdict;
    verdict.atRest = drape.run.atRest;
    verdict.maxStretch = drape.run.maxStretch;
    verdict.clampedSectionShareAtEnd = drape.run.clampedSectionShareAtEnd;
    verdict.limitedNodeShareAtEnd = drape.run.limitedNodeShareAtEnd;
    verdict.failedSteps = drape.run.failedSteps;
    if (verdict.tore() || verdict.failedSteps > 0) return "torn";
    if (!verdict.clean()) state = "restless";
  }
  return state;
}

}  // namespace figment::serve
