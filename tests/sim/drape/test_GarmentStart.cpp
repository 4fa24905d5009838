// A garment's start checked against its body: a tube round a column, as worn, in another
// unit, on its side, inside the column, and wound the other way.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "sim/drape/GarmentStart.h"

namespace test_GarmentStart {

namespace {

using figment::Bounds;
using figment::GarmentStart;
using figment::TriangleMesh;
using figment::Vec3;

// A vertical column of radius 0.15 m round the y axis, 1.7 m tall: distance and outward
// normal are analytic.
class Column : public figment::Collider {
 public:
  static constexpr double kRadius = 0.15, kHeight = 1.7;
  bool contact(const Vec3& p, double clearance, double, figment::Contact& out) const override {
    const Vec3 radial(p.x(), 0.0, p.z());
    out.normal = radial.norm() > 0.0 ? Vec3(radial.normalized()) : Vec3(Vec3::UnitX());
    out.distance = radial.norm() - kRadius;
    out.surfacePoint = Vec3(0.0, p.y(), 0.0) + kRadius * out.normal;
    return out.distance <= clearance;
  }
  static Bounds box() {
    Bounds b;
    b.extend(Vec3(-kRadius, 0.0, -kRadius));
    b.extend(Vec3(kRadius, kHeight, kRadius));
    return b;
  }
};

// A tube of `radius` round the y axis from 0.8 to 1.2 m, its faces counterclockwise seen
// from outside (normals outward) unless `clockwise`.
TriangleMesh tube(double radius, bool clockwise = false) {
  constexpr int kAround = 24, kRings = 5;
  TriangleMesh mesh;
  for (int k = 0; k < kRings; ++k)
    for (int i = 0; i < kAround; ++i) {
      const double angle = 2.0 * std::numbers::pi * i / kAround;
      mesh.vertices.emplace_back(radius * std::cos(angle), 0.8 + 0.1 * k, radius * std::sin(angle));
    }
  for (int k = 0; k + 1 < kRings; ++k)
    for (int i = 0; i < kAround; ++i) {
      const int a = k * kAround + i, b = k * kAround + (i + 1) % kAround, c = b + kAround, d = a + kAround;
      // (a, c, b): the edge along the ring crossed with the edge up points outward.
      mesh.triangles.push_back(clockwise ? figment::Triangle{a, b, c} : figment::Triangle{a, c, b});
      mesh.triangles.push_back(clockwise ? figment::Triangle{a, c, d} : figment::Triangle{a, d, c});
    }
  return mesh;
}

TriangleMesh transformed(TriangleMesh mesh, const std::function<Vec3(const Vec3&)>& f) {
  for (Vec3& v : mesh.vertices) v = f(v);
  return mesh;
}

GarmentStart check(const TriangleMesh& garment) {
  const Column column;
  return figment::checkGarmentStart(garment, Column::box(), &column);
}

}  // namespace

TEST(GarmentStart, ATubeWornRoundTheBodyPasses) {
  const TriangleMesh garment = tube(0.2);
  // Control: the first face's normal points away from the column.
  const auto& t = garment.triangles[0];
  const Vec3 n =
      (garment.vertices[t[1]] - garment.vertices[t[0]]).cross(garment.vertices[t[2]] - garment.vertices[t[0]]);
  ASSERT_GT(n.dot(Vec3(garment.vertices[t[0]].x(), 0, garment.vertices[t[0]].z())), 0.0);
  const GarmentStart start = check(garment);
  EXPECT_FALSE(start.tooLarge());
  EXPECT_NEAR(start.sizeRatio(), 0.4 / 1.7, 1e-9);  // the tube's 0.4 m diameter and height
  EXPECT_FALSE(start.up);
  EXPECT_EQ(start.insideShare, 0.0);
  ASSERT_TRUE(start.inwardShare);  // all of it lies 5 cm from the column, within reach
  EXPECT_EQ(*start.inwardShare, 0.0);
  EXPECT_FALSE(start.clockwise());
}

TEST(GarmentStart, FacesWoundClockwiseFaceIntoTheBody) {
  const GarmentStart start = check(tube(0.2, true));
  ASSERT_TRUE(start.inwardShare);
  EXPECT_EQ(*start.inwardShare, 1.0);
  EXPECT_TRUE(start.clockwise());
}

TEST(GarmentStart, AGarmentInAnotherUnitIsTooLargeAndItsUnitIsFound) {
  const GarmentStart cm = check(transformed(tube(0.2), [](const Vec3& v) { return Vec3(100.0 * v); }));
  EXPECT_TRUE(cm.tooLarge());
  EXPECT_EQ(cm.unitFactor, 0.01);
  EXPECT_FALSE(cm.up);  // brought back to metres, it is worn upright
  EXPECT_FALSE(cm.inwardShare);
  // Up to ten times the body is taken for a garment in metres (a sheet over a small ball).
  EXPECT_FALSE(check(transformed(tube(0.2), [](const Vec3& v) { return Vec3(v * (9.9 * 1.7 / 0.4)); })).tooLarge());
  const GarmentStart mm = check(transformed(tube(0.2), [](const Vec3& v) { return Vec3(1000.0 * v); }));
  EXPECT_EQ(mm.unitFactor, 0.001);
}

TEST(GarmentStart, AGarmentOnItsSideIsFoundWithTheDirectionThatIsUp) {
  // A z-up file read as y-up: the file's (x, -z, y) of the worn tube (io/UpAxis.h's toYUp
  // for Z takes it back).
  const GarmentStart zUp = check(transformed(tube(0.2), [](const Vec3& v) { return Vec3(v.x(), -v.z(), v.y()); }));
  ASSERT_TRUE(zUp.up);
  EXPECT_EQ(*zUp.up, Vec3::UnitZ());
  EXPECT_FALSE(zUp.inwardShare);  // not measured on a garment that wears nothing
  // Upside down: -y is up.
  const GarmentStart down = check(transformed(tube(0.2), [](const Vec3& v) { return Vec3(v.x(), -v.y(), -v.z()); }));
  ASSERT_TRUE(down.up);
  EXPECT_EQ(*down.up, -Vec3::UnitY());
}

TEST(GarmentStart, NodesStartingInsideTheBodyAreCounted) {
  EXPECT_EQ(check(tube(0.1)).insideShare, 1.0);
  // The lower two of five rings inside: 2/5 of the nodes.
  const GarmentStart start = check(
      transformed(tube(0.2), [](const Vec3& v) { return v.y() < 0.95 ? Vec3(0.5 * v.x(), v.y(), 0.5 * v.z()) : v; }));
  EXPECT_DOUBLE_EQ(start.insideShare, 0.4);
}

TEST(GarmentStart, WithoutABodyOnlyTheSizeIsChecked) {
  const TriangleMesh fifty = transformed(tube(0.2), [](const Vec3& v) { return Vec3(125.0 * v); });  // 50 m
  const GarmentStart start = figment::checkGarmentStart(fifty, std::nullopt, nullptr);
  EXPECT_EQ(start.bodyExtent, GarmentStart::kTypicalStature);
  EXPECT_TRUE(start.tooLarge());
  EXPECT_FALSE(start.up);
  EXPECT_FALSE(figment::checkGarmentStart(tube(0.2), std::nullopt, nullptr).tooLarge());
}

TEST(GarmentStart, WearingNeedsTheBodysAxisThroughTheGarmentAndHalfItsHeightBeside) {
  const Bounds body = Column::box();
  EXPECT_TRUE(figment::wearsBody(tube(0.2).vertices, body));
  // Beside the body (its axis misses the garment), or above its head.
  EXPECT_FALSE(
      figment::wearsBody(transformed(tube(0.2), [](const Vec3& v) { return Vec3(v + Vec3(1, 0, 0)); }).vertices, body));
  EXPECT_FALSE(
      figment::wearsBody(transformed(tube(0.2), [](const Vec3& v) { return Vec3(v + Vec3(0, 1, 0)); }).vertices, body));
}

}  // namespace test_GarmentStart
