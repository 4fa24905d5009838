// One scene session: a load error is one line; every engine drapes once, in scene order,
// with its own result and error; staging after the drape simulates nothing again; the
// guard's shape check runs after the drape and before staging; a drape that is not clean
// is one line of verdicts(). Two
// sessions in one process share nothing: each drapes with its own cache and observers.

#include <Inventor/fields/SoMFVec3f.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "headless/InitHeadless.h"
#include "io/DrapeCache.h"
#include "nodes/cloth/DrapeKey.h"
#include "session/SceneSession.h"
#include "sim/cloth/ClothSolver.h"
#include "sim/drape/DrapeReport.h"
#include "support/TempDir.h"

using namespace figment::session;

namespace {

// A falling square of cloth fed by an engine named `name` with `fields`.
std::string cloth(const std::string& name, const std::string& fields) {
  return "  Separator {\n    Coordinate3 { point = DEF " + name +
         " ClothEngine {\n"
         "      restPoints [ -0.5 1 -0.5, 0.5 1 -0.5, 0.5 1 0.5, -0.5 1 0.5 ]\n"
         "      coordIndex [ 0 3 2 1 -1 ]  maxTime 0.01 " +
         // Written for the paper's explicit path, once the default: named unless `fields` name another.
         (fields.find("integrator") == std::string::npos ? "integrator HEUN " : "") + fields +
         "\n"
         "    } . positions }\n"
         "    IndexedFaceSet { coordIndex [ 0 3 2 1 -1 ] }\n  }\n";
}

class SceneSessionTest : public ::testing::Test {
 protected:
  void SetUp() override { figment::initHeadless(); }
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

  const std::vector<ClothEngine*>& drapes = session.drape();
  ASSERT_EQ(drapes.size(), 2u);
  EXPECT_EQ(drapes[0]->getName().getString(), std::string("First"));
  EXPECT_EQ(drapes[0]->label(), "ClothEngine 'First'");
  EXPECT_EQ(drapes[0]->lastError(), "");
  EXPECT_GT(drapes[0]->lastRun().run.iterations, 0);
  EXPECT_EQ(drapes[0]->lastRun().triangles, 2);
  EXPECT_EQ(figment::fieldName(drapes[0]->lastRun().method.integrator), std::string("HEUN"));
  EXPECT_EQ(drapes[0]->lastRun().body.kind, "none");
  EXPECT_EQ(drapes[1]->getName().getString(), std::string("Second"));
  EXPECT_NE(drapes[1]->lastError().find("thickness = -0.001 must be > 0"), std::string::npos) << drapes[1]->lastError();
  EXPECT_EQ(session.firstError(), drapes[1]->lastError());
  for (const ClothEngine* engine : session.engines()) EXPECT_EQ(engine->evaluationCount(), 1);

  ASSERT_NE(session.stage({64, 48}, ViewDirection{30.0, 10.0}), nullptr);
  EXPECT_FALSE(session.stagedBox().isEmpty());
  for (const ClothEngine* engine : session.engines())
    EXPECT_EQ(engine->evaluationCount(), 1) << "staging after the drape simulates nothing again";
}

// The verdicts any front end reads: one line for each drape that is not clean (here two
// squares stopped mid-fall by maxTime), none for a clean one (weightless, at rest once
// its window passed) nor for one that failed (its error says what happened).
TEST_F(SceneSessionTest, SaysWhichDrapesAreNotCleanInOneLineEach) {
  const std::string scene =
      dir_.file("four.iv", "#Inventor V2.1 ascii\nSeparator {\n" + cloth("Falling", "timeStep 0.001") +
                               cloth("Resting", "timeStep 0.001 maxTime 1 gravity 0 0 0 restWindow 0.005") +
                               cloth("Broken", "thickness -0.001") + cloth("AlsoFalling", "timeStep 0.002") + "}\n");
  SceneSession session;
  ASSERT_TRUE(session.load(scene)) << session.loadError();
  const std::vector<ClothEngine*>& drapes = session.drape();
  ASSERT_EQ(drapes.size(), 4u);
  EXPECT_EQ(drapes[1]->lastRun().verdict, "");
  EXPECT_TRUE(drapes[1]->lastRun().run.atRest);
  EXPECT_EQ(drapes[1]->lastRun().maxTime, 1.0);  // the method that ran, its bound included
  const std::vector<std::string> lines = session.verdicts();
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].rfind("ClothEngine 'Falling': not at rest after maxTime 0.01 s (max speed 0.09", 0), 0u)
      << lines[0];
  EXPECT_EQ(lines[1].rfind("ClothEngine 'AlsoFalling': not at rest after maxTime 0.01 s", 0), 0u) << lines[1];
  EXPECT_NEAR(drapes[0]->lastRun().run.maxStretch, 1.0, 1e-6);  // a falling square keeps its shape
}

TEST_F(SceneSessionTest, DrapingAgainSimulatesOnlyTheEnginesWhoseInputsChanged) {
  const std::string scene =
      dir_.file("two.iv", "#Inventor V2.1 ascii\nSeparator {\n" + cloth("First", "") + cloth("Second", "") + "}\n");
  SceneSession session;
  ASSERT_TRUE(session.load(scene)) << session.loadError();
  session.drape();
  session.engines()[1]->friction = 0.2;
  const std::vector<ClothEngine*>& drapes = session.drape();
  EXPECT_EQ(session.engines()[0]->evaluationCount(), 1);
  EXPECT_EQ(session.engines()[1]->evaluationCount(), 2);
  EXPECT_EQ(drapes[1]->lastError(), "");
  EXPECT_GT(drapes[1]->lastRun().run.iterations, 0);
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

// A ClothingLayer asking for a display mesh it cannot have is refused as a bad shape is.
TEST_F(SceneSessionTest, RefusesADisplaySubdivisionOutOfRange) {
  const std::string bad =
      dir_.file("layer.iv",
                "#Inventor V2.1 ascii\nSeparator {\n  Coordinate3 { point [ 0 0 0, 1 0 0, 0 1 0 ] }\n"
                "  DEF Dress ClothingLayer { coordIndex [ 0 1 2 -1 ] displaySubdivision 9 }\n}\n");
  SceneSession session;
  ASSERT_TRUE(session.load(bad)) << session.loadError();
  EXPECT_EQ(session.stage({64, 48}, std::nullopt), nullptr);
  EXPECT_EQ(session.shapeError(), "ClothingLayer 'Dress': displaySubdivision = 9 is not 0 to 3");
}

TEST_F(SceneSessionTest, StagingAnUndrapedSceneChecksItsShapesFirst) {
  const std::string bad =
      dir_.file("faces.iv",
                "#Inventor V2.1 ascii\nSeparator {\n  Coordinate3 { point [ 0 0 0, 1 0 0, 0 1 0 ] }\n"
                "  IndexedFaceSet { coordIndex [ 0 1 2147483647 -1 ] }\n}\n");
  SceneSession session;
  ASSERT_TRUE(session.load(bad)) << session.loadError();
  EXPECT_EQ(session.stage({64, 48}, std::nullopt), nullptr);
  EXPECT_EQ(session.shapeError(),
            "IndexedFaceSet: coordIndex[2] = 2147483647 is not a vertex: the coordinates have 3 points");
}

namespace {

// A box 0.4 m wide whose top is at `top` m, as an OBJ file (faces wound outwards).
std::string boxObj(double top) {
  const std::string lo = "0.1", hi = std::to_string(top);
  return "v -0.2 " + lo + " -0.2\nv 0.2 " + lo + " -0.2\nv 0.2 " + lo + " 0.2\nv -0.2 " + lo + " 0.2\n" + "v -0.2 " +
         hi + " -0.2\nv 0.2 " + hi + " -0.2\nv 0.2 " + hi + " 0.2\nv -0.2 " + hi + " 0.2\n" +
         "f 5 8 7\nf 5 7 6\nf 1 2 3\nf 1 3 4\nf 4 3 7\nf 4 7 8\nf 1 5 6\nf 1 6 2\nf 2 6 7\nf 2 7 3\n"
         "f 1 4 8\nf 1 8 5\n";
}

// A square of cloth `width` m wide, 0.1 m above the box in `obj`, dropped on it for 0.2 s
// at steps of 1 ms (200 steps).
std::string clothOnBox(const std::string& obj, double width, double top) {
  const std::string h = std::to_string(width / 2), y = std::to_string(top + 0.1);
  return "#Inventor V2.1 ascii\nSeparator {\n  DEF Body MeshFile { fileName \"" + obj +
         "\" }\n"
         "  Coordinate3 { point = DEF Drape ClothEngine {\n    restPoints [ -" +
         h + " " + y + " -" + h + ", " + h + " " + y + " -" + h + ", " + h + " " + y + " " + h + ", -" + h + " " + y +
         " " + h + ", 0 " + y +
         " 0 ]\n"
         "    coordIndex [ 0 4 1 -1, 1 4 2 -1, 2 4 3 -1, 3 4 0 -1 ]  body USE Body  timeStep 0.001  maxTime 0.2\n"
         "  } . positions }\n  IndexedFaceSet { coordIndex [ 0 4 1 -1, 1 4 2 -1, 2 4 3 -1, 3 4 0 -1 ] }\n}\n";
}

// The draped points where the scene's one engine feeds them (a new connection to its
// output would evaluate it again).
std::vector<SbVec3f> drapedPositions(const SceneSession& session) {
  const auto* points = static_cast<const SoMFVec3f*>(session.engines().front()->positions[0]);
  return {points->getValues(0), points->getValues(0) + points->getNum()};
}

bool sameBits(const std::vector<SbVec3f>& a, const std::vector<SbVec3f>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(SbVec3f)) == 0;
}

std::set<std::filesystem::path> filesIn(const std::filesystem::path& folder) {
  std::set<std::filesystem::path> files;
  std::error_code none;  // a folder never made holds nothing
  for (const auto& entry : std::filesystem::directory_iterator(folder, none)) files.insert(entry.path());
  return files;
}

// What a session's observers saw: the engines they were called for, and how often.
struct Watch {
  std::set<const ClothEngine*> progressFrom, stepsFrom;
  int progressReports = 0, stepCalls = 0;

  // Progress every 64 steps; it leaves the cache in use.
  void watchProgress(figment::DrapeContext& context) {
    context.progress = [this](const ClothEngine& engine, const ClothEngine::Progress&) {
      progressFrom.insert(&engine);
      ++progressReports;
    };
    context.progressInterval = 0.0;
  }
  // Every step; an observed drape is simulated, not read from the cache.
  void watchSteps(figment::DrapeContext& context) {
    context.stepObserver = [this](const ClothEngine& engine, const figment::ClothSolver&) {
      stepsFrom.insert(&engine);
      ++stepCalls;
    };
  }
};

}  // namespace

TEST_F(SceneSessionTest, TwoSessionsInOneProcessKeepTheirOwnCachesAndObservers) {
  const std::string sceneA = dir_.file("a/scene.iv", clothOnBox("box.obj", 0.6, 0.5));
  const std::string sceneB = dir_.file("b/scene.iv", clothOnBox("box.obj", 0.3, 0.7));
  dir_.file("a/box.obj", boxObj(0.5));
  dir_.file("b/box.obj", boxObj(0.7));
  // Each scene alone, with nothing set: the drape to compare with.
  std::vector<SbVec3f> aloneA, aloneB;
  int stepsA = 0, stepsB = 0;
  for (auto [scene, positions, steps] : {std::tuple{sceneA, &aloneA, &stepsA}, std::tuple{sceneB, &aloneB, &stepsB}}) {
    SceneSession alone;
    ASSERT_TRUE(alone.load(scene)) << alone.loadError();
    ASSERT_EQ(alone.drape().front()->lastError(), "");
    *positions = drapedPositions(alone);
    *steps = alone.engines().front()->lastRun().run.iterations;
  }
  ASSERT_FALSE(sameBits(aloneA, aloneB));
  ASSERT_GE(stepsA, 128);  // enough for progress reports
  ASSERT_GE(stepsB, 128);

  // Both loaded and set up before either drapes: a setting shared between them would
  // be the second one's for both.
  SceneSession a, b;
  ASSERT_TRUE(a.load(sceneA)) << a.loadError();
  ASSERT_TRUE(b.load(sceneB)) << b.loadError();
  const std::filesystem::path folderA = dir_.path() / "cache-a", folderB = dir_.path() / "cache-b";
  a.context().cache = std::make_shared<figment::DrapeCache>(folderA, 1u << 20);
  b.context().cache = std::make_shared<figment::DrapeCache>(folderB, 1u << 20);
  Watch watchA, watchB;
  watchA.watchProgress(a.context());
  watchB.watchProgress(b.context());
  ASSERT_EQ(a.drape().front()->lastError(), "");
  ASSERT_EQ(b.drape().front()->lastError(), "");
  EXPECT_TRUE(sameBits(drapedPositions(a), aloneA));
  EXPECT_TRUE(sameBits(drapedPositions(b), aloneB));
  const ClothEngine* engineA = a.engines().front();
  const ClothEngine* engineB = b.engines().front();
  EXPECT_EQ(watchA.progressFrom, std::set<const ClothEngine*>{engineA});
  EXPECT_EQ(watchB.progressFrom, std::set<const ClothEngine*>{engineB});
  EXPECT_EQ(watchA.progressReports, stepsA / 64);
  EXPECT_EQ(watchB.progressReports, stepsB / 64);
  // Each cache folder holds its own scene's drape, and only that.
  EXPECT_EQ(filesIn(folderA), std::set{a.context().cache->entryPath(figment::drapeKey(*engineA, ""))});
  EXPECT_EQ(filesIn(folderB), std::set{b.context().cache->entryPath(figment::drapeKey(*engineB, ""))});

  // Step observers, both set before either drapes again: each sees its own steps only.
  watchA.watchSteps(a.context());
  watchB.watchSteps(b.context());
  a.engines().front()->restPoints.touch();
  b.engines().front()->restPoints.touch();
  ASSERT_EQ(a.drape().front()->lastError(), "");
  ASSERT_EQ(b.drape().front()->lastError(), "");
  EXPECT_TRUE(sameBits(drapedPositions(a), aloneA));
  EXPECT_TRUE(sameBits(drapedPositions(b), aloneB));
  EXPECT_EQ(watchA.stepsFrom, std::set<const ClothEngine*>{engineA});
  EXPECT_EQ(watchB.stepsFrom, std::set<const ClothEngine*>{engineB});
  EXPECT_EQ(watchA.stepCalls, stepsA + 1);  // before the first step, then after each
  EXPECT_EQ(watchB.stepCalls, stepsB + 1);
}

TEST_F(SceneSessionTest, AnEngineLeftByItsSessionDrapesWithoutItsContext) {
  const std::string scene = dir_.file("one.iv", "#Inventor V2.1 ascii\nSeparator {\n" + cloth("Only", "") + "}\n");
  SceneSession session;
  ASSERT_TRUE(session.load(scene)) << session.loadError();
  ClothEngine* engine = session.engines().front();
  EXPECT_EQ(engine->drapeContext(), session.sharedContext());
  engine->ref();
  session.clear();
  EXPECT_EQ(engine->drapeContext(), nullptr);
  engine->unref();
}

TEST_F(SceneSessionTest, AdoptsAGraphBuiltInCodeAsALoadedOne) {
  // A front end's own graph: a square of cloth fed by an engine made in code, no text read.
  ClothEngine* engine = new ClothEngine;
  const float square[4][3] = {{-0.5f, 1, -0.5f}, {0.5f, 1, -0.5f}, {0.5f, 1, 0.5f}, {-0.5f, 1, 0.5f}};
  engine->restPoints.setValues(0, 4, square);
  const int32_t faces[] = {0, 3, 2, 1, -1};
  engine->coordIndex.setValues(0, 5, faces);
  engine->maxTime = 0.01;
  auto* root = new SoSeparator;
  auto* coordinates = new SoCoordinate3;
  coordinates->point.connectFrom(&engine->positions);
  auto* shape = new SoIndexedFaceSet;
  shape->coordIndex.setValues(0, 5, faces);
  root->addChild(coordinates);
  root->addChild(shape);
  SceneSession session;
  session.adopt(root);
  ASSERT_EQ(session.engines().size(), 1u);
  EXPECT_EQ(session.engines().front(), engine);
  EXPECT_EQ(engine->drapeContext(), session.sharedContext());
  const std::vector<ClothEngine*>& drapes = session.drape();
  ASSERT_EQ(drapes.size(), 1u);
  EXPECT_EQ(drapes.front()->lastError(), "");
  EXPECT_GT(drapes.front()->lastRun().run.iterations, 0);  // it simulated
  EXPECT_NE(session.stage(ImageSize{64, 48}, ViewDirection{}), nullptr);
  engine->ref();
  session.clear();
  EXPECT_EQ(engine->drapeContext(), nullptr);  // the session let it go
  engine->unref();
}
