// The radial depth volume (paper §3.2): a cone's nearest point and normal are exact, the
// push-out follows the normal, not the radius.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/collision/RadialDepth.h"

using namespace figment;

namespace {

// A cone frustum along y: radius r0 at s = 0, r1 at s = length, no harmonics.
RadialDepth frustum(double r0, double r1, double length) {
  RadialDepthParameters p;
  p.length = length;
  p.coefficients = {{r0}, {r1}};
  return RadialDepth(p);
}

// A wavy volume along y: 2 harmonics over 3 sections, 0.4 m long.
RadialDepthParameters wavyVolume() {
  RadialDepthParameters p;
  p.length = 0.4;
  p.harmonics = 2;
  p.coefficients = {
      {0.08, 0.01, -0.005, 0.002, 0.001}, {0.06, -0.01, 0.004, 0.0, -0.002}, {0.07, 0.0, 0.0, 0.003, 0.0}};
  return p;
}

}  // namespace

TEST(RadialDepth, AConesNearestPointAndNormalAreExact) {
  // Radius 0.1 at the bottom, 0.05 at the top of a 0.5 m axis: the side leans in by
  // atan(0.1) and its outward normal has an axial component of sin(atan(0.1)).
  const RadialDepth cone = frustum(0.1, 0.05, 0.5);
  const double slope = 0.05 / 0.5, lean = std::atan(slope);
  const Vec3 p(0.2, 0.25, 0.0);  // outside, level with the middle (radius 0.075)
  const SurfacePoint s = cone.nearest(p);
  // Distance from p to the side's line in the x-y plane.
  const Vec3 foot(0.075, 0.25, 0.0), along = Vec3(-slope, 1.0, 0.0).normalized();
  const Vec3 expected = foot + (p - foot).dot(along) * along;
  EXPECT_NEAR((s.point - expected).norm(), 0.0, 1e-8);
  EXPECT_NEAR(s.normal.y(), std::sin(lean), 1e-6) << "along the normal, not the radius";
  EXPECT_NEAR(s.normal.x(), std::cos(lean), 1e-6);
  EXPECT_NEAR(s.distance, (p - expected).norm(), 1e-8);
  // Inside, nearer the side than the caps: pushed out along the same tilted normal.
  const SurfacePoint in = cone.nearest(Vec3(0.07, 0.25, 0.0));
  EXPECT_LT(in.distance, 0.0);
  EXPECT_NEAR(in.normal.y(), std::sin(lean), 1e-5);
  EXPECT_TRUE(cone.contains(Vec3(0.07, 0.25, 0.0)));
  EXPECT_FALSE(cone.contains(Vec3(0.08, 0.25, 0.0)));
  EXPECT_FALSE(cone.contains(Vec3(0.0, 0.51, 0.0)));
}

TEST(RadialDepth, PointsNearAnEndGoToTheCap) {
  const RadialDepth cone = frustum(0.1, 0.05, 0.5);
  const SurfacePoint top = cone.nearest(Vec3(0.01, 0.49, 0.02));
  EXPECT_NEAR(top.distance, -0.01, 1e-9);
  EXPECT_NEAR((top.point - Vec3(0.01, 0.5, 0.02)).norm(), 0.0, 1e-9);
  EXPECT_NEAR(top.normal.y(), 1.0, 1e-9);
  const SurfacePoint below = cone.nearest(Vec3(0.03, -0.2, 0.0));
  EXPECT_NEAR(below.distance, 0.2, 1e-9);
  EXPECT_NEAR(below.normal.y(), -1.0, 1e-9);
}

TEST(RadialDepth, BadParametersAreNamed) {
  RadialDepthParameters p;
  p.coefficients = {{0.1}};
  EXPECT_THROW(RadialDepth{p}, std::invalid_argument);
  p.coefficients = {{0.1}, {0.1, 0.0}};
  EXPECT_THROW(RadialDepth{p}, std::invalid_argument);
  p.coefficients = {{0.1}, {0.1}};
  p.reference = Vec3::UnitY();
  EXPECT_THROW(RadialDepth{p}, std::invalid_argument);
}

TEST(RadialDepth, AnalyticTangentsMatchFiniteDifferences) {
  RadialDepthParameters p = wavyVolume();
  p.direction = Vec3(0.2, 1.0, -0.1).normalized();
  p.reference = p.direction.unitOrthogonal();
  const RadialDepth v(p);
  for (double s : {0.05, 0.13, 0.27, 0.36})
    for (double a : {0.3, 2.2, 5.0}) {
      const SurfaceSample x = v.sample(s, a);
      const Vec3 ds = (v.surface(s + 1e-7, a) - v.surface(s - 1e-7, a)) / 2e-7;
      const Vec3 da = (v.surface(s, a + 1e-7) - v.surface(s, a - 1e-7)) / 2e-7;
      EXPECT_NEAR((x.w - v.surface(s, a)).norm(), 0.0, 1e-15);
      EXPECT_NEAR((x.dt - ds).norm(), 0.0, 1e-6) << "s " << s << " a " << a;
      EXPECT_NEAR((x.da - da).norm(), 0.0, 1e-6) << "s " << s << " a " << a;
    }
}

TEST(RadialDepth, TheFastPathStaysCloseToTheExactNearestPoint) {
  // A wavy volume (2 harmonics, 3 sections); points within 1 cm of its side.
  const RadialDepth v(wavyVolume());
  double worst = 0.0;
  for (int i = 0; i < 300; ++i) {
    const double s = 0.02 + 0.36 * ((i * 37) % 300) / 300.0, a = 2 * M_PI * ((i * 91) % 300) / 300.0;
    const Vec3 q = v.surface(s, a) + 0.01 * Vec3(std::sin(3.0 * i), std::cos(5.0 * i), std::sin(7.0 * i));
    worst = std::max(worst, std::abs(v.nearestFast(q).distance - v.nearest(q).distance));
  }
  EXPECT_LT(worst, 3e-4);
}

TEST(RadialDepth, TheFastPathPushesADeepPointStraightOut) {
  // Points up to 4 cm deep in a wavy volume: the push-out from p to point + clearance
  // normal runs along the normal (else a contact response turns its sideways part into
  // velocity).
  const RadialDepth v(wavyVolume());
  int tested = 0;
  for (int i = 0; i < 1000; ++i) {
    const double s = 0.01 + 0.38 * ((i * 37) % 1000) / 1000.0, a = 2 * M_PI * ((i * 91) % 1000) / 1000.0;
    const Vec3 surface = v.surface(s, a);
    const Vec3 q = surface - 0.04 * ((i * 13) % 100 + 1) / 101.0 * Vec3(surface.x(), 0.0, surface.z()).normalized();
    if (!v.contains(q)) continue;
    ++tested;
    const SurfacePoint fast = v.nearestFast(q);
    ASSERT_LT(fast.distance, 0.0);
    const Vec3 r = q - fast.point;
    EXPECT_LT((r - r.dot(fast.normal) * fast.normal).norm(), kSideways + 1e-12) << q.transpose();
  }
  EXPECT_GT(tested, 800);
}
