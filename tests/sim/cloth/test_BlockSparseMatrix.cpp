// The block matrix's layout (each row sorted, its diagonal always there) and its product
// against the same matrix written densely.
#include <gtest/gtest.h>

#include <vector>

#include "sim/cloth/BlockSparseMatrix.h"

using namespace figment;

namespace {

TEST(BlockSparseMatrix, KeepsEachRowsColumnsOnceSortedWithItsDiagonal) {
  // Row 0 names 2 twice and not itself; row 1 nothing; row 2 names 0.
  const BlockSparseMatrix a({{2, 2}, {}, {0}});
  ASSERT_EQ(a.rows(), 3);
  EXPECT_EQ(a.blockCount(), 5u);  // (0,0) (0,2) (1,1) (2,0) (2,2)
  EXPECT_EQ(a.column(a.rowStart(0)), 0);
  EXPECT_EQ(a.column(a.rowStart(0) + 1), 2);
  EXPECT_GE(a.find(1, 1), 0);
  EXPECT_EQ(a.find(1, 0), -1);
  EXPECT_EQ(a.find(0, 1), -1);
  EXPECT_EQ(a.column(a.find(2, 0)), 0);
}

TEST(BlockSparseMatrix, ProductEqualsTheDenseOne) {
  BlockSparseMatrix a({{1}, {0, 2}, {1}});
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(9, 9);
  double value = 1;
  for (int i = 0; i < a.rows(); ++i)
    for (int k = a.rowStart(i); k < a.rowStart(i + 1); ++k) {
      Block3 block;
      block << value, 2 * value, 0, -value, 1, 3, 0.5, 0, value;
      value += 1;
      a.block(k) = block;
      dense.block<3, 3>(3 * i, 3 * a.column(k)) = block;
    }
  const std::vector<Vec3> x = {{1, 2, 3}, {-1, 0, 2}, {0.5, -2, 1}};
  Eigen::VectorXd flat(9);
  for (int i = 0; i < 3; ++i) flat.segment<3>(3 * i) = x[i];
  std::vector<Vec3> y;
  a.multiply(x, y);
  const Eigen::VectorXd expected = dense * flat;
  ASSERT_EQ(y.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(y[i].isApprox(expected.segment<3>(3 * i), 1e-14)) << i;
    EXPECT_TRUE(a.multiplyRow(i, x).isApprox(y[i], 1e-14)) << i;
  }
  EXPECT_EQ(&a.diagonal(1), &a.block(a.find(1, 1)));
}

}  // namespace
