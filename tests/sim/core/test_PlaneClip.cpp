// Cutting along a plane: the kept part's area is the analytic one, the cut edge lies on
// the plane, windings stay, snapping leaves no sliver.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/core/PlaneClip.h"
#include "support/MeshChecks.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {
// Shortest altitude of the mesh's triangles.
double thinnest(const TriangleMesh& mesh) {
  double least = INFINITY;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec3 &a = mesh.vertices[t[k]], &b = mesh.vertices[t[(k + 1) % 3]], &c = mesh.vertices[t[(k + 2) % 3]];
      least = std::min(least, (b - a).cross(c - a).norm() / (b - a).norm());
    }
  return least;
}
}  // namespace

// A 40 x 30 cm sheet (y from 0 down to -0.3) cut at y = -0.1234 along a slanted plane's
// trace: the part above, 40 x 12.34 cm, stays, with its new edge on the plane.
TEST(PlaneClip, KeepsTheFrontWithTheCutOnThePlane) {
  const TriangleMesh sheet = meshes::grid(8, 6, 0.4, 0.3);
  const Plane plane{Vec3(0, -0.1234, 0), Vec3::UnitY()};
  const TriangleMesh top = clippedByPlane(sheet, plane);
  EXPECT_NEAR(surfaceArea(top), 0.4 * 0.1234, 1e-12);
  int onPlane = 0;
  for (const Vec3& x : top.vertices) {
    EXPECT_GE(plane.signedDistance(x), -1e-15);
    onPlane += std::abs(plane.signedDistance(x)) < 1e-15;
  }
  EXPECT_EQ(onPlane, 9 + 8);  // each column line crossed once, each cell's diagonal once
  for (const Triangle& t : top.triangles) EXPECT_GT(checks::normalOf(top, t).z(), 0.0);
  EXPECT_EQ(checks::connectedComponents(top), 1);
}

// A cut 1 mm past a row of vertices makes 1 mm slivers; a 2 mm snap moves that row onto
// the plane instead, and the area is the snapped one.
TEST(PlaneClip, SnappingLeavesNoSliver) {
  const TriangleMesh sheet = meshes::grid(8, 6, 0.4, 0.3);  // rows every 5 cm
  const Plane plane{Vec3(0, -0.101, 0), Vec3::UnitY()};
  EXPECT_LT(thinnest(clippedByPlane(sheet, plane)), 0.0011);
  const TriangleMesh snapped = clippedByPlane(sheet, plane, 0.002);
  EXPECT_GT(thinnest(snapped), 0.02);
  EXPECT_NEAR(surfaceArea(snapped), 0.4 * 0.101, 1e-12);
}

// A closed sphere cut through its middle: an open hemisphere, one boundary loop on the plane.
TEST(PlaneClip, ASphereCutInHalf) {
  const TriangleMesh ball = meshes::sphere(0.1, 24, 12);
  const TriangleMesh half = clippedByPlane(ball, Plane{Vec3(0, 0.013, 0), Vec3::UnitY()});
  EXPECT_TRUE(checks::consistentlyOriented(half));
  EXPECT_EQ(checks::mostTrianglesOnAnEdge(half), 2);
  EXPECT_NEAR(surfaceArea(half), 0.5 * surfaceArea(ball) * (1.0 - 0.13), 0.02 * surfaceArea(ball));
}

// Each vertex by its own plane: the top 20 cm of the sheet (rows every 5 cm) are cut at
// y = -0.1234, the 10 cm below, though behind that plane, have none and are kept whole (as
// the torso beyond a sleeve's cut is): two pieces, each manifold and wound as before.
TEST(PlaneClip, CutsEachVertexByItsOwnPlane) {
  const TriangleMesh sheet = meshes::grid(8, 6, 0.4, 0.3);
  std::vector<int> planeOf(sheet.vertices.size());
  for (size_t v = 0; v < planeOf.size(); ++v) planeOf[v] = sheet.vertices[v].y() > -0.2 - 1e-9 ? 0 : -1;
  const Plane plane{Vec3(0, -0.1234, 0), Vec3::UnitY()};
  const TriangleMesh cut = clippedBySurfaces(sheet, {plane}, planeOf);
  EXPECT_NEAR(surfaceArea(cut), 0.4 * 0.1234 + 0.4 * 0.1, 1e-12);
  for (const Vec3& x : cut.vertices) EXPECT_TRUE(plane.signedDistance(x) >= -1e-15 || x.y() <= -0.2 + 1e-9);
  EXPECT_EQ(checks::connectedComponents(cut), 2);
  EXPECT_TRUE(checks::consistentlyOriented(cut));
  EXPECT_LE(checks::mostTrianglesOnAnEdge(cut), 2);
}

// A sphere of radius 4 cm round a point 1 cm above a flat sheet cuts a round hole of
// radius sqrt(4^2 - 1^2) cm, its edge exactly on the sphere.
TEST(PlaneClip, ASphereCutsARoundHole) {
  const TriangleMesh sheet = meshes::grid(40, 40, 0.4, 0.4, Vec3(-0.2, 0.2, 0));
  const Sphere sphere{Vec3(0, 0, 0.01), 0.04};
  const TriangleMesh cut = clippedBySurfaces(sheet, {sphere}, std::vector<int>(sheet.vertices.size(), 0), 0.002);
  const double r = std::sqrt(0.04 * 0.04 - 0.01 * 0.01);
  EXPECT_NEAR(surfaceArea(cut), 0.16 - M_PI * r * r, 0.03 * M_PI * r * r);
  int onSphere = 0;
  for (const Vec3& x : cut.vertices) {
    EXPECT_GE(sphere.signedDistance(x), -1e-12);
    onSphere += std::abs(sphere.signedDistance(x)) < 1e-12;
  }
  EXPECT_GT(onSphere, 16);
  EXPECT_TRUE(checks::consistentlyOriented(cut));
}
