// Girths as a tape measures them (sim/body/BodyMeasurements.h): convex perimeters with
// analytic values. The landmarks on a real body are checked on MakeHuman's body
// (tests/io/test_MakeHumanFiles.cpp) and human.zae (tests/io/test_MeasureTool.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/body/BodyMeasurements.h"

using namespace figment;

namespace {

// n points on the ellipse with semi-axes a (x) and b (z) at height y.
std::vector<Vec3> ellipse(int n, double a, double b, double y = 0, const Vec3& shift = Vec3::Zero()) {
  std::vector<Vec3> points;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * i / n;
    points.push_back(shift + Vec3(a * std::cos(t), y, b * std::sin(t)));
  }
  return points;
}

double polygonPerimeter(const std::vector<Vec3>& closed) {
  double sum = 0;
  for (size_t i = 0; i < closed.size(); ++i) sum += (closed[(i + 1) % closed.size()] - closed[i]).norm();
  return sum;
}

}  // namespace

TEST(BodyMeasurements, AConvexSectionMeasuresItsPerimeter) {
  // a regular 64-gon of radius 0.15: 2 n r sin(pi / n), within 0.1 % of the circle's 2 pi r
  const std::vector<Vec3> circle = ellipse(64, 0.15, 0.15, 1.2);
  EXPECT_NEAR(convexPerimeter(circle, Vec3::UnitY()), 2 * 64 * 0.15 * std::sin(std::numbers::pi / 64), 1e-12);
  EXPECT_NEAR(convexPerimeter(circle, Vec3::UnitY()), 2 * std::numbers::pi * 0.15, 2 * std::numbers::pi * 0.15 * 1e-3);
  // an ellipse section: the polygon through its points, which is convex
  const std::vector<Vec3> oval = ellipse(200, 0.16, 0.11);
  EXPECT_NEAR(convexPerimeter(oval, Vec3::UnitY()), polygonPerimeter(oval), 1e-12);
  // Ramanujan's approximation of the ellipse, to the 200-gon's discretisation (< 0.02 %)
  const double a = 0.16, b = 0.11, h = (a - b) * (a - b) / ((a + b) * (a + b));
  const double ramanujan = std::numbers::pi * (a + b) * (1 + 3 * h / (10 + std::sqrt(4 - 3 * h)));
  EXPECT_NEAR(convexPerimeter(oval, Vec3::UnitY()), ramanujan, ramanujan * 2e-4);
}

TEST(BodyMeasurements, TheTapeBridgesAConcaveSection) {
  // two discs apart (the legs, or the breasts' front): the hull of a convex polygon and its
  // copy moved by t is their Minkowski sum with the segment t: perimeter + 2 |t|
  std::vector<Vec3> both = ellipse(48, 0.08, 0.08);
  const std::vector<Vec3> other = ellipse(48, 0.08, 0.08, 0, Vec3(0.2, 0, 0));
  both.insert(both.end(), other.begin(), other.end());
  EXPECT_NEAR(convexPerimeter(both, Vec3::UnitY()), polygonPerimeter(other) + 2 * 0.2, 1e-12);
  // a point in the hollow between them changes nothing
  both.emplace_back(0.1, 0, 0);
  EXPECT_NEAR(convexPerimeter(both, Vec3::UnitY()), polygonPerimeter(other) + 2 * 0.2, 1e-12);
}

TEST(BodyMeasurements, AGirthIsTakenInItsOwnPlane) {
  // the same circle in the plane with normal (1, 1, 0) / sqrt 2, tilted like an arm
  const Vec3 n = Vec3(1, 1, 0).normalized(), u = n.unitOrthogonal(), v = n.cross(u);
  std::vector<Vec3> tilted;
  for (int i = 0; i < 64; ++i) {
    const double t = 2 * std::numbers::pi * i / 64;
    tilted.push_back(Vec3(0.3, 1.1, 0) + 0.05 * (std::cos(t) * u + std::sin(t) * v));
  }
  EXPECT_NEAR(convexPerimeter(tilted, n), 2 * 64 * 0.05 * std::sin(std::numbers::pi / 64), 1e-12);
}

TEST(BodyMeasurements, NamedKeysAreTheIsoNamesInOrder) {
  BodyMeasurements m;
  m.waistGirth = 0.7;
  const auto named = m.named();
  ASSERT_EQ(named.size(), 11u);
  EXPECT_EQ(named[0].first, "stature");
  EXPECT_EQ(named[3].first, "waist_girth");
  EXPECT_DOUBLE_EQ(m.byName("waist_girth"), 0.7);
  EXPECT_THROW(m.byName("waist"), std::invalid_argument);
  EXPECT_THROW(measureBody(TriangleMesh{}), std::invalid_argument);
}
