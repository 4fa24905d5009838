// Principal axes of a literal point set whose spread is known: the mean, and the axes in
// order of increasing spread.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "sim/core/PrincipalAxes.h"

using namespace figment;

namespace {

TEST(PrincipalAxes, MeanAndAxesOfAFlatCrossOrderedBySpread) {
  // A cross in the z = 1 plane about (1, 2, 1): arms of +-3 along x, +-1 along y, none in z.
  const std::vector<Vec3> points = {{4, 2, 1}, {-2, 2, 1}, {1, 3, 1}, {1, 1, 1}};
  const PrincipalAxes axes = principalAxes(points);
  EXPECT_TRUE(axes.mean.isApprox(Vec3(1, 2, 1), 1e-12));
  // Columns by increasing spread: z (none), then y, then x; each unit, up to sign.
  EXPECT_NEAR(std::abs(axes.axes.col(0).dot(Vec3::UnitZ())), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(axes.axes.col(1).dot(Vec3::UnitY())), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(axes.axes.col(2).dot(Vec3::UnitX())), 1.0, 1e-12);
}

TEST(PrincipalAxes, AxesAreOrthonormal) {
  const std::vector<Vec3> points = {{0, 0, 0}, {1, 2, 0}, {3, 1, 1}, {2, 5, 2}, {-1, 0, 4}};
  const Eigen::Matrix3d axes = principalAxes(points).axes;
  EXPECT_TRUE((axes.transpose() * axes).isApprox(Eigen::Matrix3d::Identity(), 1e-12));
}

TEST(PrincipalAxes, RefusesNoPoints) {
  EXPECT_THROW(principalAxes({}), std::invalid_argument);
}

}  // namespace
