// Placing a pattern made for one body on another: its feet and axis onto the body's,
// heights scaled by the statures, sleeves turned to the body's arm angle.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "sim/pattern/PatternPlacement.h"
#include "sim/pattern/ShoulderRest.h"
#include "support/TestMeshes.h"

namespace figment {
namespace {

// A closed cylinder of radius r from y0 to y0 + height about (cx, cz): a torso standing on
// its feet, without arms.
TriangleMesh column(double r, double height, double y0, double cx, double cz) {
  TriangleMesh mesh;
  constexpr int kSides = 24, kRings = 40;
  for (int j = 0; j <= kRings; ++j)
    for (int k = 0; k < kSides; ++k) {
      const double a = 2 * M_PI * k / kSides;
      mesh.vertices.emplace_back(cx + r * std::cos(a), y0 + height * j / kRings, cz - r * std::sin(a));
    }
  for (int j = 0; j < kRings; ++j)
    for (int k = 0; k < kSides; ++k) {
      const int a = j * kSides + k, b = j * kSides + (k + 1) % kSides;
      mesh.triangles.push_back({a, b, a + kSides});
      mesh.triangles.push_back({b, b + kSides, a + kSides});
    }
  return mesh;
}

Panel panel(double zDegrees, const Vec3& translation) {
  Panel p;
  p.vertices = {Vec2(0, 0), Vec2(0.2, 0), Vec2(0.2, 0.1), Vec2(0, 0.1)};
  p.rotation = Eigen::AngleAxisd(zDegrees * M_PI / 180.0, Vec3::UnitZ()).toRotationMatrix();
  p.translation = translation;
  return p;
}

TEST(PatternPlacement, PutsThePatternsFeetAndAxisOnTheBodys) {
  const TriangleMesh body = column(0.15, 1.70, 0.02, 0.10, 0.05);
  const PatternPlacement placement = placementOn(body, 1.68);
  EXPECT_NEAR(placement.feet, 0.02, 1e-12);
  EXPECT_NEAR(placement.heightScale, 1.70 / 1.68, 1e-9);
  EXPECT_NEAR(placement.axis.x(), 0.10, 2e-3);  // the section's centroid, to the polygon's error
  EXPECT_NEAR(placement.axis.y(), 0.05, 2e-3);
  EXPECT_EQ(placement.armAngle, 0.0);  // no arms
  const Vec3 moved = placement(Vec3(0.3, 1.0, 0.2));
  EXPECT_NEAR(moved.x(), 0.3 + placement.axis.x(), 1e-12);
  EXPECT_NEAR(moved.y(), 0.02 + 1.0 * 1.70 / 1.68, 1e-12);
  EXPECT_NEAR(moved.z(), 0.2 + placement.axis.y(), 1e-12);
}

TEST(PatternPlacement, TurnsSleevesToTheBodysArmAngleAndLeavesTheRest) {
  SewingPattern pattern;
  pattern.panels = {panel(0.0, Vec3(-0.1, 1.0, 0.2)), panel(-45.0, Vec3(0.2, 1.3, 0.1)),
                    panel(45.0, Vec3(-0.2, 1.3, 0.1))};
  PatternPlacement placement;
  placement.armAngle = 53.0;
  const SewingPattern out = placed(pattern, placement);
  const auto zAngle = [](const Panel& p) { return std::atan2(p.rotation(1, 0), p.rotation(0, 0)) * 180.0 / M_PI; };
  EXPECT_NEAR(zAngle(out.panels[0]), 0.0, 1e-12);
  EXPECT_NEAR(zAngle(out.panels[1]), -53.0, 1e-9);  // the left sleeve, lowered
  EXPECT_NEAR(zAngle(out.panels[2]), 53.0, 1e-9);   // the right one, mirrored
  // Turned about its point nearest the body's axis (its corner (0, 0), at x = 0.2): that point
  // stays where it was.
  const Vec3 pivotBefore = pattern.panels[1].rotation * Vec3(0, 0, 0) + pattern.panels[1].translation;
  const Vec3 pivotAfter = out.panels[1].rotation * Vec3(0, 0, 0) + out.panels[1].translation;
  EXPECT_LT((pivotAfter - pivotBefore).norm(), 1e-12);
  // The control: a placement that knows no arm angle turns nothing.
  EXPECT_NEAR(zAngle(placed(pattern, PatternPlacement{}).panels[1]), -45.0, 1e-9);
}

// On a body it knows the surface of, placed() rests the garment's shoulders on the body's
// (ShoulderRest.h) and moves its arm panels clear of the arms (LimbClearance.h).
TEST(PatternPlacement, RestsShouldersOnTheBodyAndMovesSleevesClearOfTheArms) {
  // A torso 1.5 m tall and a "forearm" 15 cm before its shoulder line.
  TriangleMesh body = meshes::box(Vec3(-0.2, 0.0, -0.12), Vec3(0.2, 1.5, 0.12));
  const TriangleMesh arm = meshes::sphere(0.05, 32, 16, Vec3(0.45, 1.245, 0.1));
  const int offset = static_cast<int>(body.vertices.size());
  body.vertices.insert(body.vertices.end(), arm.vertices.begin(), arm.vertices.end());
  for (const Triangle& t : arm.triangles) body.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  // A front and a back panel sewn along their tops 4 cm under the torso's top, and a
  // sleeve panel turned 45 degrees about z through the forearm.
  SewingPattern pattern;
  for (double z : {0.3, -0.3}) {
    Panel p = panel(0.0, Vec3(0.05, 1.36, z));
    for (int k = 0; k < 4; ++k) p.edges.push_back({k, (k + 1) % 4, {}});
    pattern.panels.push_back(p);
  }
  pattern.stitches.push_back({{0, 2}, {1, 2}, false});
  Panel sleeve = panel(-45.0, Vec3(0.25, 1.35, 0.12));
  sleeve.vertices = {Vec2(0, -0.1), Vec2(0.3, -0.1), Vec2(0.3, 0.1), Vec2(0, 0.1)};
  pattern.panels.push_back(sleeve);

  const PatternPlacement placement = placementOn(body, 0.0);
  ASSERT_NE(placement.surface, nullptr);
  PatternPlacement unknown = placement;
  unknown.surface.reset();
  const SewingPattern bare = placed(pattern, unknown), out = placed(pattern, placement);
  const double rise = out.panels[0].translation.y() - bare.panels[0].translation.y();
  EXPECT_NEAR(rise, 0.04 + ShoulderRestOptions{}.clearance, 1e-6);
  EXPECT_NEAR(out.panels[1].translation.y() - bare.panels[1].translation.y(), rise, 1e-12);  // all of it
  // The sleeve rose with the rest and moved forward until the forearm (its front 0.15 m)
  // lies behind it; the torso's panels did not move in z.
  EXPECT_NEAR(out.panels[2].translation.y() - bare.panels[2].translation.y(), rise, 1e-12);
  EXPECT_GT(out.panels[2].translation.z(), 0.15);
  EXPECT_EQ(out.panels[0].translation.z(), bare.panels[0].translation.z());
}

TEST(PatternPlacement, RefusesABodyOfNoHumanStature) {
  EXPECT_THROW(placementOn(column(0.15, 17.0, 0.0, 0.0, 0.0), 0.0), std::invalid_argument);
  EXPECT_THROW(placementOn(column(0.15, 1.7, 0.0, 0.0, 0.0), 170.0), std::invalid_argument);
  EXPECT_THROW(placementOn(TriangleMesh{}, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace figment
