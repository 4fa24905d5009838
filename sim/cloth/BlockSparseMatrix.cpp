#include "sim/cloth/BlockSparseMatrix.h"

#include <algorithm>

#include "sim/cloth/ParallelLoops.h"

namespace figment {

BlockSparseMatrix::BlockSparseMatrix(std::vector<std::vector<int>> columns) {
  const int n = static_cast<int>(columns.size());
  diagonal_.assign(n, -1);
  for (int i = 0; i < n; ++i) {
    std::vector<int>& row = columns[i];
    row.push_back(i);  // every row has its diagonal block (mass)
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    for (int j : row) {
      if (j == i) diagonal_[i] = static_cast<int>(column_.size());
      column_.push_back(j);
    }
    rowStart_.push_back(static_cast<int>(column_.size()));
  }
  blocks_.assign(column_.size(), Block3::Zero());
}

int BlockSparseMatrix::find(int row, int column) const {
  const auto first = column_.begin() + rowStart_[row], last = column_.begin() + rowStart_[row + 1];
  const auto at = std::lower_bound(first, last, column);
  return at != last && *at == column ? static_cast<int>(at - column_.begin()) : -1;
}

void BlockSparseMatrix::multiply(const std::vector<Vec3>& x, std::vector<Vec3>& y) const {
  const int n = rows();
  y.resize(n);
#pragma omp parallel for schedule(static) if (n >= kParallelSolveNodes)
  for (int i = 0; i < n; ++i) y[i] = multiplyRow(i, x);
}

}  // namespace figment
