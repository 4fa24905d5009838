#include "sim/cloth/implicit/FilteredPcg.h"

#include "sim/cloth/implicit/ParallelLoops.h"

#include <algorithm>

namespace figment {

namespace {
constexpr int kChunk = 256;  // nodes per partial sum of a dot product
}

void NodeFilter::reset(size_t nodes) {
  kind.assign(nodes, Free);
  normal.assign(nodes, Vec3::Zero());
  prescribed.assign(nodes, Vec3::Zero());
}

double FilteredPcg::dot(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  const int n = static_cast<int>(a.size());
  const int chunks = (n + kChunk - 1) / kChunk;
  partial_.resize(chunks);
#pragma omp parallel for schedule(static) if (n >= kParallelSolveNodes)
  for (int k = 0; k < chunks; ++k) {
    double sum = 0.0;
    for (int i = k * kChunk; i < std::min(n, (k + 1) * kChunk); ++i) sum += a[i].dot(b[i]);
    partial_[k] = sum;
  }
  double total = 0.0;
  for (double p : partial_) total += p;
  return total;
}

void FilteredPcg::precondition(const NodeFilter& filter, const std::vector<Vec3>& r, std::vector<Vec3>& s) const {
  const int n = static_cast<int>(r.size());
#pragma omp parallel for schedule(static) if (n >= kParallelSolveNodes)
  for (int i = 0; i < n; ++i) s[i] = filter.apply(i, inverseDiagonal_[i] * filter.apply(i, r[i]));
}

PcgReport FilteredPcg::solve(const BlockSparseMatrix& A, const std::vector<Vec3>& b, const NodeFilter& filter,
                             const PcgStop& stop, std::vector<Vec3>& y, bool warmStart) {
  const int n = A.rows();
  inverseDiagonal_.resize(n);
  r_.resize(n), c_.resize(n), q_.resize(n), s_.resize(n);
  for (int i = 0; i < n; ++i) {
    const Block3& D = A.diagonal(i);
    inverseDiagonal_[i] = D.determinant() > 0.0 ? Block3(D.inverse()) : Block3(Block3::Zero());
  }
  if (warmStart && y.size() == static_cast<size_t>(n)) {
    for (int i = 0; i < n; ++i) y[i] = filter.prescribed[i] + filter.apply(i, y[i]);
  } else {
    y = filter.prescribed;
  }
  A.multiply(y, q_);
  for (int i = 0; i < n; ++i) r_[i] = filter.apply(i, b[i] - q_[i]);
  for (int i = 0; i < n; ++i) q_[i] = filter.apply(i, b[i]);
  precondition(filter, q_, s_);
  const double target = std::max(stop.relative * stop.relative * dot(q_, s_), stop.absolute);
  precondition(filter, r_, c_);
  double delta = dot(r_, c_);
  PcgReport report;
  while (delta > target && report.iterations < stop.maxIterations) {
    A.multiply(c_, q_);
    for (int i = 0; i < n; ++i) q_[i] = filter.apply(i, q_[i]);
    const double curvature = dot(c_, q_);
    if (!(curvature > 0.0)) break;
    const double alpha = delta / curvature;
    for (int i = 0; i < n; ++i) y[i] += alpha * c_[i], r_[i] -= alpha * q_[i];
    precondition(filter, r_, s_);
    const double next = dot(r_, s_);
    for (int i = 0; i < n; ++i) c_[i] = s_[i] + (next / delta) * c_[i];
    delta = next;
    ++report.iterations;
  }
  report.converged = delta <= target;
  return report;
}

}  // namespace figment
