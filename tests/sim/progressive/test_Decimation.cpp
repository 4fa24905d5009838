// Decimation by edge collapses and its inverse, the vertex splits: replaying every split
// gives back the garment exactly, no level folds over, the perimeter stays the perimeter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "sim/progressive/Decimation.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {
// Each edge with the number of faces holding it.
std::map<std::pair<int, int>, int> edgeUse(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> use;
  for (const Triangle& t : mesh.triangles)
    for (int e = 0; e < 3; ++e) ++use[{std::min(t[e], t[(e + 1) % 3]), std::max(t[e], t[(e + 1) % 3])}];
  return use;
}

std::set<int> boundaryVertices(const TriangleMesh& mesh) {
  std::set<int> out;
  for (const auto& [edge, count] : edgeUse(mesh))
    if (count == 1) out.insert(edge.first), out.insert(edge.second);
  return out;
}

Vec3 normalOf(const TriangleMesh& mesh, const Triangle& t) {
  const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
  return (b - a).cross(c - a);
}
}  // namespace

TEST(Decimation, ReplayingEverySplitGivesBackTheGarmentExactly) {
  const TriangleMesh sheet = meshes::curvedSheet();
  const ProgressiveMesh pm = decimate(sheet, DecimationOptions{.targetFaces = 60});
  MeshLevel level(pm);
  EXPECT_LE(level.activeFaces(), 80);
  EXPECT_GT(pm.levels(), 300);
  level.splitTo(pm.levels());
  std::vector<int> fullIndex;
  const TriangleMesh back = level.restMesh(fullIndex);
  ASSERT_EQ(back.vertices.size(), sheet.vertices.size());
  ASSERT_EQ(back.triangles.size(), sheet.triangles.size());
  for (size_t v = 0; v < sheet.vertices.size(); ++v) {
    EXPECT_EQ(fullIndex[v], static_cast<int>(v));
    EXPECT_EQ(back.vertices[v], sheet.vertices[v]) << "vertex " << v;
  }
  for (size_t f = 0; f < sheet.triangles.size(); ++f) EXPECT_EQ(back.triangles[f], sheet.triangles[f]) << "face " << f;
}

TEST(Decimation, NoLevelFoldsOverOrLeavesTheManifold) {
  const TriangleMesh sheet = meshes::curvedSheet();
  const ProgressiveMesh pm = decimate(sheet, DecimationOptions{.targetFaces = 60});
  MeshLevel level(pm);
  for (int k = 0; k <= pm.levels(); k += 7) {
    level.splitTo(k);
    std::vector<int> fullIndex;
    const TriangleMesh mesh = level.restMesh(fullIndex);
    int f = 0;
    for (size_t face = 0; face < sheet.triangles.size(); ++face) {
      if (!level.faceActive(static_cast<int>(face))) continue;
      const Vec3 now = normalOf(mesh, mesh.triangles[f++]), original = normalOf(sheet, sheet.triangles[face]);
      ASSERT_GT(now.normalized().dot(original.normalized()), std::cos(45.0 * M_PI / 180.0) - 1e-9)
          << "level " << k << ", face " << face;
    }
    for (const auto& [edge, count] : edgeUse(mesh)) ASSERT_LE(count, 2) << "level " << k;
  }
}

TEST(Decimation, ThePerimeterStaysThePerimeter) {
  // Every vertex on a level's boundary is one of the garment's boundary vertices, at its
  // own rest position, and the coarsest level still spans the sheet's four corners.
  const TriangleMesh sheet = meshes::curvedSheet();
  const std::set<int> original = boundaryVertices(sheet);
  const ProgressiveMesh pm = decimate(sheet, DecimationOptions{.targetFaces = 60});
  MeshLevel level(pm);
  for (int k = 0; k <= pm.levels(); k += 11) {
    level.splitTo(k);
    std::vector<int> fullIndex;
    const TriangleMesh mesh = level.restMesh(fullIndex);
    for (int v : boundaryVertices(mesh)) {
      ASSERT_TRUE(original.count(fullIndex[v])) << "level " << k << ", vertex " << fullIndex[v];
      // On the original perimeter's line: x at +-0.2 or y at +-0.15.
      const Vec3& x = mesh.vertices[v];
      ASSERT_LT(std::min(std::abs(std::abs(x.x()) - 0.2), std::abs(std::abs(x.y()) - 0.15)), 1e-12) << "level " << k;
    }
  }
  const MeshLevel coarsest(pm);
  std::vector<int> fullIndex;
  const Bounds box = boundsOf(coarsest.restMesh(fullIndex).vertices);
  EXPECT_NEAR(box.size().x(), 0.4, 1e-12);
  EXPECT_NEAR(box.size().y(), 0.3, 1e-12);
}

TEST(Decimation, FlatRegionsCoarsenEvenly) {
  // The homogeneity term: on a flat sheet at a quarter of its sections, the largest
  // section is at most 6 times the smallest (without it, QEM leaves any order).
  const TriangleMesh flat = meshes::grid(24, 24, 0.4, 0.4);
  const ProgressiveMesh pm = decimate(flat, DecimationOptions{.targetFaces = 288});
  MeshLevel level(pm);
  std::vector<int> fullIndex;
  const TriangleMesh mesh = level.restMesh(fullIndex);
  double smallest = 1.0, largest = 0.0;
  for (const Triangle& t : mesh.triangles) {
    const double area = 0.5 * normalOf(mesh, t).norm();
    smallest = std::min(smallest, area), largest = std::max(largest, area);
  }
  EXPECT_LT(largest / smallest, 6.0);
}
