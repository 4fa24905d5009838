// The display mesh: four triangles for one per level, the simulation's vertices kept, the
// new ones on a smooth surface through them; boundaries smoother than the coarse mesh's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sim/core/BoundaryLoops.h"
#include "sim/core/DisplaySubdivision.h"
#include "sim/core/Subdivision.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {

struct Display {
  std::vector<Vec3> points, normals;
  std::vector<Triangle> triangles;
};

Display display(const TriangleMesh& mesh, int levels) {
  const DisplaySubdivision layout(mesh.triangles, mesh.vertices, levels);
  Display out;
  layout.apply(mesh.vertices, out.points, out.normals);
  out.triangles = layout.triangles();
  return out;
}

// The unit sphere's cap above y = 0.3 (a sphere-like patch with a free, circular boundary):
// the sphere's triangles with every corner there, the vertices kept as they are.
TriangleMesh cap(int slices, int stacks) {
  TriangleMesh ball = meshes::sphere(1.0, slices, stacks);
  std::vector<Triangle> kept;
  for (const Triangle& t : ball.triangles)
    if (std::all_of(t.begin(), t.end(), [&](int v) { return ball.vertices[v].y() > 0.3; })) kept.push_back(t);
  ball.triangles = kept;
  return ball;
}

// Largest distance from the unit sphere of the vertices the triangles use.
double largestDeviation(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles) {
  double most = 0.0;
  for (const Triangle& t : triangles)
    for (int v : t) most = std::max(most, std::abs(points[v].norm() - 1.0));
  return most;
}

}  // namespace

TEST(DisplaySubdivision, KeepsTheSimulationsVerticesAndSplitsEachTriangleInFour) {
  const TriangleMesh sheet = meshes::grid(3, 2, 0.3, 0.2);
  for (int levels : {0, 1, 2}) {
    const Display fine = display(sheet, levels);
    EXPECT_EQ(fine.triangles.size(), sheet.triangles.size() << (2 * levels));
    for (size_t v = 0; v < sheet.vertices.size(); ++v) EXPECT_EQ(fine.points[v], sheet.vertices[v]);
    for (const Triangle& t : fine.triangles) {  // every new triangle faces as the sheet does
      const Vec3 n = (fine.points[t[1]] - fine.points[t[0]]).cross(fine.points[t[2]] - fine.points[t[0]]);
      EXPECT_GT(n.z(), 0.0);
    }
  }
}

// A flat sheet stays flat, and its square corners stay square: no vertex leaves the sheet's
// rectangle (the 4-point rule next to a corner would overshoot it; corners take midpoints).
TEST(DisplaySubdivision, AFlatSheetStaysInsideItsRectangle) {
  const Display fine = display(meshes::grid(4, 3, 0.4, 0.3), 2);
  for (const Vec3& p : fine.points) {
    EXPECT_NEAR(p.z(), 0.0, 1e-15);
    EXPECT_GE(p.x(), -1e-15);
    EXPECT_LE(p.x(), 0.4 + 1e-15);
    EXPECT_GE(p.y(), -0.3 - 1e-15);  // the grid runs down from y = 0
    EXPECT_LE(p.y(), 1e-15);
  }
}

// The cap of a coarse sphere (15 degrees between vertices): midpoint subdivision leaves
// its new vertices on the chords, up to 1 - cos 7.5 deg = 0.0086 inside the sphere; the
// display mesh's stay within a tenth of that of the limit surface, the sphere, at every
// level, its boundary circle included, and its normals point out of the sphere.
TEST(DisplaySubdivision, ASphericalPatchStaysNearTheSphere) {
  const TriangleMesh patch = cap(24, 12);
  const TriangleMesh chords = subdivided(subdivided(patch));
  const double chordDeviation = largestDeviation(chords.vertices, chords.triangles);
  EXPECT_GT(chordDeviation, 0.008);
  for (int levels : {1, 2}) {
    const Display fine = display(patch, levels);
    EXPECT_LT(largestDeviation(fine.points, fine.triangles), 0.1 * chordDeviation) << levels << " levels";
    for (const Triangle& t : fine.triangles)
      for (int v : t) EXPECT_GT(fine.normals[v].dot(fine.points[v].normalized()), 0.99);
  }
}

// The cap's boundary is a 24-gon: 15 degrees at each vertex. Once split it turns about half
// as much a vertex, twice split a quarter.
TEST(DisplaySubdivision, TheBoundaryTurnsLessThanTheSimulationMeshes) {
  const TriangleMesh patch = cap(24, 12);
  const double coarse = medianBoundaryTurning(patch.vertices, patch.triangles);
  EXPECT_NEAR(coarse, 15.0, 1e-9);
  const Display once = display(patch, 1), twice = display(patch, 2);
  EXPECT_LT(medianBoundaryTurning(once.points, once.triangles), 0.55 * coarse);
  EXPECT_LT(medianBoundaryTurning(twice.points, twice.triangles), 0.3 * coarse);
}

// Two sheets side by side, each with its own vertices along the line they share (a seam):
// one surface for the display mesh, its boundary the outline of both (no loop along the
// seam), the same normal on both sides of it.
TEST(DisplaySubdivision, ASeamIsOneSurface) {
  TriangleMesh left = meshes::grid(2, 2, 0.2, 0.2);
  const TriangleMesh right = meshes::grid(2, 2, 0.2, 0.2, Vec3(0.2, 0.0, 0.0));
  const int offset = static_cast<int>(left.vertices.size());
  left.vertices.insert(left.vertices.end(), right.vertices.begin(), right.vertices.end());
  for (const Triangle& t : right.triangles) left.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  for (Vec3& p : left.vertices) p.z() = 0.5 * p.x() * p.x();  // bent across the seam
  ASSERT_EQ(boundaryLoops(left.triangles).size(), 2u);
  const Display fine = display(left, 1);
  EXPECT_EQ(boundaryLoops(fine.triangles).size(), 1u);
  for (int v = 0; v < offset; ++v)
    for (int w = offset; w < 2 * offset; ++w)
      if (left.vertices[v] == left.vertices[w]) {
        EXPECT_EQ(fine.normals[v], fine.normals[w]);
      }
}

TEST(DisplaySubdivision, RefusesBadInput) {
  const TriangleMesh sheet = meshes::grid(2, 2, 0.2, 0.2);
  auto make = [&](const std::vector<Triangle>& triangles, int levels) {
    return DisplaySubdivision(triangles, sheet.vertices, levels);
  };
  EXPECT_THROW(make(sheet.triangles, -1), std::invalid_argument);
  EXPECT_THROW(make({{0, 1, 99}}, 1), std::invalid_argument);
  const DisplaySubdivision layout(sheet.triangles, sheet.vertices, 1);
  std::vector<Vec3> points, normals;
  EXPECT_THROW(layout.apply({Vec3::Zero()}, points, normals), std::invalid_argument);
}
