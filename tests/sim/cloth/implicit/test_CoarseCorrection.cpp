// The two-level preconditioner's coarse part on a chain of six nodes: its aggregates (a node
// and its free neighbours, greedily in node order), the restriction as sums over them, and the
// coarse solve, which for the identity matrix divides each aggregate's sum by its size.
#include <gtest/gtest.h>

#include <vector>

#include "sim/cloth/BlockSparseMatrix.h"
#include "sim/cloth/implicit/CoarseCorrection.h"
#include "sim/cloth/implicit/NodeFilter.h"

using namespace figment;

namespace {

// 0 - 1 - 2 - 3 - 4 - 5, each node's row holding its neighbours.
BlockSparseMatrix chain() {
  return BlockSparseMatrix({{1}, {0, 2}, {1, 3}, {2, 4}, {3, 5}, {4}});
}

TEST(CoarseCorrection, AggregatesANodeWithItsFreeNeighbours) {
  const CoarseCorrection coarse(chain());
  // 0 takes 1; 3 takes 2 and 4 (2's neighbour 1 was taken); 5 joins its neighbour 4's.
  ASSERT_EQ(coarse.aggregates(), 2);
  for (int i : {0, 1}) EXPECT_EQ(coarse.aggregateOf(i), 0) << i;
  for (int i : {2, 3, 4, 5}) EXPECT_EQ(coarse.aggregateOf(i), 1) << i;
}

TEST(CoarseCorrection, ForTheIdentityTheSolveAveragesEachAggregate) {
  BlockSparseMatrix A = chain();
  for (int i = 0; i < A.rows(); ++i) A.block(A.find(i, i)) = Block3::Identity();
  NodeFilter free;
  free.reset(6);
  CoarseCorrection coarse(A);
  coarse.prepare(A, free);
  const std::vector<Vec3> r = {{1, 0, 0}, {3, 0, 0}, {0, 4, 0}, {0, 4, 0}, {0, 0, 8}, {0, 0, 0}};
  std::vector<Vec3> rc(coarse.aggregates());
  for (int a = 0; a < coarse.aggregates(); ++a) coarse.restrictTo(a, r, rc);
  EXPECT_EQ(rc[0], Vec3(4, 0, 0));
  EXPECT_EQ(rc[1], Vec3(0, 8, 8));
  std::vector<Vec3> ec;
  coarse.solve(rc, ec);
  ASSERT_EQ(ec.size(), 2u);
  EXPECT_TRUE(ec[0].isApprox(Vec3(2, 0, 0), 1e-6)) << ec[0].transpose();  // A_c = 2 I
  EXPECT_TRUE(ec[1].isApprox(Vec3(0, 2, 2), 1e-6)) << ec[1].transpose();  // A_c = 4 I
}

}  // namespace
