// ClothEngine.tolerance: the engine drapes by the fastest configuration the study
// measured within it and says which; a tolerance nothing meets, or a negative one, is
// one line naming the field and value; with none the scene's own fields drape. And the
// committed table's pick for the default dress at 0.5 % lands within 0.5 % of a
// converged drape.
#include <Inventor/SoPath.h>
#include <Inventor/fields/SoMFVec3f.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>

#include "nodes/SceneSearch.h"
#include "nodes/body/Mannequin.h"
#include "sim/collision/Collider.h"
#include "sim/drape/DrapeReport.h"
#include "support/IoTestSupport.h"
#include "support/ShippedGarmentScene.h"

using namespace figment::test;

namespace {

const char* kTable =
    "method,body,progressive,resolution,garments,worst_mean_dev_pct_height,total_median_wall_s\n"
    "implicit:0.05,volumes,off,0.5,3,0.9,0.2\n"  // another resolution: never picked
    "implicit+penalty:0.05,volumes,off,1,3,1.2,0.5\n"
    "implicit:0.05,volumes,0:3000,1,3,0.7,0.8\n"
    "implicit:0.05,triangles,off,1,3,0.6,0.9\n"
    "heun:1.5e-4:clamp:30,triangles,off,1,3,0.05,20\n";

std::vector<SbVec3f> drape(ClothEngine& engine) {
  SoMFVec3f positions;
  positions.connectFrom(&engine.positions);
  positions.evaluate();
  return {positions.getValues(0), positions.getValues(0) + positions.getNum()};
}

class ToleranceEngine : public ::testing::Test {
 protected:
  TempDir dir_;
  ScopedEnvironment table_{"FIGMENT_TRADEOFF_TABLE", dir_.file("table.csv", kTable)};
};

}  // namespace

TEST_F(ToleranceEngine, DrapesByTheFastestMeasuredWithinItAndSaysWhich) {
  const ShippedGarmentScene scene("dress.iv");
  ClothEngine& engine = *scene.engine();
  engine.tolerance = 1.0;
  drape(engine);
  ASSERT_EQ(engine.lastError(), "");
  EXPECT_EQ(engine.lastRun().picked, "implicit:0.05, volumes, progressive 0:3000");
  EXPECT_DOUBLE_EQ(engine.lastRun().pickedDeviation, 0.7);
  EXPECT_GT(engine.lastRun().levels, 0);  // draped progressively, from a mesh made for it
  EXPECT_TRUE(engine.lastRun().run.atRest);

  engine.tolerance = 0.65;
  engine.timeStep = 0.1;  // the pick's step replaces the field's
  drape(engine);
  ASSERT_EQ(engine.lastError(), "");
  const figment::DrapeReport& run = engine.lastRun();
  EXPECT_EQ(run.picked, "implicit:0.05, triangles, progressive off");
  EXPECT_EQ(run.levels, 0);
  // The method that ran is the pick's, not the fields' (what --stats reports).
  EXPECT_EQ(run.pickedBody, "triangles");
  EXPECT_EQ(figment::fieldName(run.method.integrator), "IMPLICIT");
  EXPECT_DOUBLE_EQ(run.method.timeStep, 0.05);
  EXPECT_NEAR(run.run.simulatedTime, run.run.iterations * 0.05, 1e-9);
  EXPECT_EQ(run.passedOver, "");  // nothing faster within 0.65 % was refused
}

TEST_F(ToleranceEngine, AToleranceNothingMeetsOrANegativeOneIsOneLineNamingIt) {
  const ShippedGarmentScene scene("dress.iv");
  ClothEngine& engine = *scene.engine();
  engine.tolerance = 0.01;
  drape(engine);
  EXPECT_NE(engine.lastError().find("tolerance = 0.01: no configuration"), std::string::npos) << engine.lastError();
  EXPECT_EQ(std::count(engine.lastError().begin(), engine.lastError().end(), '\n'), 0);
  engine.tolerance = -1.0;
  drape(engine);
  EXPECT_NE(engine.lastError().find("tolerance"), std::string::npos) << engine.lastError();
  EXPECT_NE(engine.lastError().find("-1"), std::string::npos) << engine.lastError();
}

TEST_F(ToleranceEngine, WithoutAToleranceNothingIsPicked) {
  const ShippedGarmentScene scene("dress.iv");
  ClothEngine& engine = *scene.engine();
  drape(engine);
  ASSERT_EQ(engine.lastError(), "");
  const figment::DrapeReport& run = engine.lastRun();
  EXPECT_EQ(run.picked, "");
  // The scene's own method ran: its implicit steps from 1/20 s growing to 0.4 s (a pick
  // would step 0.02 s or 1.5e-4 s, fixed) on the garment's own sections (a pick may
  // decimate them).
  EXPECT_GT(run.run.iterations, 0);
  EXPECT_EQ(run.run.implicitCosts.steps, run.run.iterations);
  EXPECT_EQ(run.method.text(), "implicit:0.05:0.4");
  EXPECT_GT(run.run.simulatedTime, run.run.iterations * engine.timeStep.getValue() + 0.1);
  EXPECT_LE(run.run.simulatedTime, run.run.iterations * engine.maxTimeStep.getValue() + 1e-9);
  EXPECT_DOUBLE_EQ(engine.timeStep.getValue(), 0.05);
  EXPECT_EQ(run.triangles, engine.coordIndex.getNum() / 4);
}

TEST(ToleranceEngineMix, APosedMannequinGetsThePerPartMixNotItsRestPoseTriangles) {
  TempDir dir;
  const ScopedEnvironment table{"FIGMENT_TRADEOFF_TABLE",
                                dir.file("table.csv",
                                         "method,body,progressive,resolution,garments,worst_mean_dev_pct_height,"
                                         "total_median_wall_s\n"
                                         "implicit:0.05,triangles,off,1,3,0.5,0.3\n"
                                         "implicit:0.05,mix,off,1,3,0.6,0.5\n")};
  const ShippedGarmentScene scene("dress.iv");
  ClothEngine& engine = *scene.engine();
  engine.tolerance = 0.7;
  drape(engine);
  ASSERT_EQ(engine.lastError(), "");
  EXPECT_EQ(engine.lastRun().picked, "implicit:0.05, triangles, progressive off");
  // Arms turned out a little: the body's own triangles are not posed, the mix's parts are.
  const SoPathList found = figment::findAll(scene.root(), Mannequin::getClassTypeId());
  ASSERT_EQ(found.getLength(), 1);
  auto* mannequin = static_cast<Mannequin*>(found[0]->getTail());
  mannequin->rotatedJoints.setValues(0, 2, std::array<SbString, 2>{"shoulderL", "shoulderR"}.data());
  mannequin->rotations.setValues(
      0, 2, std::array<SbRotation, 2>{SbRotation(SbVec3f(0, 0, 1), 0.1f), SbRotation(SbVec3f(0, 0, 1), -0.1f)}.data());
  const std::vector<SbVec3f> posed = drape(engine);
  ASSERT_EQ(engine.lastError(), "");
  EXPECT_EQ(engine.lastRun().picked, "implicit:0.05, mix, progressive off");
  EXPECT_TRUE(engine.lastRun().run.atRest);
  // The faster triangles were passed over, and the run says why.
  EXPECT_EQ(
      engine.lastRun().passedOver,
      "implicit:0.05, triangles, progressive off (the Mannequin's triangles are its rest pose and size, and it is "
      "posed (rotatedJoints))");
  // At rest outside the posed body's volumes (the mix's volume parts and more).
  int inside = 0;
  figment::Contact contact;
  for (const SbVec3f& p : posed)
    inside += mannequin->collider()->contact({p[0], p[1], p[2]}, 0.0, 0.05, contact) && contact.distance < -0.01;
  EXPECT_EQ(inside, 0);
}

// At 0.6 %: since the T-shirt's mesh was cut again (2026-11-27) the paper's path, the old
// table's pick at 0.5 %, blows up on it, and nothing rests within 0.5 % on all three
// garments (docs/results.md, "Speed against accuracy").
TEST(ToleranceEngineCommittedTable, TheDressPickedAtSixTenthsOfAPercentLandsWithinItOfAConvergedDrape) {
  const ShippedGarmentScene scene("dress.iv");
  ClothEngine& engine = *scene.engine();
  engine.tolerance = 0.6;
  const std::vector<SbVec3f> picked = drape(engine);
  ASSERT_EQ(engine.lastError(), "");
  ASSERT_LE(engine.lastRun().pickedDeviation, 0.6);
  // The converged drape as the study makes it: Heun without limiters at a small step on
  // the body's own triangles (1e-4 s here; at 5e-5 s it moves 0.01 %).
  const SoPathList mannequins = figment::findAll(scene.root(), Mannequin::getClassTypeId());
  ASSERT_EQ(mannequins.getLength(), 1);
  engine.tolerance = 0.0;
  engine.body = static_cast<Mannequin*>(mannequins[0]->getTail())->body.getValue();
  engine.integrator = ClothEngine::HEUN;
  engine.maxTimeStep = 0.0;  // the dress's growing step is IMPLICIT's
  engine.accelerationLimiter = ClothEngine::NONE;
  engine.timeStep = 1e-4;
  const std::vector<SbVec3f> reference = drape(engine);
  ASSERT_EQ(engine.lastError(), "");
  ASSERT_TRUE(engine.lastRun().run.atRest);
  float low = 1e9f, high = -1e9f;
  for (int i = 0; i < engine.restPoints.getNum(); ++i)
    low = std::min(low, engine.restPoints[i][1]), high = std::max(high, engine.restPoints[i][1]);
  double mean = 0.0;
  for (size_t i = 0; i < picked.size(); ++i) mean += (picked[i] - reference[i]).length();
  mean /= static_cast<double>(picked.size());
  EXPECT_LT(100.0 * mean / (high - low), 0.6);
}
