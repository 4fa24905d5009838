// Progressive drapes: splits place their vertices from the deformed neighbourhood (exact
// for any affine deformation), keep the garment's mass, never fold a section over, and
// end near the drape of the full garment.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "sim/collision/CapsuleCollider.h"
#include "sim/collision/MeshCollider.h"
#include "sim/progressive/Decimation.h"
#include "sim/progressive/ProgressiveDrape.h"
#include "sim/progressive/SplitPlacement.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {
constexpr double kRadius = 0.15;  // m, the ball

// A 50 cm sheet of 20 x 20 quads, 2 cm above the ball.
TriangleMesh sheetAboveBall() {
  return meshes::grid(20, 20, 0.5, 0.5, Vec3(-0.25, kRadius + 0.02, 0.25), Vec3::UnitX(), -Vec3::UnitZ());
}

std::shared_ptr<const Collider> ball() {
  return std::make_shared<MeshCollider>(meshes::sphere(kRadius, 48, 24));
}

ClothParameters implicitDrape() {
  ClothParameters p;
  p.integrator = Integrator::Implicit;
  p.timeStep = 1.0 / 50.0;
  p.maxTime = 6.0;
  return p;
}

double meanDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]).norm();
  return sum / a.size();
}
}  // namespace

TEST(SplitPlacement, EverySplitIsExactUnderAnAffineDeformation) {
  // The coarsest level moved by x -> A X + t: each split puts its vertices at A X + t of
  // their rest positions, so the full garment comes back exactly deformed.
  const TriangleMesh sheet = sheetAboveBall();
  const ProgressiveMesh pm = decimate(sheet, DecimationOptions{.targetFaces = 80});
  Eigen::Matrix3d A = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  A.col(0) *= 1.1;  // stretched along the rest x axis too
  const Vec3 t(0.3, -0.2, 0.1);
  MeshLevel level(pm);
  std::vector<Vec3> x(sheet.vertices.size()), v(sheet.vertices.size(), Vec3(0.0, -1.0, 0.0));
  for (size_t i = 0; i < x.size(); ++i) x[i] = A * level.rest(static_cast<int>(i)) + t;
  for (int k = 0; k < pm.levels(); ++k) {
    placeSplit(pm.splits[k], level, x, v);
    level.splitTo(k + 1);
  }
  for (size_t i = 0; i < x.size(); ++i) {
    EXPECT_LT((x[i] - (A * sheet.vertices[i] + t)).norm(), 1e-12) << "vertex " << i;
    EXPECT_LT((v[i] - Vec3(0.0, -1.0, 0.0)).norm(), 1e-12) << "vertex " << i;
  }
}

TEST(ProgressiveDrape, KeepsTheGarmentsMassAtEveryLevel) {
  const TriangleMesh sheet = sheetAboveBall();
  const ProgressiveMesh pm = decimate(sheet, DecimationOptions{.targetFaces = 80});
  const ClothParameters p = implicitDrape();
  const ClothSolver fullSolver(sheet, p, nullptr);
  double full = 0.0;
  for (double m : fullSolver.model().masses()) full += m;
  ProgressiveDrape drape(pm, p, ball(), ProgressiveSchedule{0, -1, 2000.0});
  EXPECT_LT(drape.sections(), 100);
  while (drape.level() < drape.endLevel()) {
    EXPECT_NEAR(drape.mass(), full, 1e-12 * full) << "level " << drape.level();
    drape.step();
  }
  EXPECT_NEAR(drape.mass(), full, 1e-12 * full);
  EXPECT_EQ(drape.sections(), static_cast<int>(sheet.triangles.size()));
}

TEST(ProgressiveDrape, SplitsOnADrapedSheetFoldNoSectionOver) {
  // The coarsest sheet draped on the ball to rest, then every split at once: no section
  // of the full sheet faces against its rest orientation's neighbours (its normal
  // agrees with the mean normal of the sections around its corners).
  const TriangleMesh sheet = sheetAboveBall();
  const ProgressiveMesh pm = decimate(sheet, DecimationOptions{.targetFaces = 80});
  ProgressiveDrape drape(pm, implicitDrape(), ball(), ProgressiveSchedule{0, -1, 0.0});
  while (drape.level() == 0 && drape.solver().time() < 6.0) drape.step();
  ASSERT_EQ(drape.level(), pm.levels()) << "the coarse level never rested";
  const std::vector<Vec3> x = drape.fullPositions();
  std::vector<Vec3> vertexNormal(x.size(), Vec3::Zero());
  auto normal = [&](const Triangle& t) { return Vec3((x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]])); };
  for (const Triangle& t : sheet.triangles)
    for (int c : t) vertexNormal[c] += normal(t);
  for (size_t f = 0; f < sheet.triangles.size(); ++f) {
    const Triangle& t = sheet.triangles[f];
    const Vec3 around = vertexNormal[t[0]] + vertexNormal[t[1]] + vertexNormal[t[2]];
    EXPECT_GT(normal(t).dot(around), 0.0) << "section " << f;
  }
}

TEST(ProgressiveDrape, SplitsOnTheBallPutNoVertexInsideItNorStretchAnEdgeFar) {
  // A coarse section resting on the ball cuts a chord through it (8 cm sections on a
  // 15 cm ball sag about 5 mm below their corners), so a split that placed its vertex in
  // the section would put it under the skin; and where the coarse drape bent across a
  // fold a split can stretch the new sections. Neither survives the split (the ball is
  // faceted: its facets lie up to 0.5 mm inside the sphere).
  const TriangleMesh sheet = sheetAboveBall();
  const ProgressiveMesh pm = decimate(sheet, DecimationOptions{.targetFaces = 80});
  const ClothParameters p = implicitDrape();
  ProgressiveDrape drape(pm, p, ball(), ProgressiveSchedule{0, -1, 0.0});
  while (drape.level() == 0 && drape.solver().time() < 6.0) drape.step();
  ASSERT_EQ(drape.level(), pm.levels()) << "the coarse level never rested";
  const std::vector<Vec3> placed = drape.fullPositions();  // as the split left them
  for (size_t i = 0; i < placed.size(); ++i) EXPECT_GT(placed[i].norm(), kRadius + 0.7 * p.clearance) << "vertex " << i;
  double longest = 0.0;
  for (const Triangle& t : sheet.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      longest = std::max(longest, (placed[a] - placed[b]).norm() / (sheet.vertices[a] - sheet.vertices[b]).norm());
    }
  EXPECT_LT(longest, 1.12);
}

TEST(ProgressiveDrape, EndsNearTheFullGarmentsDrape) {
  // A towel over a bar (a sheet over a horizontal capsule: one rest shape, unlike a
  // sheet on a ball, whose folds may form in more than one way): from 3/4 of its
  // sections, all splits once that level rests. The coarse level's friction on the bar
  // holds some of its shape: from 480 sections it ends 4.0 mm from the full drape (320:
  // 3.2 mm, 160: 4.0 mm), from 120 sections 7.1 mm (80: 5.3 mm; 40 never rests).
  CapsuleParameters bar;
  bar.x = bar.z = 0.1;
  bar.y = 1.0;
  bar.tiltOnto(Vec3::UnitX());
  const auto body = std::make_shared<CapsuleCollider>(bar);
  const TriangleMesh towel = meshes::grid(20, 16, 0.5, 0.4, Vec3(-0.25, 0.07, 0.2), Vec3::UnitX(), -Vec3::UnitZ());
  const ClothParameters p = implicitDrape();
  ClothSolver full(towel, p, body);
  ASSERT_TRUE(full.run().atRest);
  const ProgressiveMesh pm = decimate(towel, DecimationOptions{.targetFaces = 480});
  ProgressiveDrape drape(pm, p, body, ProgressiveSchedule{0, -1, 0.0});
  const DrapeResult result = drape.run();
  ASSERT_TRUE(result.atRest);
  // 5 mm (1.25 % of the towel's 0.4 m) parts a first level that holds the garment's shape
  // (480 sections: 4.0 mm) from one too coarse to (120 sections, the control: 7.1 mm).
  EXPECT_LT(meanDistance(drape.fullPositions(), full.positions()), 0.005);
  const ProgressiveMesh coarse = decimate(towel, DecimationOptions{.targetFaces = 120});
  ProgressiveDrape fromCoarse(coarse, p, body, ProgressiveSchedule{0, -1, 0.0});
  ASSERT_TRUE(fromCoarse.run().atRest);
  EXPECT_GT(meanDistance(fromCoarse.fullPositions(), full.positions()), 0.005);
}

TEST(ProgressiveDrape, RecordsWhenTheFullDetailArrivedAndHowFarItMovedAfter) {
  // A sheet dropped onto the ball: all splits once the coarse level rests. The record
  // holds the simulated time of the last split and how far the full sheet moved from
  // its placed state to its rest; begun at full detail, the arrival is 0 and the move is
  // the whole drape's, from the flat sheet.
  const TriangleMesh sheet = sheetAboveBall();
  const ProgressiveMesh pm = decimate(sheet, DecimationOptions{.targetFaces = 160});
  const ClothParameters p = implicitDrape();
  ProgressiveDrape progressive(pm, p, ball(), ProgressiveSchedule{0, -1, 0.0});
  EXPECT_LT(progressive.endLevelSettling().arrival, 0.0);  // not yet
  double coarseRest = -1.0;
  while (!progressive.atRest() && progressive.solver().time() < p.maxTime) {
    progressive.step();
    if (coarseRest < 0.0 && progressive.level() == pm.levels()) coarseRest = progressive.solver().time();
  }
  ASSERT_TRUE(progressive.atRest());
  const EndLevelSettling settled = progressive.endLevelSettling();
  EXPECT_DOUBLE_EQ(settled.arrival, coarseRest);
  const std::vector<Vec3> rest = progressive.fullPositions();
  EXPECT_GT(settled.maxMove, 0.0);
  EXPECT_LE(settled.meanMove, settled.maxMove);

  ProgressiveDrape whole(pm, p, ball(), ProgressiveSchedule{pm.levels(), -1, 0.0});
  ASSERT_TRUE(whole.run().atRest);
  const EndLevelSettling fromStart = whole.endLevelSettling();
  EXPECT_EQ(fromStart.arrival, 0.0);
  EXPECT_NEAR(fromStart.meanMove, meanDistance(whole.fullPositions(), sheet.vertices), 1e-12);
  EXPECT_GT(fromStart.meanMove, 0.02);  // the sheet fell 2 cm and more onto the ball
}

TEST(ProgressiveDrape, RefusesLevelsOutsideTheMesh) {
  const TriangleMesh sheet = sheetAboveBall();
  const ProgressiveMesh pm = decimate(sheet, DecimationOptions{.targetFaces = 80});
  EXPECT_THROW(ProgressiveDrape(pm, implicitDrape(), nullptr, ProgressiveSchedule{5, 3, 0.0}), std::invalid_argument);
  EXPECT_THROW(ProgressiveDrape(pm, implicitDrape(), nullptr, ProgressiveSchedule{0, pm.levels() + 1, 0.0}),
               std::invalid_argument);
  EXPECT_THROW(ProgressiveDrape(pm, implicitDrape(), nullptr, ProgressiveSchedule{0, -1, -1.0}), std::invalid_argument);
}

TEST(ProgressiveDrape, AnExplicitDrapeStepsLongerOnCoarseLevelsAndTheScenesStepAtFullDetail) {
  // The coarsest sheet's nodes are heavier for their stiffness than the full sheet's:
  // its Heun steps are longer (at most twice the scene's); every split in, they are the
  // scene's again.
  const TriangleMesh sheet = sheetAboveBall();
  const ProgressiveMesh pm = decimate(sheet, DecimationOptions{.targetFaces = 80});
  ClothParameters p;
  p.integrator = Integrator::Heun;
  p.timeStep = 1e-4;
  ProgressiveDrape drape(pm, p, ball(), ProgressiveSchedule{0, -1, 0.0});
  drape.step();
  const double coarseStep = drape.solver().time();
  EXPECT_GT(coarseStep, 1.5 * p.timeStep);
  EXPECT_LE(coarseStep, 2.0 * p.timeStep * (1.0 + 1e-12));
  ProgressiveDrape full(pm, p, ball(), ProgressiveSchedule{pm.levels(), -1, 0.0});
  full.step();
  EXPECT_DOUBLE_EQ(full.solver().time(), p.timeStep);
}
