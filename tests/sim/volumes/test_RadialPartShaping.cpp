// The radial part fit: the gap estimate against a cylinder whose answer is known, and a fit
// of a box-shaped part along its bone that spans every vertex of it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sim/body/BodyParts.h"
#include "sim/collision/RadialDepth.h"
#include "sim/volumes/RadialPartShaping.h"
#include "support/BoxFigure.h"

using namespace figment;

namespace {

// A cylinder of radius 0.1 m along +y from the origin, 1 m long.
RadialDepth cylinder() {
  RadialDepthParameters p;
  p.coefficients = {{0.1}, {0.1}};
  return RadialDepth(p);
}

TEST(RadialPartShaping, GapEstimateIsTheMeanShortfallCappedByTheEnds) {
  const std::vector<Vec3> vertices = {
      {0.05, 0.5, 0},  // 5 cm inside the side
      {0.1, 0.5, 0},   // on it
      {0.2, 0.5, 0},   // outside: no gap
      {0, 0.02, 0},    // on the axis, 2 cm from the bottom cap: the cap is nearer than the side
  };
  EXPECT_NEAR(radialGapEstimate(cylinder(), vertices), (0.05 + 0 + 0 + 0.02) / 4, 1e-12);
}

TEST(RadialPartShaping, AVolumeAlongItsBoneSpansThePart) {
  PartMesh part;
  part.name = "shinL";
  part.mesh = mannequin::boxMesh({{-0.05, 0.0, -0.05}, {0.05, 0.4, 0.05}});
  part.from = Vec3(0, 0.4, 0);
  part.to = Vec3(0, 0, 0);
  const RadialDepth fitted = shapeRadialPart(part, 1, 0.05);
  const RadialDepthParameters& p = fitted.parameters();
  EXPECT_GT(std::abs(p.direction.dot(Vec3::UnitY())), 0.9);  // about along the bone
  for (const Vec3& v : part.mesh.vertices) {
    double s, a, rho;
    fitted.toAxis(v, s, a, rho);
    EXPECT_GE(s, -1e-9) << v.transpose();
    EXPECT_LE(s, p.length + 1e-9) << v.transpose();
  }
  EXPECT_EQ(p.harmonics, 1);
}

}  // namespace
