// ClothEngine with a progressive mesh (paper §4): it drapes from the script's coarsest
// level to the level asked for, outputs every rest point and the level's sections, and a
// script that is missing or belongs to another garment is a one-line error.

#include <Inventor/fields/SoMFInt32.h>
#include <Inventor/fields/SoMFVec3f.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "io/ProgressiveScript.h"
#include "nodes/cloth/ClothEngine.h"
#include "nodes/cloth/ClothEngineInputs.h"
#include "sim/progressive/Decimation.h"
#include "support/SceneTestSupport.h"
#include "support/ShippedGarmentScene.h"

using namespace figment::test;

namespace {

// An n x n grid of cloth 0.5 m wide falling for 0.1 s at 1/50 s, its splits at 500 a second.
std::string clothScene(int n) {
  const Grid g = grid(n, 0.5, 1.0);
  return "#Inventor V2.1 ascii\nSeparator {\n"
         "  DEF Cloth Coordinate3 {\n"
         "    point = DEF Drape ClothEngine {\n"
         "      restPoints [ " +
         g.points +
         " ]\n"
         "      coordIndex [ " +
         g.coordIndex +
         " ]\n"
         "      integrator IMPLICIT  timeStep 0.02  maxTime 0.1  splitRate 500\n"
         "    } . positions\n"
         "  }\n"
         "}\n";
}

struct Drape {
  SceneRoot root;
  ClothEngine* engine = nullptr;
  SoMFVec3f positions;
  SoMFInt32 sections;
};

// Reads the scene of an n x n grid; its positions and sections are read through `drape`.
void read(Drape& drape, int n) {
  initCoin();
  drape.root = readString(clothScene(n));
  drape.engine = static_cast<ClothEngine*>(SoBase::getNamedBase("Drape", ClothEngine::getClassTypeId()));
  drape.positions.connectFrom(&drape.engine->positions);
  drape.sections.connectFrom(&drape.engine->levelCoordIndex);
}

// Writes the progressive mesh of an n x n grid's garment (as its engine sees it) in `dir`.
std::string writeScript(const TempDir& dir, int n) {
  Drape other;
  read(other, n);
  const figment::TriangleMesh garment = figment::garmentFromFields(other.engine->restPoints, other.engine->coordIndex);
  const std::string path = (dir.path() / "cloth.pm").string();
  figment::writeProgressiveScript(figment::decimate(garment, figment::DecimationOptions{.targetFaces = 40}), path);
  return path;
}

int faces(const SoMFInt32& coordIndex) {
  return static_cast<int>(std::count(coordIndex.getValues(0), coordIndex.getValues(0) + coordIndex.getNum(), -1));
}

}  // namespace

TEST(ProgressiveClothEngine, DrapesFromTheCoarsestLevelToTheFullGarment) {
  TempDir dir;
  Drape drape;
  read(drape, 12);
  drape.engine->progressiveScript = writeScript(dir, 12).c_str();
  drape.engine->splitRate = 5000.0;  // every split due by the second step
  drape.positions.evaluate();
  ASSERT_EQ(drape.engine->lastError(), "");
  const figment::DrapeReport& run = drape.engine->lastRun();
  EXPECT_GT(run.levels, 50);
  EXPECT_EQ(run.level, run.levels);
  EXPECT_EQ(faces(drape.sections), 2 * 11 * 11);
  EXPECT_EQ(run.sections, 2 * 11 * 11);
  ASSERT_EQ(drape.positions.getNum(), 144);
  EXPECT_LT(drape.positions[0][1], 1.0f) << "it fell";
}

TEST(ProgressiveClothEngine, StopsAtTheEndLevelWithEveryPointPlaced) {
  TempDir dir;
  Drape drape;
  read(drape, 12);
  drape.engine->progressiveScript = writeScript(dir, 12).c_str();
  drape.engine->endLevel = 0;
  drape.positions.evaluate();
  ASSERT_EQ(drape.engine->lastError(), "");
  EXPECT_EQ(drape.engine->lastRun().level, 0);
  EXPECT_LE(faces(drape.sections), 50);
  ASSERT_EQ(drape.positions.getNum(), 144);
  for (int i = 0; i < drape.positions.getNum(); ++i) {
    const SbVec3f& p = drape.positions[i];
    ASSERT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) << "point " << i;
    EXPECT_LT(p[1], 1.0f) << "point " << i << " came down with the coarse level";
  }
}

TEST(ProgressiveClothEngine, AScriptOfAnotherGarmentIsOneLineNamingTheFile) {
  TempDir dir;
  Drape drape;
  read(drape, 12);
  const std::string path = writeScript(dir, 11);
  drape.engine->progressiveScript = path.c_str();
  drape.positions.evaluate();
  EXPECT_EQ(drape.engine->lastError(), "ClothEngine 'Drape': " + path +
                                           ":2: for a garment of 121 vertices and 200 faces, not this one's 144 "
                                           "and 242");
  EXPECT_EQ(drape.positions.getNum(), 144) << "the rest shape comes out";
}

TEST(ProgressiveClothEngine, AMissingScriptIsOneLineNamingTheField) {
  Drape drape;
  read(drape, 12);
  drape.engine->progressiveScript = "nothere.pm";
  drape.positions.evaluate();
  EXPECT_EQ(drape.engine->lastError(), "ClothEngine 'Drape': progressiveScript \"nothere.pm\" not found");
}

TEST(ProgressiveClothEngine, TheDressSplitAllAtOnceOnThePapersPathDoesNotBlowUp) {
  // scenes/dress-progressive.iv on the paper's explicit path (Heun, clamp at 30 g) at a
  // step 1 % longer than the scene's 1.5e-4 s, every split at once when the coarsest
  // level rests (1.75 s): with the split's sections let stretch up to 5 % the dress blew
  // up 0.05 s after it. Run to 0.15 s past the split.
  const ShippedGarmentScene scene("dress-progressive.iv");
  ASSERT_NE(scene.engine(), nullptr);
  ClothEngine& engine = *scene.engine();
  engine.integrator = ClothEngine::HEUN;
  engine.timeStep = 1.515e-4;
  engine.accelerationLimiter = ClothEngine::CLAMP;
  engine.accelerationLimit = 30.0;
  engine.splitRate = 0.0;
  engine.maxTime = 1.9;
  SoMFVec3f positions;
  positions.connectFrom(&engine.positions);
  positions.evaluate();
  EXPECT_EQ(engine.lastError(), "");
  const figment::DrapeReport& run = engine.lastRun();
  ASSERT_EQ(run.level, run.levels) << "the coarsest level did not rest by " << run.run.simulatedTime << " s";
  EXPECT_LT(run.settling.arrival, 1.8);
  EXPECT_LT(run.settling.maxMove, 0.1);
}
