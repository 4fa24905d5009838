// Midpoint subdivision: four triangles for one, the surface unmoved, windings kept.
#include <gtest/gtest.h>

#include <map>

#include "sim/core/Subdivision.h"
#include "support/MeshChecks.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {
int boundaryEdges(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> use;
  for (const Triangle& t : mesh.triangles)
    for (int e = 0; e < 3; ++e) ++use[std::minmax(t[e], t[(e + 1) % 3])];
  int count = 0;
  for (const auto& [edge, n] : use) count += n == 1;
  return count;
}
}  // namespace

// A 3 x 2 grid: 12 triangles, 12 vertices, 23 edges (10 on the boundary) become 48
// triangles over 12 + 23 vertices, 20 boundary edges, the same area and orientation.
TEST(Subdivision, FourTrianglesForOneOnTheSameSurface) {
  const TriangleMesh sheet = meshes::grid(3, 2, 0.3, 0.2);
  const TriangleMesh fine = subdivided(sheet);
  EXPECT_EQ(fine.triangles.size(), 48u);
  EXPECT_EQ(fine.vertices.size(), 12u + 23u);
  EXPECT_EQ(boundaryEdges(sheet), 10);
  EXPECT_EQ(boundaryEdges(fine), 20);
  EXPECT_NEAR(surfaceArea(fine), surfaceArea(sheet), 1e-15);
  for (size_t v = 0; v < sheet.vertices.size(); ++v) EXPECT_EQ(fine.vertices[v], sheet.vertices[v]);
  for (const Triangle& t : fine.triangles) {  // every new triangle faces as the sheet does
    const Vec3 n = (fine.vertices[t[1]] - fine.vertices[t[0]]).cross(fine.vertices[t[2]] - fine.vertices[t[0]]);
    EXPECT_GT(n.z(), 0.0);
  }
}

// A closed sphere stays closed and wound outward, its new vertices on the old chords.
TEST(Subdivision, AClosedSurfaceStaysClosed) {
  const TriangleMesh ball = meshes::sphere(0.1, 12, 6);
  const TriangleMesh fine = subdivided(ball);
  EXPECT_TRUE(checks::everyEdgeSharedByTwo(fine));
  EXPECT_TRUE(checks::consistentlyOriented(fine));
  EXPECT_NEAR(checks::signedVolume(fine), checks::signedVolume(ball), 1e-12);
  EXPECT_EQ(fine.triangles.size(), 4 * ball.triangles.size());
}
