// The radial depth volume (paper §3.2): a cylinder has a constant radial depth and no
// higher harmonics; a cone's nearest point and normal are exact, the push-out follows
// the normal, not the radius; a fitted volume encloses its part's vertices.
#include "support/TestMeshes.h"
#include "sim/collision/RadialDepth.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace figment;

namespace {

// A closed cylinder mesh of radius r from y = 0 to y = height, `slices` around.
TriangleMesh cylinder(double r, double height, int slices, int rings) {
  TriangleMesh mesh;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j < slices; ++j) {
      const double a = 2 * M_PI * j / slices;
      mesh.vertices.push_back(Vec3(r * std::cos(a), height * i / rings, r * std::sin(a)));
    }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < slices; ++j) {
      const int a = i * slices + j, b = i * slices + (j + 1) % slices;
      mesh.triangles.push_back({a, a + slices, b});
      mesh.triangles.push_back({b, a + slices, b + slices});
    }
  return mesh;
}

// A cone frustum along y: radius r0 at s = 0, r1 at s = length, no harmonics.
RadialDepth frustum(double r0, double r1, double length) {
  RadialDepthParameters p;
  p.length = length;
  p.coefficients = {{r0}, {r1}};
  return RadialDepth(p);
}

}  // namespace

TEST(RadialDepth, ACylinderHasAConstantDepthAndNoHigherHarmonics) {
  const TriangleMesh mesh = cylinder(0.1, 0.5, 96, 10);
  const RadialDepth v = fitRadialDepth(mesh, Vec3(0, 0, 0), Vec3::UnitY(), 0.5, 0.3, 6, 4);
  for (const auto& c : v.parameters().coefficients) {
    EXPECT_NEAR(c[0], 0.1, 0.001);  // the 96-gon's chords lie within 0.05 mm of r
    for (size_t k = 1; k < c.size(); ++k) EXPECT_NEAR(c[k], 0.0, 2e-4) << "term " << k;
  }
}

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

TEST(RadialDepth, AFittedVolumeEnclosesItsPartAndFollowsItsShape) {
  // A ball (UV sphere, r = 0.12) along a tilted axis through it: every vertex whose
  // projection falls on the axis is inside, and the surface stays within 1 cm of the ball
  // (sections every 2.4 cm, 8 harmonics).
  const TriangleMesh ball = meshes::sphere(0.12, 48, 24);
  const Vec3 direction = Vec3(0.3, 1.0, 0.2).normalized();
  const Vec3 base = -0.12 * direction;
  const RadialDepth v = fitRadialDepth(ball, base, direction, 0.24, 0.5, 11, 8);
  int checked = 0;
  for (const Vec3& p : ball.vertices) {
    double s, a, rho;
    v.toAxis(p, s, a, rho);
    if (s <= 0.0 || s >= 0.24) continue;
    ++checked;
    EXPECT_TRUE(v.contains(p)) << p.transpose();
  }
  EXPECT_GT(checked, 1000);
  for (double s : {0.06, 0.12, 0.18})
    for (double a : {0.0, 1.0, 2.0, 4.0}) EXPECT_NEAR(v.surface(s, a).norm(), 0.12, 0.01) << s << " " << a;
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
  RadialDepthParameters p;
  p.direction = Vec3(0.2, 1.0, -0.1).normalized();
  p.reference = p.direction.unitOrthogonal();
  p.length = 0.4;
  p.harmonics = 2;
  p.coefficients = {{0.08, 0.01, -0.005, 0.002, 0.001}, {0.06, -0.01, 0.004, 0.0, -0.002}, {0.07, 0.0, 0.0, 0.003, 0.0}};
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
  RadialDepthParameters p;
  p.length = 0.4;
  p.harmonics = 2;
  p.coefficients = {{0.08, 0.01, -0.005, 0.002, 0.001}, {0.06, -0.01, 0.004, 0.0, -0.002}, {0.07, 0.0, 0.0, 0.003, 0.0}};
  const RadialDepth v(p);
  double worst = 0.0;
  for (int i = 0; i < 300; ++i) {
    const double s = 0.02 + 0.36 * ((i * 37) % 300) / 300.0, a = 2 * M_PI * ((i * 91) % 300) / 300.0;
    const Vec3 q = v.surface(s, a) + 0.01 * Vec3(std::sin(3.0 * i), std::cos(5.0 * i), std::sin(7.0 * i));
    worst = std::max(worst, std::abs(v.nearestFast(q).distance - v.nearest(q).distance));
  }
  EXPECT_LT(worst, 3e-4);
}

TEST(RadialDepth, AnEnvelopeFitEnclosesItsPointsAndHugsAnEllipticTube) {
  // An elliptic tube (semi-axes 6 and 4 cm) along a tilted axis: every point inside, and
  // the side within 1 mm of the ellipse (K = 4 resolves it), the mean gap under 0.5 mm.
  const Vec3 direction = Vec3(0.2, 1.0, 0.1).normalized(), u = direction.unitOrthogonal(), w = direction.cross(u);
  std::vector<Vec3> points;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j < 48; ++j) {
      const double a = 2 * M_PI * j / 48;
      points.push_back(0.4 * i / 20 * direction + 0.06 * std::cos(a) * u + 0.04 * std::sin(a) * w);
    }
  const RadialDepth v = fitRadialDepthToPoints(points, points, -1e-4 * direction, direction, 0.4002, 9, 4);
  double total = 0.0;
  for (const Vec3& p : points) {
    EXPECT_TRUE(v.contains(p)) << p.transpose();
    total += std::abs(v.nearest(p).distance);
  }
  EXPECT_LT(total / points.size(), 5e-4);
  for (double a : {0.0, 1.0, 2.5}) {
    const Vec3 s = v.surface(0.2, a) - (v.parameters().base + 0.2 * v.parameters().direction);
    const double x = s.dot(u), z = s.dot(w);
    EXPECT_NEAR(std::hypot(x / 0.06, z / 0.04), 1.0, 0.03) << a;
  }
}

TEST(RadialDepth, TheFastPathPushesADeepPointStraightOut) {
  // Points up to 4 cm deep in a wavy volume: the push-out from p to point + clearance
  // normal runs along the normal (else a contact response turns its sideways part into
  // velocity).
  RadialDepthParameters p;
  p.length = 0.4;
  p.harmonics = 2;
  p.coefficients = {{0.08, 0.01, -0.005, 0.002, 0.001}, {0.06, -0.01, 0.004, 0.0, -0.002}, {0.07, 0.0, 0.0, 0.003, 0.0}};
  const RadialDepth v(p);
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
