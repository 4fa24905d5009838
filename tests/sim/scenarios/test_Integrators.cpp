// The three integrators converge at their orders, and the acceleration limiters cap
// each node's net acceleration as the paper's Fig. 2.3 draws them.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/cloth/ClothSolver.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {

// A soft strip pinned at one end, released horizontally: it falls and swings, a smooth
// non-linear motion (elastic, bending, air resistance) with no closed form.
ClothParameters swingingStrip(Integrator integrator, double dt) {
  ClothParameters p;
  p.material.youngsModulus = 5e4;
  p.strainRateDamping = 1e-3;  // resolves the fast stretch modes at every dt below
  p.integrator = integrator;
  p.timeStep = dt;
  p.maxTime = 0.1;  // mid-fall
  p.rest.window = 1.0;
  return p;
}

std::vector<Vec3> positionsAtEnd(Integrator integrator, double dt) {
  const TriangleMesh strip = meshes::grid(12, 2, 0.3, 0.05, Vec3::Zero(), Vec3::UnitX(), -Vec3::UnitZ());
  ClothSolver solver(strip, swingingStrip(integrator, dt), nullptr);
  for (int row = 0; row <= 2; ++row) solver.pin(row * 13);  // the x = 0 edge
  solver.run();
  EXPECT_NEAR(solver.time(), 0.1, 1e-9);
  return solver.positions();
}

double maxDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, (a[i] - b[i]).norm());
  return worst;
}

}  // namespace

class Convergence : public ::testing::TestWithParam<std::tuple<Integrator, double>> {};

TEST_P(Convergence, HalvingTheStepDividesTheErrorByTwoToTheOrder) {
  const auto [integrator, expectedRatio] = GetParam();
  const std::vector<Vec3> reference = positionsAtEnd(Integrator::Heun, 2.5e-6);
  const double coarse = maxDistance(positionsAtEnd(integrator, 1e-4), reference);
  const double fine = maxDistance(positionsAtEnd(integrator, 5e-5), reference);
  ASSERT_GT(coarse, 1e-9) << "the error must be measurable";
  RecordProperty("error_ratio", std::to_string(coarse / fine));
  EXPECT_NEAR(coarse / fine, expectedRatio, 0.1 * expectedRatio)
      << integratorName(integrator) << ": error " << coarse << " m at dt 1e-4, " << fine << " m at dt 5e-5";
}

INSTANTIATE_TEST_SUITE_P(Orders, Convergence,
                         ::testing::Values(std::make_tuple(Integrator::ExplicitEuler, 2.0),
                                           std::make_tuple(Integrator::SymplecticEuler, 2.0),
                                           std::make_tuple(Integrator::Heun, 4.0)));

TEST(AccelerationLimiter, ClampAndTanhCapTheElasticAcceleration) {
  // One stretched section: the elastic acceleration is far above the limit.
  TriangleMesh section;
  section.vertices = {Vec3(0, 0, 0), Vec3(0.05, 0, 0), Vec3(0, 0.05, 0)};
  section.triangles = {{0, 1, 2}};
  std::vector<Vec3> stretched = section.vertices;
  stretched[1].x() = 0.06;
  const std::vector<Vec3> still(3, Vec3::Zero());
  ClothParameters p;
  p.gravity = Vec3::Zero();
  p.accelerationLimit = 2.0;  // 2 x 9.81 m/s^2 (no gravity: g = 9.81 is the unit)
  std::vector<Vec3> free, clamped, smooth;
  ClothModel(section, p).accelerations(stretched, still, 0.0, free);
  p.accelerationLimiter = AccelerationLimiter::Clamp;
  ClothModel(section, p).accelerations(stretched, still, 0.0, clamped);
  p.accelerationLimiter = AccelerationLimiter::Tanh;
  ClothModel(section, p).accelerations(stretched, still, 0.0, smooth);
  const double limit = 2.0 * 9.81;
  for (int i = 0; i < 3; ++i) {
    ASSERT_GT(free[i].norm(), 10 * limit);
    EXPECT_NEAR(clamped[i].norm(), limit, 1e-9);
    EXPECT_NEAR(smooth[i].norm(), limit * std::tanh(free[i].norm() / limit), 1e-9);
    EXPECT_GT(clamped[i].normalized().dot(free[i].normalized()), 1 - 1e-12);  // direction kept
    EXPECT_GT(smooth[i].normalized().dot(free[i].normalized()), 1 - 1e-12);
  }
}

TEST(AccelerationLimiter, SmallAccelerationsPassTheClampUnchanged) {
  ClothParameters p;  // a sheet in free fall: |a| = g, below a limit of 20 g
  p.accelerationLimiter = AccelerationLimiter::Clamp;
  const TriangleMesh sheet = meshes::grid(2, 2, 0.1, 0.1);
  std::vector<Vec3> a;
  ClothModel(sheet, p).accelerations(sheet.vertices, std::vector<Vec3>(sheet.vertices.size(), Vec3::Zero()), 0.0, a);
  for (const Vec3& ai : a) EXPECT_LT((ai - p.gravity).norm(), 1e-9);
}

TEST(AccelerationLimiter, GravityAndDampingPassIt) {
  // The limiter cuts the elastic pull only. A sheet in free fall under a 0.1 g cap falls
  // at g; an unstrained sheet whose nodes move apart (a strain rate, no strain) feels its
  // strain-rate damping in full. (Cutting the damping let Heun amplify the fast membrane
  // modes: the flared skirt shredded, tests/nodes/scenarios/test_SkirtUnderLimiters.cpp.)
  const TriangleMesh sheet = meshes::grid(2, 2, 0.1, 0.1);
  ClothParameters p;
  p.accelerationLimiter = AccelerationLimiter::Clamp;
  p.accelerationLimit = 0.1;
  const std::vector<Vec3> still(sheet.vertices.size(), Vec3::Zero());
  std::vector<Vec3> a;
  ClothModel(sheet, p).accelerations(sheet.vertices, still, 0.0, a);
  for (const Vec3& ai : a) EXPECT_LT((ai - p.gravity).norm(), 1e-9);

  std::vector<Vec3> spreading;
  for (const Vec3& x : sheet.vertices) spreading.push_back(5.0 * x);  // 5 m/s per m: a strain rate of 5/s
  p.gravity = Vec3::Zero();
  p.strainRateDamping = 1e-3;
  std::vector<Vec3> limited, free;
  ClothModel(sheet, p).accelerations(sheet.vertices, spreading, 0.0, limited);
  p.accelerationLimiter = AccelerationLimiter::None;
  ClothModel(sheet, p).accelerations(sheet.vertices, spreading, 0.0, free);
  double largest = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    largest = std::max(largest, free[i].norm());
    EXPECT_LT((limited[i] - free[i]).norm(), 1e-9 * free[i].norm() + 1e-12);
  }
  EXPECT_GT(largest, 10 * 0.1 * 9.81) << "the damping must exceed the cap to show it passes";
}

TEST(AccelerationLimiter, TheRunReportsHowOftenEachMeasureEngaged) {
  // One stretched section: its three elastic accelerations exceed 2 g, none exceeds 1e6 g.
  // A soft strip (E = 2 kPa) hanging from its top stretches far beyond 1 %: strain
  // clamping at 1 % engages, and at 50 % it never does.
  TriangleMesh section;
  section.vertices = {Vec3(0, 0, 0), Vec3(0.05, 0, 0), Vec3(0, 0.05, 0)};
  section.triangles = {{0, 1, 2}};
  std::vector<Vec3> stretched = section.vertices, a;
  stretched[1].x() = 0.06;
  ClothParameters p;
  p.accelerationLimiter = AccelerationLimiter::Clamp;
  for (const auto& [limit, limited] : {std::pair{2.0, 3LL}, std::pair{1e6, 0LL}}) {
    p.accelerationLimit = limit;
    const ClothModel model(section, p);
    model.accelerations(stretched, std::vector<Vec3>(3, Vec3::Zero()), 0.0, a);
    EXPECT_EQ(model.limiterCounts().evaluations, 1);
    EXPECT_EQ(model.limiterCounts().limitedNodes, limited) << "limit " << limit << " g";
  }
  ClothParameters soft;
  soft.material.youngsModulus = 2e3;
  soft.maxTime = 0.2;
  soft.timeStep = 1e-3;
  const TriangleMesh strip = meshes::grid(1, 8, 0.02, 0.2);
  for (const auto& [limit, engaged] : {std::pair{0.01, true}, std::pair{0.5, false}}) {
    soft.strainLimit = limit;
    ClothSolver solver(strip, soft, nullptr);
    solver.pin(0), solver.pin(1);
    const DrapeResult result = solver.run();
    EXPECT_EQ(result.clampedSectionShare > 0.0, engaged) << "limit " << limit;
    EXPECT_LT(result.clampedSectionShare, 1.0);
  }
}

TEST(Integrators, BlowUpNamesTheMethod) {
  ClothParameters p;
  p.material.youngsModulus = 1e9;
  p.strainRateDamping = 0.0;
  p.timeStep = 5e-3;
  p.integrator = Integrator::SymplecticEuler;
  ClothSolver solver(meshes::grid(2, 20, 0.05, 0.5), p, nullptr);
  for (int i = 0; i <= 2; ++i) solver.pin(i);
  try {
    solver.run();
    FAIL() << "no error";
  } catch (const SimulationError& error) {
    EXPECT_NE(std::string(error.what()).find("method symplectic Euler"), std::string::npos) << error.what();
  }
}
