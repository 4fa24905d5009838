// MakeHumanSession: MakeHuman's data found and read once for its owner, bodies made from it
// as fitBody makes them, the missing data's one line, and no sharing between two sessions.
// The tests with the data skip without it (scripts/setup.sh fetches it).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "io/MakeHumanFiles.h"
#include "io/MakeHumanSession.h"
#include "support/ChartBodies.h"
#include "support/IoTestSupport.h"

using namespace figment;
using figment::test::ScopedEnvironment;
using figment::test::TempDir;

TEST(MakeHumanSession, WithoutDataItSaysHowToGetItAndLooksAgain) {
  const TempDir dir;
  const ScopedEnvironment empty("FIGMENT_MAKEHUMAN_DIR", dir.path().string());
  MakeHumanSession human;
  EXPECT_EQ(human.dir(), "");
  try {
    human.model();
    FAIL() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), kMakeHumanDataMissing);
  }
  EXPECT_THROW(human.fit(Sex::Female, {{"stature", 1.68}}), std::runtime_error);
  // Not found is not kept: the folder is looked for again once it holds the base mesh.
  dir.file("3dobjs/base.obj", "v 0 0 0\n");
  EXPECT_EQ(human.dir(), dir.path().string());
}

TEST(MakeHumanSession, TheStartIsTheSexsDefaultBody) {
  EXPECT_EQ(MakeHumanSession::start(Sex::Female).macro.gender, 0.0);
  EXPECT_EQ(MakeHumanSession::start(Sex::Male).macro.gender, 1.0);
  EXPECT_EQ(MakeHumanSession::start(Sex::Male).macro.weight, HumanParameters{}.macro.weight);
}

class MakeHumanSessionData : public ::testing::Test {
 protected:
  void SetUp() override {
    if (human_.dir().empty()) GTEST_SKIP() << test::kMakeHumanDataSkip;
  }
  MakeHumanSession human_;
};

TEST_F(MakeHumanSessionData, TheModelIsReadOnceAndKept) {
  const HumanModel& model = human_.model();
  EXPECT_EQ(&human_.model(), &model);
  EXPECT_EQ(human_.dir(), findMakeHumanData());
  MakeHumanSession other;  // a second owner reads its own
  EXPECT_NE(&other.model(), &model);
}

// A chart body is fitBody's from the sex's default body to stature, bust, waist and hip
// girth in that order: the same vertices, and each girth met within the fit's 5 mm.
TEST_F(MakeHumanSessionData, AChartBodyIsFitBodysToTheSizesFourMeasurements) {
  const ChartSize m{Sex::Male, "M", "48", 1.74, 0.96, 0.84, 1.00};
  const BodyFitResult made = human_.fit(m);
  const BodyFitResult direct =
      fitBody(human_.model(), MakeHumanSession::start(Sex::Male),
              {{"stature", 1.74}, {"bust_girth", 0.96}, {"waist_girth", 0.84}, {"hip_girth", 1.00}});
  ASSERT_EQ(made.body.vertices.size(), direct.body.vertices.size());
  for (size_t i = 0; i < made.body.vertices.size(); ++i) ASSERT_EQ(made.body.vertices[i], direct.body.vertices[i]) << i;
  EXPECT_EQ(made.parameters.macro.gender, 1.0);
  EXPECT_NEAR(made.achieved.stature, 1.74, 0.005);
  EXPECT_NEAR(made.achieved.hipGirth, 1.00, 0.005);
}

TEST_F(MakeHumanSessionData, AMeasurementOutOfReachIsRefusedNamingIt) {
  try {
    human_.fit(Sex::Female, {{"hip_girth", 0.30}});
    FAIL() << "no exception";
  } catch (const UnreachableMeasurement& error) {
    EXPECT_NE(std::string(error.what()).find("hip_girth"), std::string::npos) << error.what();
  }
}
