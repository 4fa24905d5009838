// Boundary loops and their turning angles on analytic shapes: a regular n-gon turns 360/n
// degrees at each rim vertex, a rectangle 90 at its corners and 0 along its sides, a closed
// surface has no boundary, an open tube two loops wound opposite ways.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sim/core/BoundaryLoops.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {
// A regular n-gon of radius r in the plane y = 0 as a fan from its centre (vertex n),
// counter-clockwise seen from +y.
TriangleMesh ngon(int n, double r) {
  TriangleMesh mesh;
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * M_PI * k / n;
    mesh.vertices.emplace_back(r * std::cos(a), 0.0, -r * std::sin(a));
  }
  mesh.vertices.emplace_back(0.0, 0.0, 0.0);
  for (int k = 0; k < n; ++k) mesh.triangles.push_back({n, k, (k + 1) % n});
  return mesh;
}
}  // namespace

TEST(BoundaryLoops, ARegularPolygonTurns360OverNAtEachVertex) {
  for (int n : {3, 5, 12, 40}) {
    const TriangleMesh polygon = ngon(n, 0.3);
    const std::vector<std::vector<int>> loops = boundaryLoops(polygon.triangles);
    ASSERT_EQ(loops.size(), 1u);
    ASSERT_EQ(static_cast<int>(loops[0].size()), n);
    // Wound as the triangles are: vertex k is followed by vertex k + 1.
    for (int k = 0; k < n; ++k) EXPECT_EQ(loops[0][(k + 1) % n], (loops[0][k] + 1) % n);
    for (double angle : boundaryTurningAngles(polygon.vertices, loops)) EXPECT_NEAR(angle, 360.0 / n, 1e-9) << n;
    EXPECT_NEAR(medianBoundaryTurning(polygon.vertices, polygon.triangles), 360.0 / n, 1e-9);
  }
}

// A 4 x 3 grid's rim: 4 corners of 90 degrees among 14 vertices, the rest straight.
TEST(BoundaryLoops, ARectangleTurnsOnlyAtItsCorners) {
  const TriangleMesh sheet = meshes::grid(4, 3, 0.4, 0.3);
  const std::vector<std::vector<int>> loops = boundaryLoops(sheet.triangles);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].size(), 14u);
  int corners = 0;
  for (double angle : boundaryTurningAngles(sheet.vertices, loops)) {
    EXPECT_TRUE(std::abs(angle) < 1e-9 || std::abs(angle - 90.0) < 1e-9) << angle;
    corners += std::abs(angle - 90.0) < 1e-9;
  }
  EXPECT_EQ(corners, 4);
  EXPECT_NEAR(medianBoundaryTurning(sheet.vertices, sheet.triangles), 0.0, 1e-9);
}

TEST(BoundaryLoops, AClosedSurfaceHasNone) {
  const TriangleMesh ball = meshes::sphere(0.1, 16, 8);
  EXPECT_TRUE(boundaryLoops(ball.triangles).empty());
  EXPECT_EQ(medianBoundaryTurning(ball.vertices, ball.triangles), 0.0);
}

// A sphere without its caps' fans is a tube: two loops, each a regular 16-gon in a
// horizontal plane, turning 22.5 degrees at each vertex.
TEST(BoundaryLoops, AnOpenTubeHasTwoLoops) {
  TriangleMesh ball = meshes::sphere(0.1, 16, 8);
  std::erase_if(ball.triangles, [&](const Triangle& t) {
    for (int c : t)
      if (std::abs(std::abs(ball.vertices[c].y()) - 0.1) < 1e-12) return true;  // a pole
    return false;
  });
  const std::vector<std::vector<int>> loops = boundaryLoops(ball.triangles);
  ASSERT_EQ(loops.size(), 2u);
  for (const std::vector<int>& loop : loops) {
    EXPECT_EQ(loop.size(), 16u);
    for (int v : loop) EXPECT_NEAR(ball.vertices[v].y(), ball.vertices[loop[0]].y(), 1e-12);
  }
  for (double angle : boundaryTurningAngles(ball.vertices, loops)) EXPECT_NEAR(angle, 22.5, 1e-9);
}

// A zig-zag edge: a triangle strip whose rim doubles back turns by more than 90 degrees at
// its teeth; two triangles sharing only a corner make two loops through that corner.
TEST(BoundaryLoops, TeethTurnSharplyAndLoopsMayTouch) {
  TriangleMesh bowtie;
  bowtie.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0), Vec3(0, -1, 0)};
  bowtie.triangles = {{0, 1, 2}, {0, 3, 4}};
  const std::vector<std::vector<int>> loops = boundaryLoops(bowtie.triangles);
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_EQ(loops[0].size() + loops[1].size(), 6u);
  const std::vector<double> angles = boundaryTurningAngles(bowtie.vertices, loops);
  for (double angle : angles) EXPECT_GE(angle, 90.0 - 1e-9);
  EXPECT_NEAR(angles[0] + angles[1] + angles[2], 360.0, 1e-9);  // a triangle's exterior angles
}

// Splitting a 12-gon's 5 longest rim edges (all equal: the lowest indices go first) gives 17
// rim vertices, 5 more triangles, the same area, and each new vertex midway along its edge.
TEST(BoundaryLoops, SplitsTheLongestBoundaryEdges) {
  const TriangleMesh polygon = ngon(12, 0.3);
  const TriangleMesh split = withBoundaryEdgesSplit(polygon, 5);
  EXPECT_EQ(split.triangles.size(), polygon.triangles.size() + 5);
  EXPECT_EQ(split.vertices.size(), polygon.vertices.size() + 5);
  EXPECT_NEAR(surfaceArea(split), surfaceArea(polygon), 1e-12);
  const std::vector<std::vector<int>> loops = boundaryLoops(split.triangles);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].size(), 17u);
  for (const Vec3& x : split.vertices) EXPECT_LE(x.norm(), 0.3 + 1e-12);
  // Asking for more than the rim has splits every rim edge once.
  EXPECT_EQ(boundaryLoops(withBoundaryEdgesSplit(polygon, 100).triangles)[0].size(), 24u);
}

// A hem's zig-zag: a 24-gon in the plane y = 0 with every other rim vertex 5 % further in and
// 3 degrees further round (turning 9 to 31 degrees); smoothed along the loop on its plane, it
// turns the regular 15 degrees again within half a degree, and keeps its size (Taubin's
// steps do not shrink it as plain averaging would).
TEST(BoundaryLoops, SmoothingTakesOutAZigZag) {
  TriangleMesh polygon = ngon(24, 1.0);
  const Eigen::AngleAxisd turn(3.0 * M_PI / 180.0, Vec3::UnitY());
  for (int k = 1; k < 24; k += 2) polygon.vertices[k] = 0.95 * (turn * polygon.vertices[k]);
  const std::vector<std::vector<int>> loops = boundaryLoops(polygon.triangles);
  const std::vector<double> before = boundaryTurningAngles(polygon.vertices, loops);
  EXPECT_GT(*std::max_element(before.begin(), before.end()), 25.0);
  auto onPlane = [](const Vec3& x) { return Vec3(x.x(), 0.0, x.z()); };
  smoothLoop(polygon.vertices, loops[0], 10, onPlane);
  for (double angle : boundaryTurningAngles(polygon.vertices, loops)) EXPECT_NEAR(angle, 15.0, 0.5);
  double radius = 0;
  for (int k = 0; k < 24; ++k) radius += polygon.vertices[k].norm() / 24;
  EXPECT_NEAR(radius, 0.975, 0.01);
}
