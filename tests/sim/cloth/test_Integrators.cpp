// The three integrators converge at their orders, and the acceleration limiters cap
// each node's net acceleration as the paper's Fig. 2.3 draws them.
#include "support/TestMeshes.h"
#include "sim/cloth/ClothSolver.h"

#include <gtest/gtest.h>

#include <cmath>

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

TEST(AccelerationLimiter, ClampAndTanhCapTheNetAcceleration) {
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

TEST(AccelerationLimiter, TheRunReportsHowOftenEachMeasureEngaged) {
  // A sheet falling freely: every acceleration is g. Capped at 0.5 g, all are cut; at
  // 20 g, none. A soft strip (E = 2 kPa) hanging from its top stretches far beyond 1 %:
  // strain clamping at 1 % engages, and at 50 % it never does.
  const TriangleMesh sheet = meshes::grid(2, 2, 0.1, 0.1);
  ClothParameters p;
  p.maxTime = 0.01;
  p.accelerationLimiter = AccelerationLimiter::Clamp;
  for (const auto& [limit, share] : {std::pair{0.5, 1.0}, std::pair{20.0, 0.0}}) {
    p.accelerationLimit = limit;
    ClothSolver solver(sheet, p, nullptr);
    EXPECT_DOUBLE_EQ(solver.run().limitedNodeShare, share) << "limit " << limit << " g";
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
