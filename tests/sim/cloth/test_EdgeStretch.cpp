// The garment's edges against their rest lengths: what the drape verdict's tear bound
// and the implicit step control read.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sim/cloth/EdgeStretch.h"

using namespace figment;

namespace {
// Two right triangles sharing the diagonal 1-2 of a unit square: five edges, the
// diagonal sqrt(2) long.
TriangleMesh unitSquare() {
  TriangleMesh mesh;
  mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
  mesh.triangles = {{0, 1, 2}, {2, 1, 3}};
  return mesh;
}
}  // namespace

TEST(EdgeStretch, CountsEachSharedEdgeOnceAndLeavesOutZeroLengthOnes) {
  EXPECT_EQ(EdgeStretch(unitSquare()).edgeCount(), 5u);
  TriangleMesh withDuplicate = unitSquare();
  withDuplicate.vertices.push_back(Vec3(1, 1, 0));  // 4: where 3 is
  withDuplicate.triangles.push_back({3, 4, 1});
  EXPECT_EQ(EdgeStretch(withDuplicate).edgeCount(), 6u);  // 3-4 has no length; 4-1 is new
  EXPECT_EQ(EdgeStretch().edgeCount(), 0u);
}

TEST(EdgeStretch, LargestIsOneAtRestAndTheMostStretchedEdgesRatio) {
  const TriangleMesh mesh = unitSquare();
  const EdgeStretch edges(mesh);
  EXPECT_DOUBLE_EQ(edges.largest(mesh.vertices), 1.0);
  std::vector<Vec3> x = mesh.vertices;
  x[3] = Vec3(1, 3, 0);  // 1-3 from 1 to 3; 2-3 from 1 to sqrt(5)
  EXPECT_DOUBLE_EQ(edges.largest(x), 3.0);
  // A uniform scale stretches every edge alike.
  x = mesh.vertices;
  for (Vec3& p : x) p *= 1.25;
  EXPECT_DOUBLE_EQ(edges.largest(x), 1.25);
  EXPECT_DOUBLE_EQ(EdgeStretch().largest(x), 1.0);
}

TEST(EdgeStretch, AJumpNeedsBothTheBoundAndTheGrowth) {
  const TriangleMesh mesh = unitSquare();
  const EdgeStretch edges(mesh);
  std::vector<Vec3> grown = mesh.vertices, further = mesh.vertices;
  grown[3] = Vec3(1, 2.2, 0);    // 1-3: 1 -> 2.2, grown by 1.2, past 1.5
  further[3] = Vec3(1, 2.5, 0);  // from `grown`: 2.2 -> 2.5, past 1.5 but grown by 0.3
  EXPECT_TRUE(edges.jumped(mesh.vertices, grown, 1.5, 1.0));
  EXPECT_FALSE(edges.jumped(grown, further, 1.5, 1.0));        // stretched, but not in this step
  EXPECT_FALSE(edges.jumped(mesh.vertices, grown, 2.5, 1.0));  // grown, but within the bound
  EXPECT_FALSE(edges.jumped(mesh.vertices, mesh.vertices, 1.5, 1.0));
  std::vector<Vec3> lost = mesh.vertices;
  lost[0].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(edges.jumped(mesh.vertices, lost, 1.5, 1.0));  // not finite: failed, whatever the bound
}
