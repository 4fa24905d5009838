// Seams being sewn: zero-length springs with dampers, their forces the energy's gradient
// and their blocks its Hessian.
#include <gtest/gtest.h>

#include "sim/cloth/SeamSprings.h"
#include "support/FiniteDifferences.h"

namespace figment {
namespace {

const std::vector<double> kMasses{0.002, 0.004, 0.003};  // kg

TEST(SeamSprings, ForceIsMinusTheEnergysGradientAndBlocksItsHessian) {
  const double rate = 400.0;  // 1/s^2
  const SeamSprings seams({{0, 2}}, kMasses, rate);
  const double k = rate * 0.5 * (0.002 + 0.003);
  const std::vector<Vec3> x{Vec3(0.1, 0.2, 0.3), Vec3(9, 9, 9), Vec3(-0.2, 0.25, 0.1)};
  const std::vector<Vec3> rest(3, Vec3::Zero());
  std::array<Vec3, 2> force, kv;
  std::array<Block3, 4> blocks;
  const SystemWeights weights{1.0, 0.0, 1.0};
  seams.evaluate(0, x, rest, true, true, &weights, {force.data(), kv.data(), blocks.data()});
  // E = k |x_b - x_a|^2 / 2
  const auto energy = [&](const std::vector<Vec3>& y) { return 0.5 * k * (y[2] - y[0]).squaredNorm(); };
  const std::vector<Vec3> gradient = meshes::numericalGradient(energy, x, 1e-6);
  EXPECT_LT((force[0] + gradient[0]).norm(), 1e-8);
  EXPECT_LT((force[1] + gradient[2]).norm(), 1e-8);
  EXPECT_TRUE(blocks[0].isApprox(k * Block3::Identity()));
  EXPECT_TRUE(blocks[1].isApprox(-k * Block3::Identity()));
  EXPECT_NEAR(seams.largestGap(x), (x[2] - x[0]).norm(), 1e-15);
}

TEST(SeamSprings, DamperOpposesTheNodesClosingSpeedCriticallyForThePair) {
  const double rate = 100.0;
  const SeamSprings seams({{0, 1}}, {0.002, 0.002}, rate);
  const std::vector<Vec3> x(2, Vec3::Zero());
  const std::vector<Vec3> v{Vec3(1, 0, 0), Vec3(-1, 0, 0)};  // closing at 2 m/s
  std::array<Vec3, 2> force, kv;
  seams.evaluate(0, x, v, false, true, nullptr, {force.data(), kv.data(), nullptr});
  // c = 2 sqrt(rate) m: the pair of masses m, joined by k = rate m, is critically damped.
  EXPECT_NEAR(force[0].x(), -2.0 * 10.0 * 0.002 * 2.0, 1e-15);
  EXPECT_NEAR(force[1].x(), -force[0].x(), 1e-15);
}

TEST(SeamSprings, RefusesNodesOutOfRangeAndASeamToItself) {
  EXPECT_THROW(SeamSprings({{0, 3}}, kMasses, 1.0), std::invalid_argument);
  EXPECT_THROW(SeamSprings({{1, 1}}, kMasses, 1.0), std::invalid_argument);
  EXPECT_THROW(SeamSprings({{0, 1}}, kMasses, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace figment
