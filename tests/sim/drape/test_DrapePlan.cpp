// A drape in two calls without a scene: the plan keeps the asked method and body, or
// takes the tolerance's from the table; drape() runs it as drapeGarment would and fills
// the report; what cannot be planned names the parameter.
#include <gtest/gtest.h>

#include <stdexcept>

#include "sim/collision/CollisionVolume.h"
#include "sim/collision/MeshCollider.h"
#include "sim/collision/VolumeSetCollider.h"
#include "sim/drape/DrapePlan.h"
#include "support/TestCapsules.h"
#include "support/TestMeshes.h"

namespace test_DrapePlan {

using namespace figment;

namespace {
constexpr double kRadius = 0.15;  // m, the ball

DrapeAsk sheetOnBall() {
  DrapeAsk ask;
  ask.garment = meshes::grid(8, 8, 0.4, 0.4, Vec3(-0.2, kRadius + 0.02, 0.2), Vec3::UnitX(), -Vec3::UnitZ());
  ask.parameters.integrator = Integrator::Implicit;
  ask.parameters.timeStep = 1.0 / 50.0;
  ask.parameters.maxTime = 4.0;
  ask.body.collider = std::make_shared<MeshCollider>(meshes::sphere(kRadius, 32, 16));
  ask.body.description = {"mesh", {{"triangles", 1024}}};
  return ask;
}

std::string invalidArgument(DrapeAsk ask) {
  try {
    planDrape(std::move(ask));
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(DrapePlan, WithoutAToleranceThePlanIsWhatWasAskedAndDrapesAsDrapeGarment) {
  const DrapeAsk ask = sheetOnBall();
  const DrapePlan plan = planDrape(ask);
  EXPECT_EQ(plan.request.body, ask.body.collider);
  EXPECT_EQ(plan.report.method, DrapeMethod::of(ask.parameters));
  EXPECT_EQ(plan.report.body.kind, "mesh");
  EXPECT_EQ(plan.report.triangles, static_cast<int>(ask.garment.triangles.size()));
  EXPECT_EQ(plan.report.picked, "");
  int observed = 0;
  const GarmentDrape planned = drape(plan, DrapeObservers{.step = [&observed](const ClothSolver&) { ++observed; }});
  const GarmentDrape direct = drapeGarment(plan.request);
  ASSERT_TRUE(planned.report.run.atRest);
  EXPECT_EQ(planned.positions, direct.positions);  // bit for bit
  EXPECT_EQ(planned.report.run.iterations, direct.report.run.iterations);
  EXPECT_EQ(observed, planned.report.run.iterations + 1);
  EXPECT_EQ(planned.report.body.kind, "mesh");  // the plan's part of the report stays
  EXPECT_EQ(planned.report.sections, planned.report.triangles);
  EXPECT_DOUBLE_EQ(planned.report.maxTime, 4.0);
}

TEST(DrapePlan, AToleranceTakesTheTablesMethodAndProgressiveSchedule) {
  DrapeAsk ask = sheetOnBall();
  ask.body.jointed = true;
  ask.body.description = {"mannequin", {{"radial_volumes", 14}}};
  const MethodTable table{"t.csv", {{"implicit+penalty:0.04", "volumes", "0:3000", 1.0, 3, 0.4, 1.0}}};
  ask.tolerance = 0.5;
  ask.table = &table;
  const DrapePlan plan = planDrape(ask);
  EXPECT_DOUBLE_EQ(plan.request.parameters.timeStep, 0.04);
  EXPECT_EQ(plan.request.parameters.implicitSolver.contacts, ContactModel::Penalty);
  ASSERT_TRUE(plan.request.progressive);
  EXPECT_GT(plan.request.progressive->levels(), 0);
  EXPECT_EQ(plan.request.schedule.beginLevel, 0);
  EXPECT_DOUBLE_EQ(plan.request.schedule.splitsPerSecond, 3000.0);
  EXPECT_EQ(plan.report.picked, "implicit+penalty:0.04, volumes, progressive 0:3000");
  EXPECT_DOUBLE_EQ(plan.report.pickedDeviation, 0.4);
  EXPECT_EQ(plan.report.pickedBody, "volumes");
  EXPECT_EQ(plan.report.method.text(), "implicit+penalty:0.04");
  const GarmentDrape out = drape(plan);
  EXPECT_GT(out.report.levels, 0);
  EXPECT_EQ(out.report.picked, plan.report.picked);
}

TEST(DrapePlan, WhatCannotBePlannedNamesTheParameter) {
  DrapeAsk negative = sheetOnBall();
  negative.tolerance = -0.1;
  EXPECT_NE(invalidArgument(negative).find("tolerance"), std::string::npos);
  DrapeAsk noTable = sheetOnBall();
  noTable.tolerance = 0.5;
  EXPECT_EQ(invalidArgument(noTable), "tolerance: no tradeoff table to choose from");
  DrapeAsk sewn = sheetOnBall();
  sewn.tolerance = 0.5;
  sewn.sewing = DrapeSewing{};
  EXPECT_EQ(invalidArgument(sewn), "tolerance: a sewn garment drapes by the engine's own fields (tolerance 0)");
}

TEST(DrapePlan, MixAsksForThePartsTheGarmentStartsNear) {
  // Two parts: 7 under the sheet, 9 a metre away; the mix asks part 7 alone by its triangles.
  DrapeAsk ask = sheetOnBall();
  const auto capsule = [](const Vec3& a, const Vec3& b) { return makeVolume(test::segmentCapsule(a, b, 0.05)); };
  ask.body.collider = std::make_shared<VolumeSetCollider>(std::vector<PosedCollisionVolume>{
      {7, capsule(Vec3(-0.2, 0.12, 0.0), Vec3(0.2, 0.12, 0.0)), Eigen::Affine3d::Identity()},
      {9, capsule(Vec3(-0.2, 0.1, 1.0), Vec3(0.2, 0.1, 1.0)), Eigen::Affine3d::Identity()}});
  ask.body.jointed = true;
  ask.body.description = {"mannequin", {{"radial_volumes", 2}}};
  ask.body.triangles = [] { return std::make_shared<MeshCollider>(meshes::sphere(kRadius, 16, 8)); };
  std::vector<int> asked{-1};
  const auto mixed = std::make_shared<MeshCollider>(meshes::sphere(kRadius, 12, 6));
  ask.body.withExactParts = [&](const std::vector<int>& parts) {
    asked = parts;
    return mixed;
  };
  const MethodTable table{"t.csv", {{"implicit:0.05", "mix", "off", 1.0, 3, 0.4, 1.0}}};
  ask.tolerance = 0.5;
  ask.table = &table;
  const DrapePlan plan = planDrape(ask);
  EXPECT_EQ(asked, std::vector<int>{7});
  EXPECT_EQ(plan.request.body, mixed);
  EXPECT_EQ(plan.request.garment.vertices, ask.garment.vertices);  // the garment as asked
}

TEST(DrapePlan, SewnPanelsOverALayerAreMovedOutOverItBeforeTheSewing) {
  // Two panels placed round a ball 2 cm into a layer (a sphere 3 cm larger) that lies over it:
  // a sewn garment's start is its placed panels, so the plan moves them, not a start.
  const double layer = kRadius + 0.03;
  auto beneath = std::make_shared<MeshCollider>(meshes::sphere(layer, 32, 16));
  DrapeAsk ask;
  ask.garment = meshes::grid(4, 4, 0.1, 0.1, Vec3(-0.05, 0.05, layer - 0.02), Vec3::UnitX(), -Vec3::UnitY());
  const size_t half = ask.garment.vertices.size();
  TriangleMesh back = ask.garment;
  for (Vec3& v : back.vertices) v.z() = -v.z();
  for (Vec3& v : back.vertices) ask.garment.vertices.push_back(v);
  for (Triangle t : back.triangles)
    ask.garment.triangles.push_back({t[0] + int(half), t[2] + int(half), t[1] + int(half)});
  ask.parameters.integrator = Integrator::Implicit;
  ask.parameters.clearance = 0.003;
  ask.body.collider = beneath;
  ask.body.beneath = beneath;
  DrapeSewing sewing;
  for (const Vec3& v : ask.garment.vertices) sewing.flat.emplace_back(v.x(), v.y());
  sewing.seams = {{0, int(half)}};
  ask.sewing = sewing;
  const TriangleMesh placed = ask.garment;
  const DrapePlan plan = planDrape(ask);
  EXPECT_GT(plan.report.startedOverLayers, 0);
  EXPECT_FALSE(plan.request.start.has_value());  // the panels themselves start over the layer
  // At the clearance over the layer's facets, which lie up to 1.5 mm inside the sphere.
  for (size_t i = 0; i < placed.vertices.size(); ++i)
    EXPECT_GE(plan.request.garment.vertices[i].norm(), layer + 0.003 - 2e-3) << i;
  EXPECT_EQ(plan.request.garment.triangles, placed.triangles);
  // The control: without the layer beneath, the panels start where they were placed.
  ask.body.beneath = nullptr;
  EXPECT_EQ(planDrape(ask).request.garment.vertices, placed.vertices);
}

}  // namespace test_DrapePlan
