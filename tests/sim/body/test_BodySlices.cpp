// Body sections on box and prism bodies, where sections, hulls and reaches are known exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "sim/body/BodySlices.h"
#include "sim/core/TriangleMesh.h"
#include "support/BoxFigure.h"

using namespace figment;

namespace {

// A closed prism with a regular n-gon cross section of circumradius r around the y axis,
// vertex k at angle 2 pi k / n in (x, z), counter-clockwise seen from outside.
TriangleMesh prism(int n, double r, double height) {
  TriangleMesh mesh;
  for (int level = 0; level < 2; ++level)
    for (int k = 0; k < n; ++k) {
      const double a = 2 * M_PI * k / n;
      mesh.vertices.emplace_back(r * std::cos(a), level * height, r * std::sin(a));
    }
  const int bottom = 2 * n, top = 2 * n + 1;
  mesh.vertices.emplace_back(0, 0, 0);
  mesh.vertices.emplace_back(0, height, 0);
  for (int k = 0; k < n; ++k) {
    const int a = k, b = (k + 1) % n;
    mesh.triangles.push_back({a, n + a, b});
    mesh.triangles.push_back({b, n + a, n + b});
    mesh.triangles.push_back({bottom, a, b});
    mesh.triangles.push_back({top, n + b, n + a});
  }
  return mesh;
}

}  // namespace

TEST(BodySlices, PlaneSectionOfABoxIsItsRectangle) {
  const TriangleMesh box = mannequin::boxMesh({Vec3(-0.2, 0, -0.1), Vec3(0.2, 1, 0.1)});
  const auto segments = planeSection(box, SectionAxis::Y, 0.5);
  EXPECT_EQ(segments.size(), 8u);  // two triangles on each of the four sides
  for (const Segment2& s : segments)
    for (const Vec2& p : {s.a, s.b}) {
      const bool onSide = std::abs(std::abs(p.x()) - 0.2) < 1e-12 || std::abs(std::abs(p.y()) - 0.1) < 1e-12;
      EXPECT_TRUE(onSide) << p.transpose();
      EXPECT_LE(std::abs(p.x()), 0.2 + 1e-12);
      EXPECT_LE(std::abs(p.y()), 0.1 + 1e-12);
    }
}

// In-plane coordinates: (z, y) for a cut across x.
TEST(BodySlices, SagittalSectionUsesZAndY) {
  const TriangleMesh box = mannequin::boxMesh({Vec3(-0.2, 1, -0.1), Vec3(0.2, 2, 0.3)});
  for (const Segment2& s : planeSection(box, SectionAxis::X, 0.0))
    for (const Vec2& p : {s.a, s.b}) {
      EXPECT_GE(p.x(), -0.1 - 1e-12);
      EXPECT_LE(p.x(), 0.3 + 1e-12);
      EXPECT_GE(p.y(), 1 - 1e-12);
      EXPECT_LE(p.y(), 2 + 1e-12);
    }
}

// Runs along x: a gap wider than 4 cm between segments splits, a long segment bridges.
TEST(BodySlices, ClusterByXSplitsAtGaps) {
  const auto clusters = clusterByX({{Vec2(0.5, 0), Vec2(0.6, 0)},
                                    {Vec2(0.03, 1), Vec2(0, 0)},
                                    {Vec2(0.1, 0), Vec2(0.3, 1)},
                                    {Vec2(0.33, 0), Vec2(0.35, 1)}},
                                   0.04);
  ASSERT_EQ(clusters.size(), 3u);
  EXPECT_EQ(clusters[0].points.size(), 2u);
  EXPECT_DOUBLE_EQ(clusters[0].maxX, 0.03);
  EXPECT_DOUBLE_EQ(clusters[1].minX, 0.1);
  EXPECT_DOUBLE_EQ(clusters[1].maxX, 0.35);
  EXPECT_EQ(clusters[1].points.size(), 4u);
  EXPECT_DOUBLE_EQ(clusters[2].minX, 0.5);
}

// The hull of an n-gon prism's section is the n-gon: the ray towards a corner leaves it at r,
// towards the middle of a side at r cos(pi / n); with a clearance c both reach c further (a
// corner's offset is a circular arc around it, a side's a parallel line).
TEST(BodySlices, ReachOnAPrismIsAnalytic) {
  const int n = 12;
  const double r = 0.15, c = 0.01;
  const TorsoSlice slice = sliceTorso(prism(n, r, 1.0), 0.5);
  ASSERT_EQ(slice.hull.size(), static_cast<size_t>(n));
  const Vec2 centre = Vec2::Zero();
  const double corner = 2 * M_PI * 3 / n, side = 2 * M_PI * 3.5 / n;
  const Vec2 towardsCorner(std::cos(corner), std::sin(corner)), towardsSide(std::cos(side), std::sin(side));
  EXPECT_NEAR(slice.reach(centre, towardsCorner), r, 1e-12);
  EXPECT_NEAR(slice.reach(centre, towardsSide), r * std::cos(M_PI / n), 1e-12);
  EXPECT_NEAR(slice.reach(centre, towardsCorner, c), r + c, 1e-8);
  EXPECT_NEAR(slice.reach(centre, towardsSide, c), r * std::cos(M_PI / n) + c, 1e-8);
  EXPECT_NEAR(slice.centroid().norm(), 0.0, 1e-12);
}

// Off-centre: from a point inside a rectangle, a ray along +x reaches its right side plus c.
TEST(BodySlices, ReachOnABoxFromAnyInnerPoint) {
  const TorsoSlice slice = sliceTorso(mannequin::boxMesh({Vec3(-0.2, 0, -0.1), Vec3(0.2, 1, 0.1)}), 0.3);
  const Vec2 origin(0.05, -0.02);
  ASSERT_TRUE(slice.contains(origin));
  EXPECT_FALSE(slice.contains(Vec2(0.25, 0)));
  EXPECT_NEAR(slice.reach(origin, Vec2(1, 0), 0.01), 0.15 + 0.01, 1e-8);
  const Vec2 diagonal = (Vec2(0.2, 0.1) - origin).normalized();  // through a corner
  EXPECT_NEAR(slice.reach(origin, diagonal, 0.01), (Vec2(0.2, 0.1) - origin).norm() + 0.01, 1e-8);
  EXPECT_DOUBLE_EQ(slice.minX(), -0.2);
  EXPECT_DOUBLE_EQ(slice.maxX(), 0.2);
}

// Arms 8 cm beside the torso are left out; two legs 4 cm apart are spanned by one hull.
TEST(BodySlices, TorsoSliceLeavesOutArmsAndSpansLegs) {
  const TriangleMesh figure = mannequin::figure();
  const TorsoSlice chest = sliceTorso(figure, 1.1);
  EXPECT_NEAR(chest.minX(), -0.16, 1e-12);
  EXPECT_NEAR(chest.maxX(), 0.16, 1e-12);
  const TorsoSlice knees = sliceTorso(figure, 0.5);
  EXPECT_NEAR(knees.minX(), -0.14, 1e-12);
  EXPECT_NEAR(knees.maxX(), 0.14, 1e-12);
  EXPECT_TRUE(knees.contains(Vec2(0, 0.06)));  // between the legs, inside the hull
}

TEST(BodySlices, ArmpitsWhereTheArmsJoinAndNeckBelowTheHead) {
  const TriangleMesh figure = mannequin::figure();
  const double armpit = armpitHeight(figure);
  EXPECT_NEAR(armpit, 1.3, 0.002);
  const double neck = neckHeight(figure, armpit);
  EXPECT_GE(neck, 1.45);
  EXPECT_LT(neck, 1.55);
}

TEST(BodySlices, ArmlessBodyHasNoArmpits) {
  EXPECT_THROW(armpitHeight(mannequin::boxMesh({Vec3(-0.2, 0, -0.1), Vec3(0.2, 1.7, 0.1)})), std::invalid_argument);
}
