// A drape's verdict: clean only when at rest, untorn, unlimited at the end and with no
// failed implicit step; otherwise one line naming each thing that happened, with its
// figures.
#include <gtest/gtest.h>

#include "sim/cloth/DrapeVerdict.h"

using namespace figment;

namespace {
DrapeVerdict cleanVerdict() {
  DrapeVerdict v;
  v.run.atRest = true;
  v.maxTime = 5.0;
  v.run.maxSpeed = 0.004;
  v.run.maxStretch = 1.05;
  return v;
}
}  // namespace

TEST(DrapeVerdict, AtRestUntornAndUnlimitedIsCleanAndSaysNothing) {
  DrapeVerdict v = cleanVerdict();
  EXPECT_TRUE(v.clean());
  EXPECT_EQ(v.describe(), "");
  v.run.implicitCosts.halvedSteps = 3;  // recovered: still clean
  EXPECT_TRUE(v.clean());
  EXPECT_EQ(v.describe(), "");
}

TEST(DrapeVerdict, NotAtRestNamesMaxTimeAndTheFastestNode) {
  DrapeVerdict v = cleanVerdict();
  v.run.atRest = false;
  v.maxTime = 10.0;
  v.run.maxSpeed = 0.3149;
  EXPECT_FALSE(v.clean());
  EXPECT_EQ(v.describe(), "not at rest after maxTime 10 s (max speed 0.315 m/s)");
}

TEST(DrapeVerdict, TornIsAnEdgePastTheBoundNotAtIt) {
  DrapeVerdict v = cleanVerdict();
  v.run.maxStretch = DrapeVerdict::kTearStretch;
  EXPECT_TRUE(v.clean());
  // Just past it (a millionth of the bound, far below any edge's measured stretch): torn, so
  // a bound moved by anything that matters fails here, not only one moved past 2.
  v.run.maxStretch = 1.5 * (1 + 1e-6);
  EXPECT_TRUE(v.tore());
  EXPECT_FALSE(v.clean());
  v.run.maxStretch = 1.5 * (1 - 1e-6);
  EXPECT_TRUE(v.clean());
  v.run.maxStretch = 2.0221;
  EXPECT_TRUE(v.tore());
  EXPECT_EQ(v.describe(), "torn: an edge at 2.02 times its rest length (bound 1.5)");
}

TEST(DrapeVerdict, EveryProblemIsInTheOneLine) {
  DrapeVerdict v = cleanVerdict();
  v.run.atRest = false;
  v.run.maxStretch = 2.64;
  v.run.limitedNodeShareAtEnd = 0.0354;
  v.run.implicitCosts.halvedSteps = 5;
  v.run.implicitCosts.failedSteps = 1;
  const std::string line = v.describe();
  EXPECT_EQ(line.find('\n'), std::string::npos);
  EXPECT_NE(line.find("not at rest after maxTime 5 s"), std::string::npos) << line;
  EXPECT_NE(line.find("; torn: an edge at 2.64 times"), std::string::npos) << line;
  EXPECT_NE(line.find("; limited: the acceleration limiter cut 3.54 % of the nodes in the last step"),
            std::string::npos)
      << line;
  EXPECT_NE(line.find("; 1 implicit step still stretched an edge past 1.5 at the step control's smallest step (5 "
                      "halved)"),
            std::string::npos)
      << line;
}
