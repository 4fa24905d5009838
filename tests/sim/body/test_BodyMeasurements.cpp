// Girths as a tape measures them (sim/body/BodyMeasurements.h): convex perimeters with
// analytic values; the underbust on a mannequin of tubes whose chest front is a formula: the
// fold under the breasts wherever the belly recedes, 3.5 cm under a flat chest's bust, and
// continuous between. The landmarks on a real body are checked on MakeHuman's body
// (tests/io/test_MakeHumanFiles.cpp, tests/io/scenarios/test_MeasuredBodies.cpp) and
// human.zae (tests/io/test_MeasureTool.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "sim/body/BodyMeasurements.h"

namespace test_BodyMeasurements {

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

// An open tube of rings of 48 points from `low` to `high` every 2.5 mm; the ring at height y
// the ellipse of half-width halfWidth(y) (x) about x = `x`, from z = back(y) to z = front(y).
struct Ring {
  std::function<double(double)> halfWidth, back, front;
};
void addTube(TriangleMesh& mesh, double x, double low, double high, const Ring& ring) {
  constexpr int kAround = 48;
  const int rings = static_cast<int>(std::lround((high - low) / 0.0025)) + 1;
  const int first = static_cast<int>(mesh.vertices.size());
  for (int r = 0; r < rings; ++r) {
    const double y = low + (high - low) * r / (rings - 1);
    const double a = ring.halfWidth(y), mid = 0.5 * (ring.front(y) + ring.back(y));
    const double depth = 0.5 * (ring.front(y) - ring.back(y));
    for (int i = 0; i < kAround; ++i) {
      const double t = 2 * std::numbers::pi * i / kAround;
      mesh.vertices.emplace_back(x + a * std::cos(t), y, mid + depth * std::sin(t));
    }
  }
  for (int r = 0; r + 1 < rings; ++r)
    for (int i = 0; i < kAround; ++i) {
      const int a = first + r * kAround + i, b = first + r * kAround + (i + 1) % kAround;
      mesh.triangles.push_back({a, a + kAround, b});
      mesh.triangles.push_back({b, a + kAround, b + kAround});
    }
}

double bump(double y, double at, double width) {
  return std::exp(-(y - at) * (y - at) / (width * width));
}

// A 1.7 m mannequin: legs to 0.8 m, arms hanging apart from 0.75 m to the armpits at 1.3 m,
// a torso to the top of the head, fullest at the bust (1.2 m), narrowest at the waist
// (1.0 m). Its front: a flat chest wall at z = 8 cm with breasts `breasts` m proud at the
// bust, the ribcage `ribs` m proud at 1.12 m, and the belly receding `belly` m from 1.10 m
// down to 1.0 m (coming forward where negative): the fold under the breasts lies near 1.16 m.
double chestFront(double y, double breasts, double belly, double ribs) {
  const double wall = 0.08 - belly * std::clamp((1.10 - y) / 0.1, 0.0, 1.0);
  return wall + breasts * bump(y, 1.2, 0.02) + ribs * bump(y, 1.12, 0.025);
}
TriangleMesh mannequin(double breasts, double belly, double ribs = 0.008) {
  const auto chest = [=](double y) { return chestFront(y, breasts, belly, ribs); };
  const Ring torso{[](double y) { return 0.14 + 0.02 * bump(y, 1.2, 0.06) - 0.03 * bump(y, 1.0, 0.06); },
                   [](double) { return -0.09; }, chest};
  const Ring limb{[](double) { return 0.05; }, [](double) { return -0.05; }, [](double) { return 0.05; }};
  TriangleMesh mesh;
  addTube(mesh, 0, 0.8, 1.7, torso);
  for (const double side : {-1.0, 1.0}) {
    addTube(mesh, side * 0.08, 0.0, 0.8, limb);
    addTube(mesh, side * 0.26, 0.75, 1.3, limb);
  }
  return mesh;
}

BodyLandmarks underbustOf(const TriangleMesh& body) {
  return measureBody(body, {"underbust_girth"}).landmarks;
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

// The fold under the breasts: the front's lowest level between the breasts and the ribcage
// under them, even where the belly below the ribs recedes further (the lowest front of the
// whole window, where the underbust was taken before: 8 cm under the fold on the smallest
// women's bodies of issue 31's grid), and where the ribcage comes forward only 1 mm under it
// (as on human.zae).
TEST(BodyMeasurements, TheUnderbustIsTheFoldUnderTheBreasts) {
  for (const double ribs : {0.008, 0.001})
    for (const double belly : {0.0, 0.01, 0.02}) {
      const BodyLandmarks l = underbustOf(mannequin(0.02, belly, ribs));
      EXPECT_NEAR(l.bust, 1.2, 0.005) << belly;
      EXPECT_NEAR(l.waist, 1.0, 0.005) << belly;
      // the analytic fold: the chest's lowest front between the bust and the ribcage
      double fold = 1.2, lowest = 1.0;
      for (double y = 1.12; y <= 1.2; y += 1e-4)
        if (const double front = chestFront(y, 0.02, belly, ribs); front < lowest) lowest = front, fold = y;
      EXPECT_NEAR(l.underbust, fold, 0.003) << "ribs " << ribs << ", belly " << belly;
    }
}

// No breasts: 3.5 cm under the bust (where the women's folds lie), between the bust and the
// waist, not at the flat front's lowest point.
TEST(BodyMeasurements, AFlatChestsUnderbustIsUnderTheBust) {
  for (const double belly : {0.0, 0.02}) {
    const BodyLandmarks l = underbustOf(mannequin(0.0, belly));
    EXPECT_NEAR(l.bust - l.underbust, 0.035, 0.002) << belly;
    EXPECT_GT(l.underbust, l.waist + 0.5 * (l.bust - l.waist)) << belly;
  }
}

// As the breasts grow from none, or the belly recedes under breasts, the underbust moves
// continuously: never more than 1 cm between bodies 2 mm apart (before, it fell 8 cm to the
// window's foot as soon as the belly there receded past the fold's front).
TEST(BodyMeasurements, TheUnderbustMovesContinuouslyWithTheBody) {
  double previous = underbustOf(mannequin(0.0, 0.015)).underbust;
  for (int mm = 2; mm <= 20; mm += 2) {
    const double now = underbustOf(mannequin(0.001 * mm, 0.015)).underbust;
    EXPECT_NEAR(now, previous, 0.01) << "breasts " << mm << " mm";
    previous = now;
  }
  previous = underbustOf(mannequin(0.02, -0.01)).underbust;
  for (int mm = -8; mm <= 20; mm += 2) {
    const double now = underbustOf(mannequin(0.02, 0.001 * mm)).underbust;
    EXPECT_NEAR(now, previous, 0.01) << "belly " << mm << " mm";
    previous = now;
  }
}

}  // namespace test_BodyMeasurements
