// The decimation's connectivity on a literal strip of two quads (four triangles, six vertices):
// rings, edge faces, the boundary, and what one collapse removes and re-points.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "sim/progressive/CollapseNeighbourhood.h"

using namespace figment;

namespace {

// 0 - 1 - 2
// | / | / |      triangles (0 4 1) (0 3 4) (1 5 2) (1 4 5)
// 3 - 4 - 5
TriangleMesh strip() {
  TriangleMesh mesh;
  mesh.vertices = {{0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  mesh.triangles = {{0, 4, 1}, {0, 3, 4}, {1, 5, 2}, {1, 4, 5}};
  return mesh;
}

std::vector<int> sorted(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  return v;
}

TEST(CollapseNeighbourhood, RingsEdgesAndTheBoundaryOfTheStrip) {
  const CollapseNeighbourhood mesh(strip());
  EXPECT_EQ(mesh.activeFaces(), 4);
  EXPECT_EQ(sorted(mesh.ring(4)), (std::vector<int>{0, 1, 3, 5}));
  EXPECT_EQ(sorted(mesh.edgeFaces(1, 4)), (std::vector<int>{0, 3}));  // the inner edge
  EXPECT_FALSE(mesh.boundaryEdge(1, 4));
  EXPECT_TRUE(mesh.boundaryEdge(0, 1));
  EXPECT_TRUE(mesh.edgeFaces(0, 5).empty());
  EXPECT_TRUE(mesh.boundaryVertex(4));  // every vertex of a strip is on its edge
}

TEST(CollapseNeighbourhood, ACollapseRemovesTheEdgesFacesAndRepointsTheRest) {
  CollapseNeighbourhood mesh(strip());
  const std::vector<int> repointed = mesh.collapse(4, 1, Vec3(1, 0.5, 0));  // edge 1-4 into its midpoint
  EXPECT_EQ(mesh.activeFaces(), 2);                                         // faces 0 and 3 held the edge
  EXPECT_FALSE(mesh.active(1));
  EXPECT_TRUE(mesh.active(4));
  EXPECT_EQ(mesh.rest(4), Vec3(1, 0.5, 0));
  EXPECT_EQ(repointed, (std::vector<int>{2}));  // (1 5 2) now (4 5 2)
  EXPECT_EQ(mesh.corners(2), (Triangle{4, 5, 2}));
  EXPECT_EQ(sorted(mesh.faces(4)), (std::vector<int>{1, 2}));
  EXPECT_EQ(sorted(mesh.ring(4)), (std::vector<int>{0, 2, 3, 5}));
}

}  // namespace
