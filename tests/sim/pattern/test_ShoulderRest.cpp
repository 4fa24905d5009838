// Resting a garment's shoulders on a body it was not made for: a seam that would close
// under the body's top surface raises the garment onto it; seams that close outside the
// body, deep inside it, under more of it or under a sloping surface, seams whose panels
// already lie in the body, and darts leave it where it is.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "sim/pattern/ShoulderRest.h"
#include "support/TestMeshes.h"

namespace figment {
namespace {

using meshes::box;

// A front and a back panel, 0.1 m wide and 0.2 tall, at z = +-0.3, their tops at `top`,
// sewn along their tops: a shoulder seam whose straight closing line runs through z = 0.
SewingPattern shoulderSeam(double top) {
  SewingPattern pattern;
  for (double z : {0.3, -0.3}) {
    Panel p;
    p.vertices = {Vec2(0.05, 0.0), Vec2(0.15, 0.0), Vec2(0.15, 0.2), Vec2(0.05, 0.2)};
    for (int k = 0; k < 4; ++k) p.edges.push_back({k, (k + 1) % 4, {}});
    p.translation = Vec3(0.0, top - 0.2, z);
    pattern.panels.push_back(p);
  }
  pattern.stitches.push_back({{0, 2}, {1, 2}, false});  // the top edges
  return pattern;
}

const TriangleMesh kTorso = box(Vec3(-0.2, 0.0, -0.12), Vec3(0.2, 1.5, 0.12));

TEST(ShoulderRest, CrossingsAboveAPointInsideABoxAreItsTop) {
  const std::vector<Crossing> within = crossingsAbove(kTorso, 0.013, 0.021, 1.0);
  ASSERT_EQ(within.size(), 1u);
  EXPECT_NEAR(within[0].y, 1.5, 1e-12);
  EXPECT_NEAR(within[0].up, 1.0, 1e-12);  // the top faces up
  EXPECT_TRUE(inside(kTorso, Vec3(0.013, 1.0, 0.021)));
  EXPECT_FALSE(inside(kTorso, Vec3(0.013, 1.6, 0.021)));
  // Below the box: its bottom and its top.
  EXPECT_EQ(crossingsAbove(kTorso, 0.013, 0.021, -1.0).size(), 2u);
  // Beside it: none.
  EXPECT_TRUE(crossingsAbove(kTorso, 0.5, 0.0, 1.0).empty());
}

TEST(ShoulderRest, RaisesASeamThatClosesUnderTheTopOntoIt) {
  ShoulderRestOptions options;
  // The seam's line lies 4 cm under the top: it rises 4 cm and the clearance.
  EXPECT_NEAR(shoulderRise(shoulderSeam(1.46), kTorso, options), 0.04 + options.clearance, 1e-9);
  // The control: a seam that closes above the top does not move.
  EXPECT_EQ(shoulderRise(shoulderSeam(1.55), kTorso, options), 0.0);
}

TEST(ShoulderRest, LeavesSeamsDeepInTheBodyAndDartsWhereTheyAre) {
  ShoulderRestOptions options;
  // 30 cm under the top: not under its shoulders but through the body.
  EXPECT_EQ(shoulderRise(shoulderSeam(1.2), kTorso, options), 0.0);
  // Under the top but within one panel: a dart, which moves with its panel.
  SewingPattern dart = shoulderSeam(1.46);
  dart.stitches = {{{0, 0}, {0, 2}, false}};
  EXPECT_EQ(shoulderRise(dart, kTorso, options), 0.0);
}

TEST(ShoulderRest, LeavesASeamWhosePanelsLieInTheBodyWhereItIs) {
  // Both panels inside the torso (a waistband on a belly that stands out past it): the seam
  // does not cross over the top, its panel is in the body already.
  SewingPattern sunk = shoulderSeam(1.46);
  sunk.panels[0].translation.z() = 0.05;
  sunk.panels[1].translation.z() = -0.05;
  EXPECT_EQ(shoulderRise(sunk, kTorso), 0.0);
}

TEST(ShoulderRest, LeavesASeamUnderASlopingTopWhereItIs) {
  // A slab 1 m wide and 0.2 m thick, tilted about z through its middle (0, 1.4, 0): a
  // shoulder's 20 degrees, a hanging arm's 65.
  const auto tilted = [](double degrees) {
    TriangleMesh slab = box(Vec3(-0.5, 1.3, -0.12), Vec3(0.5, 1.5, 0.12));
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(degrees * M_PI / 180.0, Vec3::UnitZ()).toRotationMatrix();
    for (Vec3& v : slab.vertices) v = turn * (v - Vec3(0, 1.4, 0)) + Vec3(0, 1.4, 0);
    return slab;
  };
  // Each seam 5 to 8 cm under the tilted top (the line up leaves through it, not a side).
  EXPECT_GT(shoulderRise(shoulderSeam(1.46), tilted(20.0)), 0.05);
  EXPECT_EQ(shoulderRise(shoulderSeam(1.80), tilted(65.0)), 0.0);
  // The control: the steep top's seam rises when any slope will do.
  ShoulderRestOptions anySlope;
  anySlope.upward = 0.0;
  EXPECT_GT(shoulderRise(shoulderSeam(1.80), tilted(65.0), anySlope), 0.04);
}

TEST(ShoulderRest, LeavesASeamUnderMoreOfTheBodyWhereItIs) {
  // A "waist": the seam lies inside a lower box, under which a second, higher box (a
  // chest) stands apart: the line up crosses three surfaces, so the seam does not rest on
  // a top.
  TriangleMesh body = box(Vec3(-0.2, 0.0, -0.12), Vec3(0.2, 1.0, 0.12));
  const TriangleMesh chest = box(Vec3(-0.2, 1.05, -0.12), Vec3(0.2, 1.5, 0.12));
  const int offset = static_cast<int>(body.vertices.size());
  body.vertices.insert(body.vertices.end(), chest.vertices.begin(), chest.vertices.end());
  for (const Triangle& t : chest.triangles) body.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  EXPECT_EQ(shoulderRise(shoulderSeam(0.96), body), 0.0);
  // The control: without the chest the same seam rests on the lower box's top.
  EXPECT_GT(shoulderRise(shoulderSeam(0.96), box(Vec3(-0.2, 0.0, -0.12), Vec3(0.2, 1.0, 0.12))), 0.04);
}

}  // namespace
}  // namespace figment
