// A ClothEngine's fields as a drape's ask and its report before any drape: the garment, the
// parameters, the body (a Mannequin offers its own triangles and per-part mix), the
// tolerance's table, the progressive script; what cannot be used names itself.
#include <gtest/gtest.h>

#include <stdexcept>

#include "nodes/cloth/ClothEngine.h"
#include "nodes/cloth/EngineAsk.h"
#include "support/IoTestSupport.h"
#include "support/ShippedGarmentScene.h"

using namespace figment::test;

namespace {
const std::vector<std::string> kNoDirectories;

template <class Error>
std::string errorOf(const ClothEngine& engine) {
  std::optional<figment::MethodTable> table;
  try {
    figment::drapeAskFromFields(engine, kNoDirectories, table);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(EngineAsk, TheDressFieldsAskForItsGarmentParametersAndJointedBody) {
  const ShippedGarmentScene scene("dress.iv");
  ClothEngine& engine = *scene.engine();
  std::optional<figment::MethodTable> table;
  const figment::DrapeAsk ask = figment::drapeAskFromFields(engine, kNoDirectories, table);
  EXPECT_EQ(ask.garment.vertices.size(), static_cast<size_t>(engine.restPoints.getNum()));
  EXPECT_FALSE(ask.garment.triangles.empty());
  EXPECT_DOUBLE_EQ(ask.parameters.timeStep, engine.timeStepSeconds());
  EXPECT_EQ(ask.tolerance, 0.0);
  EXPECT_FALSE(table);  // no tolerance: no table read
  EXPECT_FALSE(ask.progressive);
  EXPECT_FALSE(ask.sewing);
  EXPECT_TRUE(ask.body.collider);
  EXPECT_EQ(ask.body.description.kind, "mannequin");
  ASSERT_TRUE(ask.body.jointed);
  EXPECT_EQ(ask.body.poseOrSize, "");  // the shipped Mannequin stands in its rest pose and size
  ASSERT_TRUE(ask.body.triangles);
  EXPECT_TRUE(ask.body.triangles());
  EXPECT_EQ(ask.body.trianglesDescription.kind, "mesh");
  EXPECT_TRUE(ask.body.withExactParts({}));
}

TEST(EngineAsk, AToleranceReadsTheTableAndANegativeOneIsRefused) {
  const ShippedGarmentScene scene("dress.iv");
  ClothEngine& engine = *scene.engine();
  engine.tolerance = 0.5;
  std::optional<figment::MethodTable> table;
  const figment::DrapeAsk ask = figment::drapeAskFromFields(engine, kNoDirectories, table);
  ASSERT_TRUE(table);
  EXPECT_EQ(ask.table, &*table);
  EXPECT_EQ(table->source, figment::tradeoffTablePath());
  EXPECT_FALSE(table->configurations.empty());
  engine.tolerance = -1.0;
  EXPECT_NE(errorOf<std::invalid_argument>(engine).find("tolerance"), std::string::npos);
}

TEST(EngineAsk, TheTablesPathFollowsTheEnvironment) {
  const ScopedEnvironment table{"FIGMENT_TRADEOFF_TABLE", "/nowhere/table.csv"};
  EXPECT_EQ(figment::tradeoffTablePath(), "/nowhere/table.csv");
  const ShippedGarmentScene scene("dress.iv");
  scene.engine()->tolerance = 0.5;
  EXPECT_EQ(errorOf<std::runtime_error>(*scene.engine()), "/nowhere/table.csv: cannot be read");
}

TEST(EngineAsk, AMissingProgressiveScriptIsNamed) {
  const ShippedGarmentScene scene("dress.iv");
  scene.engine()->progressiveScript = "no-such-script.txt";
  EXPECT_EQ(errorOf<std::runtime_error>(*scene.engine()), "progressiveScript \"no-such-script.txt\" not found");
}

TEST(EngineAsk, AReportBeforeAnyDrapeNamesTheFieldsMethodAndTheBody) {
  const ShippedGarmentScene scene("dress.iv");
  ClothEngine& engine = *scene.engine();
  engine.integrator = ClothEngine::HEUN;
  engine.maxTimeStep = 0.0;  // the dress's growing step is IMPLICIT's
  engine.accelerationLimiter = ClothEngine::CLAMP;
  engine.accelerationLimit = 25.0;
  engine.maxTime = 3.0;
  engine.strainLimit = 0.1;
  const figment::DrapeReport report = figment::reportBeforeDrape(engine);
  EXPECT_EQ(report.method.text(), "heun:0.05:clamp:25");  // the dress writes its timeStep
  EXPECT_DOUBLE_EQ(report.maxTime, 3.0);
  EXPECT_DOUBLE_EQ(report.strainLimit, 0.1);
  EXPECT_EQ(report.body.kind, "mannequin");
  EXPECT_EQ(report.run.iterations, 0);
  engine.body = nullptr;
  EXPECT_EQ(figment::reportBeforeDrape(engine).body.kind, "none");
  EXPECT_FALSE(figment::drapeBodyFromField(engine.body).collider);
}
