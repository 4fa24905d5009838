// Section forces are the negative gradient of the section's elastic energy, and the
// stresses follow plane-stress Hooke's law for small strains.
#include "support/FiniteDifferences.h"
#include "sim/cloth/MembraneElement.h"

#include <gtest/gtest.h>

using namespace figment;

namespace {
Material cotton() { return Material{0.0005, 300.0, 2.0e6, 0.3}; }
const PlaneStressLaw kCotton(cotton());

std::vector<Vec3> restTriangle() { return {Vec3(0, 0, 0), Vec3(0.03, 0, 0), Vec3(0.01, 0.025, 0.0)}; }
}  // namespace

TEST(MembraneElement, RestShapeHasNoStrainAndNoForce) {
  const auto X = restTriangle();
  MembraneElement section({0, 1, 2}, X[0], X[1], X[2]);
  ASSERT_TRUE(section.valid());
  EXPECT_NEAR(section.restArea(), 0.5 * 0.03 * 0.025, 1e-15);
  EXPECT_LT(section.strain(X).norm(), 1e-14);
  std::vector<Vec3> force(3, Vec3::Zero()), velocity(3, Vec3::Zero());
  section.addForces(X, velocity, kCotton, 0.0, 0.0, force);
  for (const Vec3& f : force) EXPECT_LT(f.norm(), 1e-12);
}

TEST(MembraneElement, ForcesAreMinusTheEnergyGradient) {
  const auto X = restTriangle();
  MembraneElement section({0, 1, 2}, X[0], X[1], X[2]);
  // A distorted, rotated, out-of-plane state: stretch, shear and compression together.
  std::vector<Vec3> x = {Vec3(0.001, -0.002, 0.003), Vec3(0.033, 0.004, -0.002), Vec3(0.008, 0.027, 0.006)};
  std::vector<Vec3> force(3, Vec3::Zero()), velocity(3, Vec3::Zero());
  section.addForces(x, velocity, kCotton, 0.0, 0.0, force);
  const auto gradient =
      meshes::numericalGradient([&](const std::vector<Vec3>& p) { return section.energy(p, kCotton); }, x, 1e-8);
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(force[i][k], -gradient[i][k], 1e-6 * std::max(1.0, std::abs(gradient[i][k])))
          << "corner " << i << " axis " << k;
}

TEST(MembraneElement, UniaxialStrainGivesPlaneStressHooke) {
  const auto X = restTriangle();
  MembraneElement section({0, 1, 2}, X[0], X[1], X[2]);
  const double stretch = 1e-4;  // small: Green strain ~ engineering strain
  std::vector<Vec3> x = X;
  for (Vec3& p : x) p.x() *= 1.0 + stretch;
  const Eigen::Vector3d e = section.strain(x);
  EXPECT_NEAR(e[0], stretch + 0.5 * stretch * stretch, 1e-12);
  EXPECT_NEAR(e[1], 0.0, 1e-12);
  const PlaneStress s = kCotton.stress(e);
  const double k = 2.0e6 / (1 - 0.09);
  EXPECT_NEAR(s.sigmaU, k * e[0], 1e-6);
  EXPECT_NEAR(s.sigmaV, k * 0.3 * e[0], 1e-6);
  EXPECT_NEAR(s.tauUV, 0.0, 1e-6);
}

TEST(MembraneElement, StrainRateDampingOpposesStretchingVelocity) {
  const auto X = restTriangle();
  MembraneElement section({0, 1, 2}, X[0], X[1], X[2]);
  std::vector<Vec3> velocity = {Vec3(-0.1, 0, 0), Vec3(0.1, 0, 0), Vec3(0, 0, 0)};  // corners 0, 1 separate
  std::vector<Vec3> force(3, Vec3::Zero());
  section.addForces(X, velocity, kCotton, 1e-3, 0.0, force);
  EXPECT_GT(force[0].x(), 0.0);
  EXPECT_LT(force[1].x(), 0.0);
  EXPECT_LT((force[0] + force[1] + force[2]).norm(), 1e-12);  // internal: no net force
}

TEST(MembraneElement, StrainClampingCapsTheStressAtTheLimit) {
  // Uniaxial stretch lambda along u: the force along u is proportional to lambda * S_uu.
  // Clamped at strain L, a section stretched beyond it pulls with the stress of strain L:
  // f(lambda, clamped) = (lambda / lambda_L) f(lambda_L), lambda_L = sqrt(1 + 2 L).
  const std::vector<Vec3> X = {Vec3(0, 0, 0), Vec3(0.03, 0, 0), Vec3(0, 0.03, 0)};
  MembraneElement section({0, 1, 2}, X[0], X[1], X[2]);
  const double limit = 0.1, lambdaAtLimit = std::sqrt(1 + 2 * limit), lambda = 1.5;
  auto forceOnCorner1 = [&](double stretch, double strainLimit) {
    std::vector<Vec3> x = X;
    for (Vec3& p : x) p.x() *= stretch;
    std::vector<Vec3> force(3, Vec3::Zero()), velocity(3, Vec3::Zero());
    section.addForces(x, velocity, kCotton, 0.0, strainLimit, force);
    return force[1];
  };
  const Vec3 clamped = forceOnCorner1(lambda, limit);
  const Vec3 atLimit = forceOnCorner1(lambdaAtLimit, 0.0);
  EXPECT_NEAR(clamped.x(), lambda / lambdaAtLimit * atLimit.x(), 1e-9 * std::abs(atLimit.x()));
  EXPECT_LT(std::abs(clamped.x()), std::abs(forceOnCorner1(lambda, 0.0).x()) / 3);
  // Inside the range the clamp changes nothing.
  EXPECT_EQ(forceOnCorner1(1.05, limit), forceOnCorner1(1.05, 0.0));
}
