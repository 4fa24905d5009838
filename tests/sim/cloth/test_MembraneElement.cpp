// A section's force is minus the gradient of its elastic energy, its stiffness and
// damping blocks are minus the derivatives of that force (central differences), and the
// projection keeps the stiffness positive semi-definite under compression.
#include <gtest/gtest.h>

#include <array>

#include "sim/cloth/MembraneElement.h"
#include "support/Eigenvalues.h"
#include "support/FiniteDifferences.h"

namespace test_MembraneElement {

using namespace figment;

namespace {
Material cotton() {
  return Material{0.0005, 300.0, 2.0e6, 0.3};
}

std::vector<Vec3> restTriangle() {
  return {Vec3(0, 0, 0), Vec3(0.03, 0, 0), Vec3(0.01, 0.025, 0.0)};
}

MembraneElement restSection() {
  const auto X = restTriangle();
  return MembraneElement({0, 1, 2}, X[0], X[1], X[2]);
}

// The section's forces (corner order) for `request`.
std::vector<Vec3> forces(const MembraneElement& section, const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                         const MembraneRequest& request) {
  std::vector<Vec3> force(3);
  section.evaluate(x, v, PlaneStressLaw(cotton()), request, nullptr, {force.data(), nullptr, nullptr});
  return force;
}

// The section's weighted blocks as one 9 x 9 matrix, and its K v.
struct Derivatives {
  Eigen::MatrixXd blocks = Eigen::MatrixXd::Zero(9, 9);
  std::array<Vec3, 3> stiffnessTimesVelocity;
};
Derivatives derivatives(const MembraneElement& section, const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                        double tau, const SystemWeights& weights) {
  std::array<Vec3, 3> force;
  std::array<Block3, 9> blocks;
  Derivatives d;
  section.evaluate(x, v, PlaneStressLaw(cotton()), {true, tau, 0.0}, &weights,
                   {force.data(), d.stiffnessTimesVelocity.data(), blocks.data()});
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) d.blocks.block<3, 3>(3 * a, 3 * b) = blocks[3 * a + b];
  return d;
}

// A distorted, rotated, out-of-plane state: stretch, shear and compression together.
std::vector<Vec3> distorted() {
  return {Vec3(0.001, -0.002, 0.003), Vec3(0.033, 0.004, -0.002), Vec3(0.008, 0.027, 0.006)};
}
// Stretched by 3 % and 5 % along two axes, then rotated: S positive definite.
std::vector<Vec3> stretchedBothWays() {
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  std::vector<Vec3> x;
  for (const Vec3& p : restTriangle()) x.push_back(rotation * Vec3(1.03 * p.x(), 1.05 * p.y(), p.z()));
  return x;
}
const std::vector<Vec3> kStill(3, Vec3::Zero());
}  // namespace

TEST(MembraneElement, RestShapeHasNoStrainAndNoForce) {
  const MembraneElement section = restSection();
  ASSERT_TRUE(section.valid());
  EXPECT_NEAR(section.restArea(), 0.5 * 0.03 * 0.025, 1e-15);
  EXPECT_LT(section.strain(restTriangle()).norm(), 1e-14);
  for (const Vec3& f : forces(section, restTriangle(), kStill, {})) EXPECT_LT(f.norm(), 1e-12);
}

TEST(MembraneElement, ForcesAreMinusTheEnergyGradient) {
  const MembraneElement section = restSection();
  const std::vector<Vec3> x = distorted();
  const std::vector<Vec3> force = forces(section, x, kStill, {});
  const PlaneStressLaw law(cotton());
  const auto gradient =
      meshes::numericalGradient([&](const std::vector<Vec3>& p) { return section.energy(p, law); }, x, 1e-8);
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(force[i][k], -gradient[i][k], 1e-6 * std::max(1.0, std::abs(gradient[i][k])))
          << "corner " << i << " axis " << k;
}

TEST(MembraneElement, UniaxialStrainGivesPlaneStressHooke) {
  const MembraneElement section = restSection();
  const double stretch = 1e-4;  // small: Green strain ~ engineering strain
  std::vector<Vec3> x = restTriangle();
  for (Vec3& p : x) p.x() *= 1.0 + stretch;
  const Eigen::Vector3d e = section.strain(x);
  EXPECT_NEAR(e[0], stretch + 0.5 * stretch * stretch, 1e-12);
  EXPECT_NEAR(e[1], 0.0, 1e-12);
  const PlaneStress s = PlaneStressLaw(cotton()).stress(e);
  const double k = 2.0e6 / (1 - 0.09);
  EXPECT_NEAR(s.sigmaU, k * e[0], 1e-6);
  EXPECT_NEAR(s.sigmaV, k * 0.3 * e[0], 1e-6);
  EXPECT_NEAR(s.tauUV, 0.0, 1e-6);
}

TEST(MembraneElement, StrainRateDampingOpposesStretchingVelocity) {
  const std::vector<Vec3> velocity = {Vec3(-0.1, 0, 0), Vec3(0.1, 0, 0), Vec3(0, 0, 0)};  // corners 0, 1 separate
  const std::vector<Vec3> force = forces(restSection(), restTriangle(), velocity, {true, 1e-3, 0.0});
  EXPECT_GT(force[0].x(), 0.0);
  EXPECT_LT(force[1].x(), 0.0);
  EXPECT_LT((force[0] + force[1] + force[2]).norm(), 1e-12);  // internal: no net force
  // The damping alone (elastic off) is the same force at the rest shape.
  const std::vector<Vec3> dampingOnly = forces(restSection(), restTriangle(), velocity, {false, 1e-3, 0.0});
  for (int a = 0; a < 3; ++a) EXPECT_LT((dampingOnly[a] - force[a]).norm(), 1e-12 * force[0].norm());
}

TEST(MembraneElement, ElasticAndDampingForcesAddUp) {
  // The stress is linear in e + tau e', so asking for both gives the sum of asking apart.
  const std::vector<Vec3> x = distorted(), v = {Vec3(0.1, 0.2, -0.1), Vec3(-0.3, 0.1, 0.0), Vec3(0.0, 0.2, 0.4)};
  const std::vector<Vec3> both = forces(restSection(), x, v, {true, 2e-3, 0.0});
  const std::vector<Vec3> elastic = forces(restSection(), x, v, {true, 0.0, 0.0});
  const std::vector<Vec3> damping = forces(restSection(), x, v, {false, 2e-3, 0.0});
  for (int a = 0; a < 3; ++a) EXPECT_LT((both[a] - elastic[a] - damping[a]).norm(), 1e-12 * both[a].norm());
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
    return forces(section, x, kStill, {true, 0.0, strainLimit})[1];
  };
  const Vec3 clamped = forceOnCorner1(lambda, limit);
  const Vec3 atLimit = forceOnCorner1(lambdaAtLimit, 0.0);
  EXPECT_NEAR(clamped.x(), lambda / lambdaAtLimit * atLimit.x(), 1e-9 * std::abs(atLimit.x()));
  EXPECT_LT(std::abs(clamped.x()), std::abs(forceOnCorner1(lambda, 0.0).x()) / 3);
  // Inside the range the clamp changes nothing.
  EXPECT_EQ(forceOnCorner1(1.05, limit), forceOnCorner1(1.05, 0.0));
}

TEST(MembraneElement, StiffnessIsMinusTheForceDerivative) {
  // Stretched both ways, the projection leaves K exact: K = -df/dx.
  const MembraneElement section = restSection();
  const std::vector<Vec3> x = stretchedBothWays();
  const Derivatives d = derivatives(section, x, kStill, 0.0, {0.0, 0.0, 1.0});
  const Eigen::MatrixXd numerical =
      meshes::numericalJacobian([&](const std::vector<Vec3>& p) { return forces(section, p, kStill, {}); }, x, 1e-9);
  EXPECT_LT((d.blocks + numerical).norm(), 1e-6 * d.blocks.norm());
  EXPECT_LT((d.blocks - d.blocks.transpose()).norm(), 1e-12 * d.blocks.norm());
}

TEST(MembraneElement, DampingIsMinusTheForceDerivativeInVelocity) {
  // D = -df/dv, and the stiffness weight alone gives K, whose product with v is K v.
  const MembraneElement section = restSection();
  const std::vector<Vec3> x = distorted(), v = {Vec3(0.1, 0.2, -0.1), Vec3(-0.3, 0.1, 0.0), Vec3(0.0, 0.2, 0.4)};
  const double tau = 2e-3;
  const Derivatives damping = derivatives(section, x, v, tau, {0.0, 1.0, 0.0});
  const Eigen::MatrixXd numerical = meshes::numericalJacobian(
      [&](const std::vector<Vec3>& w) {
        return forces(section, x, w, {true, tau, 0.0});
      },
      v, 1e-4);
  EXPECT_LT((damping.blocks + numerical).norm(), 1e-8 * damping.blocks.norm());
  const Derivatives stiffness = derivatives(section, x, v, tau, {0.0, 0.0, 1.0});
  Eigen::VectorXd flat(9);
  for (int a = 0; a < 3; ++a) flat.segment<3>(3 * a) = v[a];
  const Eigen::VectorXd Kv = stiffness.blocks * flat;
  for (int a = 0; a < 3; ++a)
    EXPECT_LT((stiffness.stiffnessTimesVelocity[a] - Kv.segment<3>(3 * a)).norm(), 1e-12 * Kv.norm());
}

TEST(MembraneElement, CompressedSectionKeepsThePositiveSemiDefiniteStiffness) {
  // Squeezed along u and stretched along v, S is indefinite; the projected K is not.
  const MembraneElement section = restSection();
  std::vector<Vec3> x;
  for (const Vec3& p : restTriangle()) x.push_back(Vec3(0.9 * p.x(), 1.04 * p.y(), 0.0));
  const Derivatives d = derivatives(section, x, kStill, 0.0, {0.0, 0.0, 1.0});
  const Eigen::VectorXd eigenvalues = test::symmetricEigenvalues(d.blocks);
  EXPECT_GT(eigenvalues.minCoeff(), -1e-9 * eigenvalues.maxCoeff());
}

TEST(MembraneElement, PositivePartClampsTheNegativeEigenvalue) {
  Eigen::Matrix2d S;
  S << 3.0, 1.0, 1.0, -2.0;
  const Eigen::Matrix2d plus = positivePart(S);
  const Eigen::VectorXd original = test::symmetricEigenvalues(S), clamped = test::symmetricEigenvalues(plus);
  EXPECT_NEAR(clamped[0], 0.0, 1e-12);
  EXPECT_NEAR(clamped[1], original[1], 1e-12);
  EXPECT_EQ(positivePart(Eigen::Matrix2d::Identity()), Eigen::Matrix2d::Identity());
  EXPECT_EQ(positivePart(-Eigen::Matrix2d::Identity()), Eigen::Matrix2d::Zero());
}

}  // namespace test_MembraneElement
