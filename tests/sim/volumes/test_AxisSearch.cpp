// The genetic axis search of the radial depth fit: finds a tube's axis from a nearby
// start, never ends worse than its start, repeats with its seed.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "sim/volumes/AxisSearch.h"

namespace test_AxisSearch {

using namespace figment;

namespace {

// Points on a tube of radius 5 cm around `axis`, 30 cm long.
std::vector<Vec3> tube(const Axis& axis) {
  const Vec3 e1 = axis.direction.cross(Vec3::UnitX()).normalized(), e2 = axis.direction.cross(e1);
  std::vector<Vec3> points;
  for (int i = 0; i <= 30; ++i)
    for (int k = 0; k < 24; ++k) {
      const double a = 2 * std::numbers::pi * k / 24;
      points.push_back(axis.origin + 0.01 * i * axis.direction + 0.05 * (std::cos(a) * e1 + std::sin(a) * e2));
    }
  return points;
}

// The spread of the points' distances from a candidate axis: zero on the tube's own.
double spread(const std::vector<Vec3>& points, const Axis& axis) {
  double sum = 0.0, squares = 0.0;
  for (const Vec3& p : points) {
    const Vec3 d = p - axis.origin;
    const double r = (d - d.dot(axis.direction) * axis.direction).norm();
    sum += r, squares += r * r;
  }
  const double n = static_cast<double>(points.size());
  return std::sqrt(std::max(0.0, squares / n - (sum / n) * (sum / n)));
}

const Axis kTrue{{0.01, 0.0, -0.008}, Vec3(std::sin(0.15), std::cos(0.15), 0.0)};

}  // namespace

TEST(AxisSearch, FindsATubesAxisFromANearbyStart) {
  const std::vector<Vec3> points = tube(kTrue);
  const Axis start{Vec3::Zero(), Vec3::UnitY()};  // 0.15 rad and ~1.3 cm off
  AxisSearchOptions options;
  options.population = 30;
  options.generations = 60;
  const AxisSearchResult found = searchAxis(
      start, [&](const Axis& a) { return spread(points, a); }, options);
  EXPECT_LT(found.cost, 0.1 * spread(points, start));
  EXPECT_LT(std::acos(std::min(1.0, found.axis.direction.dot(kTrue.direction))), 0.03);
  // The found axis passes within 3 mm of the true one at the tube's middle.
  const Vec3 middle = kTrue.origin + 0.15 * kTrue.direction;
  const Vec3 d = middle - found.axis.origin;
  EXPECT_LT((d - d.dot(found.axis.direction) * found.axis.direction).norm(), 0.003);
  EXPECT_EQ(found.evaluations, 30 + 60 * (9 + 9));
}

TEST(AxisSearch, NeverEndsWorseThanItsStartAndRepeatsWithItsSeed) {
  const std::vector<Vec3> points = tube(kTrue);
  auto cost = [&](const Axis& a) { return spread(points, a); };
  AxisSearchOptions options;
  options.generations = 0;
  EXPECT_DOUBLE_EQ(searchAxis(kTrue, cost, options).cost, spread(points, kTrue)) << "the start is a member";
  options.generations = 6;
  const AxisSearchResult a = searchAxis(kTrue, cost, options), b = searchAxis(kTrue, cost, options);
  EXPECT_LE(a.cost, spread(points, kTrue));
  EXPECT_EQ(a.axis.direction, b.axis.direction);
  EXPECT_EQ(a.axis.origin, b.axis.origin);
  options.seed = 2;
  EXPECT_LE(searchAxis(kTrue, cost, options).cost, spread(points, kTrue));
}

TEST(AxisSearch, RejectsAZeroDirection) {
  EXPECT_THROW(searchAxis({Vec3::Zero(), Vec3::Zero()}, [](const Axis&) { return 0.0; }), std::invalid_argument);
}

}  // namespace test_AxisSearch
