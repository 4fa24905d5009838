// Penalty contacts on a floor (normal +y, surface y = 0) with friction off: a node within the
// clearance gets the spring k (clearance - d) n, linearised as dt^2 k n n^T on its block; a
// node beyond it gets nothing.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "sim/cloth/BlockSparseMatrix.h"
#include "sim/cloth/ClothParameters.h"
#include "sim/cloth/implicit/ContactPenalty.h"
#include "sim/collision/PlaneCollider.h"

using namespace figment;

namespace {

TEST(ContactPenalty, ANodeWithinTheClearanceGetsTheSpringAndOnlyIt) {
  ClothParameters parameters;
  parameters.friction = 0.0;
  const double clearance = parameters.clearance, rate = parameters.implicitSolver.penaltyRate;
  ContactPenalty penalty(std::make_shared<PlaneCollider>(Vec3::Zero(), Vec3::UnitY()), parameters, 2);
  BlockSparseMatrix matrix(std::vector<std::vector<int>>(2));                        // each row its diagonal alone
  for (int i = 0; i < 2; ++i) matrix.block(matrix.find(i, i)) = Block3::Identity();  // the masses
  std::vector<Vec3> rhs(2, Vec3::Zero());
  const std::vector<Vec3> x = {{0, 0.5 * clearance, 0}, {1, 1.0, 0}};  // touching; a metre above
  const std::vector<Vec3> v(2, Vec3::Zero());
  const std::vector<double> masses = {0.002, 0.002};  // kg
  const double dt = 0.05;                             // s
  penalty.add(x, v, masses, dt, true, matrix, rhs);
  const double k = rate * masses[0];
  Block3 expected = Block3::Identity();
  expected(1, 1) += dt * dt * k;
  EXPECT_TRUE(matrix.diagonal(0).isApprox(expected, 1e-12)) << matrix.diagonal(0);
  EXPECT_TRUE(rhs[0].isApprox(Vec3(0, dt * k * 0.5 * clearance, 0), 1e-12)) << rhs[0].transpose();
  EXPECT_EQ(matrix.diagonal(1), Block3::Identity());
  EXPECT_EQ(rhs[1], Vec3::Zero());
}

TEST(ContactPenalty, WithoutABodyNothingIsAdded) {
  ContactPenalty penalty(nullptr, ClothParameters{}, 1);
  BlockSparseMatrix matrix(std::vector<std::vector<int>>(1));
  std::vector<Vec3> rhs = {Vec3(1, 2, 3)};
  penalty.add({Vec3::Zero()}, {Vec3::Zero()}, {1.0}, 0.05, true, matrix, rhs);
  EXPECT_EQ(rhs[0], Vec3(1, 2, 3));
  EXPECT_EQ(matrix.diagonal(0), Block3::Zero());
}

}  // namespace
