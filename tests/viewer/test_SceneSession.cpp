// One scene session: a load error is one line; every engine drapes once, in scene order,
// with its own result and error; staging after the drape simulates nothing again.

#include "support/TempDir.h"
#include "viewer/OffscreenContext.h"
#include "viewer/SceneSession.h"

#include <gtest/gtest.h>

#include <string>

using namespace figment::viewer;

namespace {

// A falling square of cloth fed by an engine named `name` with `fields`.
std::string cloth(const std::string& name, const std::string& fields) {
  return "  Separator {\n    Coordinate3 { point = DEF " + name +
         " ClothEngine {\n"
         "      restPoints [ -0.5 1 -0.5, 0.5 1 -0.5, 0.5 1 0.5, -0.5 1 0.5 ]\n"
         "      coordIndex [ 0 3 2 1 -1 ]  maxTime 0.01 " + fields + "\n"
         "    } . positions }\n"
         "    IndexedFaceSet { coordIndex [ 0 3 2 1 -1 ] }\n  }\n";
}

class SceneSessionTest : public ::testing::Test {
 protected:
  void SetUp() override { initHeadless(); }
  figment::test::TempDir dir_;
};

}  // namespace

TEST_F(SceneSessionTest, ALoadErrorIsOneLine) {
  SceneSession session;
  EXPECT_FALSE(session.load((dir_.path() / "missing.iv").string()));
  EXPECT_EQ(session.loadError(), "no such file");
  const std::string unknown = dir_.file("unknown.iv", "#Inventor V2.1 ascii\nSeparator { Frobnicator { } }\n");
  EXPECT_FALSE(session.load(unknown));
  EXPECT_NE(session.loadError().find("line 2"), std::string::npos) << session.loadError();
  EXPECT_EQ(session.loadError().find('\n'), std::string::npos) << session.loadError();
  EXPECT_EQ(session.scene(), nullptr);
}

TEST_F(SceneSessionTest, DrapesEveryEngineOnceInSceneOrderWithItsOwnResult) {
  const std::string scene = dir_.file("two.iv", "#Inventor V2.1 ascii\nSeparator {\n" + cloth("First", "") +
                                                    cloth("Second", "thickness -0.001") + "}\n");
  SceneSession session;
  ASSERT_TRUE(session.load(scene)) << session.loadError();
  ASSERT_EQ(session.engines().size(), 2u);
  EXPECT_EQ(session.engines()[0]->evaluationCount(), 0) << "loading simulates nothing";

  const std::vector<EngineDrape>& drapes = session.drape();
  ASSERT_EQ(drapes.size(), 2u);
  EXPECT_EQ(drapes[0].name, "First");
  EXPECT_EQ(drapes[0].label, "ClothEngine 'First'");
  EXPECT_EQ(drapes[0].error, "");
  EXPECT_GT(drapes[0].run.iterations, 0);
  EXPECT_EQ(drapes[0].run.triangles, 2);
  EXPECT_EQ(drapes[0].method.integrator, "HEUN");
  EXPECT_EQ(drapes[0].body.kind, "none");
  EXPECT_EQ(drapes[1].name, "Second");
  EXPECT_NE(drapes[1].error.find("thickness = -0.001 must be > 0"), std::string::npos) << drapes[1].error;
  EXPECT_EQ(session.firstError(), drapes[1].error);
  for (const ClothEngine* engine : session.engines()) EXPECT_EQ(engine->evaluationCount(), 1);

  ASSERT_NE(session.stage({64, 48}, ViewDirection{30.0, 10.0}), nullptr);
  EXPECT_FALSE(session.stagedBox().isEmpty());
  for (const ClothEngine* engine : session.engines())
    EXPECT_EQ(engine->evaluationCount(), 1) << "staging after the drape simulates nothing again";
}

TEST_F(SceneSessionTest, DrapingAgainSimulatesOnlyTheEnginesWhoseInputsChanged) {
  const std::string scene =
      dir_.file("two.iv", "#Inventor V2.1 ascii\nSeparator {\n" + cloth("First", "") + cloth("Second", "") + "}\n");
  SceneSession session;
  ASSERT_TRUE(session.load(scene)) << session.loadError();
  session.drape();
  session.engines()[1]->friction = 0.2;
  const std::vector<EngineDrape>& drapes = session.drape();
  EXPECT_EQ(session.engines()[0]->evaluationCount(), 1);
  EXPECT_EQ(session.engines()[1]->evaluationCount(), 2);
  EXPECT_EQ(drapes[1].error, "");
  EXPECT_GT(drapes[1].run.iterations, 0);
}

// The guard's draw-side check runs in the session, so every program that stages through it
// (figment-view, figment-bench, the fuzz target) gets it: after the drape, a shape indexing past
// its draped coordinates is one line, and nothing is staged.
TEST_F(SceneSessionTest, ChecksTheDrapedShapesAndStagesNothingPastTheirData) {
  const std::string good = dir_.file("good.iv", "#Inventor V2.1 ascii\nSeparator {\n" + cloth("Drape", "") + "}\n");
  SceneSession session;
  ASSERT_TRUE(session.load(good)) << session.loadError();
  session.drape();
  EXPECT_EQ(session.shapeError(), "");
  EXPECT_NE(session.stage({64, 48}, std::nullopt), nullptr);

  std::string text = cloth("Drape", "");
  text.replace(text.find("IndexedFaceSet { coordIndex [ 0 3 2 1"), 37, "IndexedFaceSet { coordIndex [ 0 3 2 9");
  const std::string bad = dir_.file("bad.iv", "#Inventor V2.1 ascii\nSeparator {\n" + text + "}\n");
  ASSERT_TRUE(session.load(bad)) << session.loadError();
  session.drape();
  EXPECT_EQ(session.shapeError(), "IndexedFaceSet: coordIndex[3] = 9 is not a vertex: the coordinates have 4 points");
  EXPECT_EQ(session.firstError(), session.shapeError());
  EXPECT_EQ(session.stage({64, 48}, std::nullopt), nullptr);
  EXPECT_EQ(session.stagedRoot(), nullptr);
}

TEST_F(SceneSessionTest, StagingAnUndrapedSceneChecksItsShapesFirst) {
  const std::string bad = dir_.file("faces.iv",
                                    "#Inventor V2.1 ascii\nSeparator {\n  Coordinate3 { point [ 0 0 0, 1 0 0, 0 1 0 ] }\n"
                                    "  IndexedFaceSet { coordIndex [ 0 1 2147483647 -1 ] }\n}\n");
  SceneSession session;
  ASSERT_TRUE(session.load(bad)) << session.loadError();
  EXPECT_EQ(session.stage({64, 48}, std::nullopt), nullptr);
  EXPECT_EQ(session.shapeError(),
            "IndexedFaceSet: coordIndex[2] = 2147483647 is not a vertex: the coordinates have 3 points");
}
