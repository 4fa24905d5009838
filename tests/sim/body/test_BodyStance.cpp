// How a body stands, on a box figure whose feet, head and stature are known: upright along +y,
// along another axis when turned, no direction when it has no two feet, and its stature in
// whatever unit it is written in.
#include <gtest/gtest.h>

#include <stdexcept>

#include "sim/body/BodyStance.h"
#include "support/BoxFigure.h"

using namespace figment;

namespace {

TriangleMesh transformed(TriangleMesh mesh, const Eigen::Matrix3d& m) {
  for (Vec3& v : mesh.vertices) v = m * v;
  return mesh;
}

TEST(BodyStance, TheFigureStandsAlongYAtItsHeight) {
  const BodyStance stance = measureStance(mannequin::stanceFigure());
  ASSERT_TRUE(stance.up.has_value());
  EXPECT_EQ(*stance.up, Vec3::UnitY());
  EXPECT_DOUBLE_EQ(stance.stature, 1.75);
}

TEST(BodyStance, TurnedOntoZItStandsAlongZ) {
  Eigen::Matrix3d yToZ;
  yToZ << 1, 0, 0, 0, 0, -1, 0, 1, 0;  // +90 degrees about x: +y goes to +z
  const BodyStance stance = measureStance(transformed(mannequin::stanceFigure(), yToZ));
  ASSERT_TRUE(stance.up.has_value());
  EXPECT_TRUE(stance.up->isApprox(Vec3::UnitZ())) << stance.up->transpose();
  EXPECT_NEAR(stance.stature, 1.75, 1e-12);
}

TEST(BodyStance, InCentimetresTheStatureIsInCentimetres) {
  const BodyStance stance = measureStance(transformed(mannequin::stanceFigure(), 100 * Eigen::Matrix3d::Identity()));
  ASSERT_TRUE(stance.up.has_value());
  EXPECT_NEAR(stance.stature, 175.0, 1e-9);
  EXPECT_GT(stance.stature, kMaxStature);  // so the tools can tell it is not in metres
}

TEST(BodyStance, ABoxHasNoFeetAndNoDirection) {
  const TriangleMesh box = mannequin::boxMesh({{0, 0, 0}, {0.3, 1.8, 0.3}});
  const BodyStance stance = measureStance(box);
  EXPECT_FALSE(stance.up.has_value());
  EXPECT_DOUBLE_EQ(stance.stature, 1.8);  // along y when there is no direction
  EXPECT_THROW(measureStance(TriangleMesh{}), std::invalid_argument);
}

}  // namespace
