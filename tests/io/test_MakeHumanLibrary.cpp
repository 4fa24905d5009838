// MakeHumanLibrary: MakeHuman's data found and read once for its owner, bodies made from it
// as makeMeasuredBody makes them, the missing data's one line, and no sharing between two libraries.
// The tests with the data skip without it (scripts/setup.sh fetches it).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "io/MakeHumanFiles.h"
#include "io/MakeHumanLibrary.h"
#include "support/ChartBodies.h"
#include "support/IoTestSupport.h"

using namespace figment;
using figment::test::ScopedEnvironment;
using figment::test::TempDir;

TEST(MakeHumanLibrary, WithoutDataItSaysHowToGetItAndLooksAgain) {
  const TempDir dir;
  const ScopedEnvironment empty("FIGMENT_MAKEHUMAN_DIR", dir.path().string());
  MakeHumanLibrary human;
  EXPECT_EQ(human.dir(), "");
  try {
    human.model();
    FAIL() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), kMakeHumanDataMissing);
  }
  EXPECT_THROW(human.measuredBody(Sex::Female, {{"stature", 1.68}}), std::runtime_error);
  // Not found is not kept: the folder is looked for again once it holds the base mesh.
  dir.file("3dobjs/base.obj", "v 0 0 0\n");
  EXPECT_EQ(human.dir(), dir.path().string());
}

TEST(MakeHumanLibrary, TheStartIsTheSexsDefaultBody) {
  EXPECT_EQ(MakeHumanLibrary::start(Sex::Female).macro.gender, 0.0);
  EXPECT_EQ(MakeHumanLibrary::start(Sex::Male).macro.gender, 1.0);
  EXPECT_EQ(MakeHumanLibrary::start(Sex::Male).macro.weight, HumanParameters{}.macro.weight);
}

class MakeHumanLibraryWithData : public ::testing::Test {
 protected:
  void SetUp() override {
    if (human_.dir().empty()) GTEST_SKIP() << test::kMakeHumanDataSkip;
  }
  MakeHumanLibrary human_;
};

TEST_F(MakeHumanLibraryWithData, TheModelIsReadOnceAndKept) {
  const HumanModel& model = human_.model();
  EXPECT_EQ(&human_.model(), &model);
  EXPECT_EQ(human_.dir(), findMakeHumanData());
  MakeHumanLibrary other;  // a second owner reads its own
  EXPECT_NE(&other.model(), &model);
}

// A chart body is makeMeasuredBody's from the sex's default body to stature, bust, waist and hip
// girth in that order: the same vertices, and each girth met within the 5 mm tolerance.
TEST_F(MakeHumanLibraryWithData, AChartBodyIsMadeToTheSizesFourMeasurements) {
  const ChartSize m{Sex::Male, "M", "48", 1.74, 0.96, 0.84, 1.00};
  const MeasuredBody made = human_.measuredBody(m);
  const MeasuredBody direct =
      makeMeasuredBody(human_.model(), MakeHumanLibrary::start(Sex::Male),
                       {{"stature", 1.74}, {"bust_girth", 0.96}, {"waist_girth", 0.84}, {"hip_girth", 1.00}});
  ASSERT_EQ(made.body.vertices.size(), direct.body.vertices.size());
  for (size_t i = 0; i < made.body.vertices.size(); ++i) ASSERT_EQ(made.body.vertices[i], direct.body.vertices[i]) << i;
  EXPECT_EQ(made.parameters.macro.gender, 1.0);
  EXPECT_NEAR(made.achieved.stature, 1.74, 0.005);
  EXPECT_NEAR(made.achieved.hipGirth, 1.00, 0.005);
}

TEST_F(MakeHumanLibraryWithData, AMeasurementOutOfReachIsRefusedNamingIt) {
  try {
    human_.measuredBody(Sex::Female, {{"hip_girth", 0.30}});
    FAIL() << "no exception";
  } catch (const UnreachableMeasurement& error) {
    EXPECT_NE(std::string(error.what()).find("hip_girth"), std::string::npos) << error.what();
  }
}
