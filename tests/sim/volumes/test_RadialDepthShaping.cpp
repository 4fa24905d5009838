// Fitting the radial depth volume (paper §3.2): a cylinder has a constant radial depth
// and no higher harmonics; a fitted volume encloses its part's vertices; an envelope fit
// encloses its points and hugs them.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/volumes/RadialDepthShaping.h"
#include "support/TestMeshes.h"

namespace test_RadialDepthShaping {

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

}  // namespace

TEST(RadialDepthShaping, ACylinderHasAConstantDepthAndNoHigherHarmonics) {
  const TriangleMesh mesh = cylinder(0.1, 0.5, 96, 10);
  const RadialDepth v = shapeRadialDepth(mesh, Vec3(0, 0, 0), Vec3::UnitY(), 0.5, 0.3, 6, 4);
  for (const auto& c : v.parameters().coefficients) {
    EXPECT_NEAR(c[0], 0.1, 0.001);  // the 96-gon's chords lie within 0.05 mm of r
    for (size_t k = 1; k < c.size(); ++k) EXPECT_NEAR(c[k], 0.0, 2e-4) << "term " << k;
  }
}

TEST(RadialDepthShaping, AShapedVolumeEnclosesItsPartAndFollowsItsShape) {
  // A ball (UV sphere, r = 0.12) along a tilted axis through it: every vertex whose
  // projection falls on the axis is inside, and the surface stays within 1 cm of the ball
  // (sections every 2.4 cm, 8 harmonics).
  const TriangleMesh ball = meshes::sphere(0.12, 48, 24);
  const Vec3 direction = Vec3(0.3, 1.0, 0.2).normalized();
  const Vec3 base = -0.12 * direction;
  const RadialDepth v = shapeRadialDepth(ball, base, direction, 0.24, 0.5, 11, 8);
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

TEST(RadialDepthShaping, AnEnvelopeEnclosesItsPointsAndHugsAnEllipticTube) {
  // An elliptic tube (semi-axes 6 and 4 cm) along a tilted axis: every point inside, and
  // the side within 1 mm of the ellipse (K = 4 resolves it), the mean gap under 0.5 mm.
  const Vec3 direction = Vec3(0.2, 1.0, 0.1).normalized(), u = direction.unitOrthogonal(), w = direction.cross(u);
  std::vector<Vec3> points;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j < 48; ++j) {
      const double a = 2 * M_PI * j / 48;
      points.push_back(0.4 * i / 20 * direction + 0.06 * std::cos(a) * u + 0.04 * std::sin(a) * w);
    }
  const RadialDepth v = shapeRadialDepthToPoints(points, points, -1e-4 * direction, direction, 0.4002, 9, 4);
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

}  // namespace test_RadialDepthShaping
