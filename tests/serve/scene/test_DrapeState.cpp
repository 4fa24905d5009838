// How a scene's drapes ended, as the X-Figment-Drape header says it: sim's DrapeVerdict
// read from each drape's run statistics, the worst of the garments winning.

#include <gtest/gtest.h>

#include "serve/scene/DrapeState.h"

using figment::DrapeReport;
using figment::serve::drapeState;

namespace {

// A drape that came to rest whole, as the drape cache records one.
DrapeReport atRest() {
  DrapeReport drape;
  drape.run.atRest = true;
  drape.run.maxStretch = 1.08;  // the shipped drapes end at 1.03 to 1.14
  return drape;
}

}  // namespace

TEST(DrapeState, DrapesAtRestAreRest) {
  EXPECT_EQ(drapeState({}), "rest");  // the body alone
  EXPECT_EQ(drapeState({atRest(), atRest()}), "rest");
}

TEST(DrapeState, ADrapeStillMovingOrHeldByALimiterIsRestless) {
  DrapeReport moving = atRest(), clamped = atRest(), limited = atRest();
  moving.run.atRest = false;
  clamped.run.clampedSectionShareAtEnd = 0.01;
  limited.run.limitedNodeShareAtEnd = 0.02;
  for (const DrapeReport& drape : {moving, clamped, limited}) EXPECT_EQ(drapeState({atRest(), drape}), "restless");
}

TEST(DrapeState, AnEdgePastTheTearStretchOrAFailedStepIsTorn) {
  DrapeReport stretched = atRest(), failed = atRest(), restlessToo = atRest();
  stretched.run.maxStretch = 1.51;  // DrapeVerdict::kTearStretch 1.5
  failed.run.implicitCosts.failedSteps = 1;
  restlessToo.run.atRest = false;
  EXPECT_EQ(drapeState({stretched}), "torn");
  EXPECT_EQ(drapeState({atRest(), failed}), "torn");
  EXPECT_EQ(drapeState({restlessToo, stretched}), "torn");  // the worse of the two
  DrapeReport atTheBound = atRest();
  atTheBound.run.maxStretch = 1.5;  // not past it
  EXPECT_EQ(drapeState({atTheBound}), "rest");
}
