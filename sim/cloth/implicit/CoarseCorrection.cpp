#include "sim/cloth/implicit/CoarseCorrection.h"

#include <algorithm>
#include <map>

namespace figment {

namespace {
// A_c's diagonal gets this share of its mean added: an aggregate whose nodes are all
// fixed (or slide on one plane) leaves its block singular; the residual it restricts is
// zero in those directions, so the small shift only keeps the factorisation defined.
constexpr double kShift = 1e-9;
}  // namespace

CoarseCorrection::CoarseCorrection(const BlockSparseMatrix& pattern) {
  const int n = pattern.rows();
  aggregate_.assign(n, -1);
  // Greedy, in node order (deterministic): an unassigned node and its unassigned
  // neighbours start an aggregate; nodes left over join a neighbour's.
  for (int i = 0; i < n; ++i) {
    if (aggregate_[i] >= 0) continue;
    bool neighbourTaken = false;
    for (int k = pattern.rowStart(i); k < pattern.rowStart(i + 1); ++k)
      neighbourTaken |= aggregate_[pattern.column(k)] >= 0;
    if (neighbourTaken) continue;
    const int a = static_cast<int>(members_.size());
    members_.emplace_back();
    for (int k = pattern.rowStart(i); k < pattern.rowStart(i + 1); ++k) aggregate_[pattern.column(k)] = a;
  }
  for (int i = 0; i < n; ++i) {
    if (aggregate_[i] >= 0) continue;
    for (int k = pattern.rowStart(i); k < pattern.rowStart(i + 1) && aggregate_[i] < 0; ++k)
      aggregate_[i] = aggregate_[pattern.column(k)];
    if (aggregate_[i] < 0) {  // a node of its own (no assigned neighbour)
      aggregate_[i] = static_cast<int>(members_.size());
      members_.emplace_back();
    }
  }
  for (int i = 0; i < n; ++i) members_[aggregate_[i]].push_back(i);
  // The coarse pattern: one block per pair of aggregates joined by a fine block.
  std::map<std::pair<int, int>, int> index;
  for (int i = 0; i < n; ++i)
    for (int k = pattern.rowStart(i); k < pattern.rowStart(i + 1); ++k) {
      const std::pair<int, int> pair(aggregate_[i], aggregate_[pattern.column(k)]);
      const auto [at, added] = index.emplace(pair, static_cast<int>(coarseBlocks_.size()));
      if (added) coarseBlocks_.push_back(pair);
      coarseBlockOf_.push_back(at->second);
    }
}

void CoarseCorrection::prepare(const BlockSparseMatrix& A, const NodeFilter& filter) {
  std::vector<Block3> blocks(coarseBlocks_.size(), Block3::Zero());
  const int n = A.rows();
  for (int i = 0; i < n; ++i)
    for (int k = A.rowStart(i); k < A.rowStart(i + 1); ++k) {
      const int j = A.column(k);
      if (filter.kind[i] == NodeFilter::Free && filter.kind[j] == NodeFilter::Free) {
        blocks[coarseBlockOf_[k]] += A.block(k);
        continue;
      }
      Block3 filtered = A.block(k);
      for (int c = 0; c < 3; ++c) filtered.col(c) = filter.apply(i, filtered.col(c));
      for (int r = 0; r < 3; ++r) filtered.row(r) = filter.apply(j, filtered.row(r).transpose()).transpose();
      blocks[coarseBlockOf_[k]] += filtered;
    }
  const int size = 3 * aggregates();
  double meanDiagonal = 0.0;
  std::vector<Eigen::Triplet<double>> entries;
  for (size_t b = 0; b < blocks.size(); ++b) {
    const auto [row, column] = coarseBlocks_[b];
    if (row == column) meanDiagonal += blocks[b].trace();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) entries.emplace_back(3 * row + r, 3 * column + c, blocks[b](r, c));
  }
  meanDiagonal = std::max(meanDiagonal / size, 1e-300);
  for (int d = 0; d < size; ++d) entries.emplace_back(d, d, kShift * meanDiagonal);
  coarse_.resize(size, size);
  coarse_.setFromTriplets(entries.begin(), entries.end());
  if (!analysed_) factor_.analyzePattern(coarse_), analysed_ = true;
  factor_.factorize(coarse_);
}

void CoarseCorrection::restrictTo(int aggregate, const std::vector<Vec3>& r, std::vector<Vec3>& rc) const {
  Vec3 sum = Vec3::Zero();
  for (int i : members_[aggregate]) sum += r[i];
  rc[aggregate] = sum;
}

void CoarseCorrection::solve(const std::vector<Vec3>& rc, std::vector<Vec3>& ec) {
  const int m = aggregates();
  rhs_.resize(3 * m);
  for (int a = 0; a < m; ++a) rhs_.segment<3>(3 * a) = rc[a];
  answer_ = factor_.solve(rhs_);
  ec.resize(m);
  for (int a = 0; a < m; ++a) ec[a] = answer_.segment<3>(3 * a);
}

}  // namespace figment
