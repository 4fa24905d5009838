// Bounds and welding by position: literal meshes where the answer is known.
#include <gtest/gtest.h>

#include <stdexcept>

#include "sim/core/TriangleMesh.h"
#include "support/BoxFigure.h"
#include "support/MeshChecks.h"

using namespace figment;

TEST(TriangleMesh, BoundsOfPoints) {
  const Bounds bounds = boundsOf({Vec3(1, -2, 3), Vec3(-1, 5, 0), Vec3(0, 0, 4)});
  EXPECT_EQ(bounds.min, Vec3(-1, -2, 0));
  EXPECT_EQ(bounds.max, Vec3(1, 5, 4));
  EXPECT_EQ(bounds.size(), Vec3(2, 7, 4));
  EXPECT_FALSE(bounds.empty());
}

TEST(TriangleMesh, BoundsOfNothingIsEmpty) {
  EXPECT_TRUE(boundsOf({}).empty());
}

// A box with four vertices per face (split along every edge, as texture seams split a mesh)
// welds into the closed box: 8 corners, every edge shared by two triangles, volume intact.
TEST(TriangleMesh, MergeByPositionClosesASplitBox) {
  const TriangleMesh split = mannequin::boxMesh({Vec3(0, 0, 0), Vec3(1, 2, 3)});
  ASSERT_EQ(split.vertices.size(), 24u);
  ASSERT_FALSE(checks::everyEdgeSharedByTwo(split));

  const TriangleMesh merged = mergeByPosition(split);
  EXPECT_EQ(merged.vertices.size(), 8u);
  EXPECT_EQ(merged.triangles.size(), 12u);
  EXPECT_TRUE(checks::everyEdgeSharedByTwo(merged));
  EXPECT_TRUE(checks::consistentlyOriented(merged));
  EXPECT_NEAR(checks::signedVolume(merged), 6.0, 1e-12);
}

// Kept vertices keep the order of their first occurrence; later copies point to them.
TEST(TriangleMesh, MergeByPositionKeepsFirstOccurrenceOrder) {
  TriangleMesh mesh;
  mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0),   // triangle 0
                   Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(1, 0, 0)};  // triangle 1, sharing an edge by copies
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
  const TriangleMesh merged = mergeByPosition(mesh);
  ASSERT_EQ(merged.vertices.size(), 4u);
  EXPECT_EQ(merged.vertices[0], Vec3(0, 0, 0));
  EXPECT_EQ(merged.vertices[1], Vec3(1, 0, 0));
  EXPECT_EQ(merged.vertices[2], Vec3(0, 1, 0));
  EXPECT_EQ(merged.vertices[3], Vec3(1, 1, 0));
  EXPECT_EQ(merged.triangles[1], (Triangle{3, 2, 1}));
}

// Closer than the tolerance welds even across a grid cell border; farther does not.
TEST(TriangleMesh, MergeByPositionUsesTheTolerance) {
  const double tolerance = 1e-3;
  TriangleMesh mesh;
  mesh.vertices = {Vec3(0.9999e-3, 0, 0), Vec3(1.0004e-3, 0, 0),  // 0.5 um apart, either side of x = 1 mm
                   Vec3(0, 1, 0), Vec3(0, 1.0011, 0),             // 1.1 mm apart
                   Vec3(1, 0, 0)};
  mesh.triangles = {{0, 2, 4}, {1, 3, 4}};
  const TriangleMesh merged = mergeByPosition(mesh, tolerance);
  EXPECT_EQ(merged.vertices.size(), 4u);
  EXPECT_EQ(merged.triangles[1][0], 0);
  EXPECT_NE(merged.triangles[1][1], merged.triangles[0][1]);
}

// A triangle two of whose corners weld has no area left and is dropped.
TEST(TriangleMesh, MergeByPositionDropsCollapsedTriangles) {
  TriangleMesh mesh;
  mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1e-9, 0, 0)};
  mesh.triangles = {{0, 1, 2}, {0, 3, 2}};
  const TriangleMesh merged = mergeByPosition(mesh, 1e-6);
  EXPECT_EQ(merged.vertices.size(), 3u);
  ASSERT_EQ(merged.triangles.size(), 1u);
  EXPECT_EQ(merged.triangles[0], (Triangle{0, 1, 2}));
}

// Tolerance 0 welds exact copies only.
TEST(TriangleMesh, MergeByPositionWithZeroToleranceWeldsExactCopies) {
  TriangleMesh mesh;
  mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(1e-12, 1, 0)};
  mesh.triangles = {{0, 1, 2}, {3, 4, 0}};
  EXPECT_EQ(mergeByPosition(mesh, 0.0).vertices.size(), 4u);
}

TEST(TriangleMesh, MergeByPositionRejectsNegativeTolerance) {
  EXPECT_THROW(mergeByPosition(TriangleMesh{}, -1e-6), std::invalid_argument);
}

TEST(TriangleMesh, CroppedToBoxKeepsTrianglesWhoseCentroidIsInside) {
  // A strip of four unit squares along x, two triangles each with centroids at i + 1/3
  // and i + 2/3; the box takes x in [1.2, 3]: the second and third squares.
  TriangleMesh strip;
  for (int i = 0; i <= 4; ++i) strip.vertices.push_back(Vec3(i, 0, 0)), strip.vertices.push_back(Vec3(i, 1, 0));
  for (int i = 0; i < 4; ++i) {
    const int a = 2 * i;
    strip.triangles.push_back({a, a + 2, a + 3});
    strip.triangles.push_back({a, a + 3, a + 1});
  }
  Bounds box;
  box.min = Vec3(1.2, -1, -1);
  box.max = Vec3(3, 2, 1);
  const TriangleMesh part = croppedToBox(strip, box);
  ASSERT_EQ(part.triangles.size(), 4u);
  EXPECT_EQ(part.vertices.size(), 6u);
  for (const Triangle& t : part.triangles) {
    const Vec3 c = (part.vertices[t[0]] + part.vertices[t[1]] + part.vertices[t[2]]) / 3.0;
    EXPECT_GE(c.x(), 1.2);
    EXPECT_LE(c.x(), 3.0);
  }
  EXPECT_EQ(part.vertices[0], Vec3(1, 0, 0)) << "vertices numbered as first used";
  EXPECT_TRUE(croppedToBox(strip, Bounds{}).triangles.empty()) << "an empty box keeps nothing";
}

// A vertex at -1.1e20 m (found by tests/fuzz/fuzz_mesh in an OBJ file) made the welding grid
// cast a double outside int64's range: undefined behaviour, which the sanitizer build stops on.
// Far and non-finite coordinates now share the outermost cell, and welding still goes by the
// true distance: the far copies weld, the near ones stay apart from them.
TEST(TriangleMesh, MergeByPositionTakesCoordinatesFarBeyondAnyBody) {
  TriangleMesh mesh;
  mesh.vertices = {Vec3(-1.1e20, 0, 0), Vec3(1, 0, 0),      Vec3(0, 1e300, 0),
                   Vec3(-1.1e20, 0, 0), Vec3(0, 0, -1e300), Vec3(0, 0, 0)};
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
  const TriangleMesh merged = mergeByPosition(mesh);
  EXPECT_EQ(merged.vertices.size(), 5u);  // the two at -1.1e20 m weld
  EXPECT_EQ(merged.triangles[1][0], merged.triangles[0][0]);
}
