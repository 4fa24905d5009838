#pragma once
// A sparse matrix of 3x3 blocks over the cloth's nodes (row i, column j: how node j's
// motion acts on node i), stored by rows (block CSR) with both triangles of a symmetric
// matrix, so that a product runs row by row in parallel and each row's sum has one
// fixed order whatever the thread count.

#include <Eigen/Core>
#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

using Block3 = Eigen::Matrix3d;

class BlockSparseMatrix {
 public:
  BlockSparseMatrix() = default;
  // `columns[i]`: the columns of row i's blocks, each once, in any order (sorted here).
  explicit BlockSparseMatrix(std::vector<std::vector<int>> columns);

  int rows() const { return static_cast<int>(rowStart_.size()) - 1; }
  size_t blockCount() const { return blocks_.size(); }
  // The index of block (row, column) among blockCount(), or -1 where there is none.
  int find(int row, int column) const;
  int rowStart(int row) const { return rowStart_[row]; }
  int column(int k) const { return column_[k]; }
  Block3& block(int k) { return blocks_[k]; }
  const Block3& block(int k) const { return blocks_[k]; }
  const Block3& diagonal(int row) const { return blocks_[diagonal_[row]]; }

  // y = A x, rows in parallel (OpenMP).
  void multiply(const std::vector<Vec3>& x, std::vector<Vec3>& y) const;
  // Row i of A x.
  Vec3 multiplyRow(int i, const std::vector<Vec3>& x) const {
    Vec3 sum = Vec3::Zero();
    for (int k = rowStart_[i]; k < rowStart_[i + 1]; ++k) sum.noalias() += blocks_[k] * x[column_[k]];
    return sum;
  }

 private:
  std::vector<int> rowStart_{0}, column_, diagonal_;
  std::vector<Block3> blocks_;
};

}  // namespace figment
