// Rings joined into a tube: the triangle count, every directed edge used once (one
// consistently oriented piece), and the two open ends as the only edges on one triangle.
#include <gtest/gtest.h>

#include <map>
#include <utility>

#include "sim/garment/RingTube.h"

using namespace figment;

TEST(RingTube, RingsBecomeOneOrientedTubeOpenAtBothEnds) {
  const int rings = 3, columns = 5;
  TriangleMesh mesh;
  mesh.vertices.resize(rings * columns, Vec3::Zero());
  addRingTubeTriangles(mesh, rings, columns);
  ASSERT_EQ(mesh.triangles.size(), static_cast<size_t>(2 * (rings - 1) * columns));

  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  int openEdges = 0;
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << edge.first << "->" << edge.second << " is used twice: faces flip";
    if (!directed.count({edge.second, edge.first})) {
      ++openEdges;
      const bool firstRing = edge.first < columns && edge.second < columns;
      const bool lastRing = edge.first >= (rings - 1) * columns && edge.second >= (rings - 1) * columns;
      EXPECT_TRUE(firstRing || lastRing) << edge.first << "-" << edge.second << " is open inside the tube";
    }
  }
  EXPECT_EQ(openEdges, 2 * columns);
}

TEST(RingTube, OneRingMakesNoTriangles) {
  TriangleMesh mesh;
  mesh.vertices.resize(8, Vec3::Zero());
  addRingTubeTriangles(mesh, 1, 8);
  EXPECT_TRUE(mesh.triangles.empty());
}
