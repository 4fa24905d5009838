// Fitting a capsule by the paper's genetic algorithm: a capsule fitted to points of a
// known capsule's surface reproduces that surface; a fit encloses its points; a seed
// repeats a fit exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "sim/volumes/CapsuleShaping.h"

using namespace figment;

namespace {

std::vector<Vec3> surfaceSamples(const Capsule& capsule, int count, uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> t(0.0, 3.0), a(0.0, 2 * M_PI);
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i) points.push_back(capsule.surface(t(random), a(random)));
  return points;
}

// Largest distance from a grid of `from`'s surface points to `to`'s surface.
double oneSidedHausdorff(const Capsule& from, const Capsule& to) {
  double worst = 0.0;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j < 40; ++j)
      worst = std::max(worst, std::abs(to.nearest(from.surface(3.0 * i / 40, 2 * M_PI * j / 40)).distance));
  return worst;
}

CapsuleParameters thigh() {
  CapsuleParameters c;
  c.r1 = 0.5, c.r2 = 0.8, c.tx = 0.4, c.tz = 0.2;
  c.x = 0.14, c.y = 0.42, c.z = 0.15;
  c.ox = 0.09, c.oy = 0.62, c.oz = 0.01;
  c.theta = 0.08, c.phi = 1.3;
  return c;
}

}  // namespace

TEST(CapsuleShaping, AShapedCapsuleReproducesTheCapsuleItsPointsCameFrom) {
  // Symmetric Hausdorff distance between the surfaces under 1 % of the capsule's length
  // (parameters may differ where two describe the same surface).
  const Capsule truth(thigh());
  const std::vector<Vec3> points = surfaceSamples(truth, 800, 3);
  const CapsuleShaping shaped = shapeCapsule(points);
  const Capsule result(shaped.parameters);
  const double size = thigh().y;
  RecordProperty("hausdorff_mm",
                 std::to_string(1000 * std::max(oneSidedHausdorff(truth, result), oneSidedHausdorff(result, truth))));
  RecordProperty("enclosure_scale", std::to_string(shaped.enclosureScale));
  EXPECT_LT(oneSidedHausdorff(truth, result), 0.01 * size);
  EXPECT_LT(oneSidedHausdorff(result, truth), 0.01 * size);
}

TEST(CapsuleShaping, TheShapedCapsuleEnclosesEveryPoint) {
  // Points of a box (a part no capsule fits exactly): enclosure grows the best capsule
  // until none is left outside.
  std::vector<Vec3> box;
  for (int i = 0; i <= 6; ++i)
    for (int j = 0; j <= 6; ++j)
      for (int k = 0; k <= 6; ++k)
        if (i % 6 == 0 || j % 6 == 0 || k % 6 == 0) box.push_back(Vec3(0.1 * i / 6, 0.3 * j / 6, 0.08 * k / 6));
  CapsuleShapingOptions options;
  options.generations = 150;
  const CapsuleShaping shaped = shapeCapsule(box, options);
  const Capsule capsule(shaped.parameters);
  for (const Vec3& p : box) EXPECT_TRUE(capsule.contains(p)) << p.transpose();
  EXPECT_GT(shaped.enclosureScale, 1.0);
}

TEST(CapsuleShaping, TheSameSeedRepeatsACapsuleAndAnotherChangesIt) {
  const std::vector<Vec3> points = surfaceSamples(Capsule(thigh()), 200, 5);
  CapsuleShapingOptions options;
  options.generations = 60;
  const CapsuleShaping a = shapeCapsule(points, options), b = shapeCapsule(points, options);
  EXPECT_EQ(a.parameters.values(), b.parameters.values());
  options.seed = 2;
  EXPECT_NE(shapeCapsule(points, options).parameters.values(), a.parameters.values());
}

TEST(CapsuleShaping, TooFewPointsAreRefused) {
  EXPECT_THROW(shapeCapsule({Vec3::Zero(), Vec3::UnitX()}), std::invalid_argument);
}

TEST(CapsuleShaping, TheGaugeAgreesWithTheInsideTest) {
  // unitGauge(u) <= 1 exactly where the unit capsule holds u, for a tapered, tilted,
  // unequally rounded capsule; and grown by the gauge a point lies on the surface.
  CapsuleParameters c = thigh();
  c.r1 = 0.2, c.r2 = 0.9;
  const Capsule capsule(c);
  std::mt19937 random(4);
  std::uniform_real_distribution<double> offset(-0.4, 0.4);
  for (int i = 0; i < 20000; ++i) {
    const Vec3 u = capsule.toUnit(Vec3(c.ox, c.oy, c.oz) + Vec3(offset(random), offset(random), offset(random)));
    const double g = unitGauge(capsule, u);
    if (std::abs(g - 1.0) > 1e-9) {
      EXPECT_EQ(g <= 1.0, capsule.containsUnit(u)) << u.transpose() << " g " << g;
    }
  }
  const Vec3 u(0.3, 0.45, -0.2);
  const Vec3 onSurface = u / unitGauge(capsule, u);
  EXPECT_NEAR((capsule.unitProjection(onSurface) - onSurface).norm(), 0.0, 1e-9);
}
