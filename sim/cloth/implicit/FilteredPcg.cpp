#include "sim/cloth/implicit/FilteredPcg.h"

#include <algorithm>

#include "sim/cloth/ParallelLoops.h"

namespace figment {

namespace {
constexpr int kChunk = 64;  // nodes per partial sum of a dot product

int chunkEnd(int chunk, int n) {
  return std::min(n, (chunk + 1) * kChunk);
}

// The partial sums added in chunk order: every thread gets the same total, whatever
// the thread count.
double total(const std::vector<double>& partial) {
  double sum = 0.0;
  for (double p : partial) sum += p;
  return sum;
}
}  // namespace

void NodeFilter::reset(size_t nodes) {
  kind.assign(nodes, Free);
  normal.assign(nodes, Vec3::Zero());
  prescribed.assign(nodes, Vec3::Zero());
}

FilteredPcg::FilteredPcg(const BlockSparseMatrix& pattern) : coarse_(std::make_unique<CoarseCorrection>(pattern)) {}

FilteredPcg::~FilteredPcg() = default;
FilteredPcg::FilteredPcg(FilteredPcg&&) noexcept = default;
FilteredPcg& FilteredPcg::operator=(FilteredPcg&&) noexcept = default;

void FilteredPcg::prepare(const BlockSparseMatrix& A, const std::vector<Vec3>& b, const NodeFilter& filter,
                          std::vector<Vec3>& y, PcgStart start, CoarseMatrix coarse) {
  const int n = A.rows();
  inverseDiagonal_.resize(n);
  r_.resize(n), c_.resize(n), q_.resize(n), s_.resize(n);
  for (int i = 0; i < n; ++i) {
    const Block3& D = A.diagonal(i);
    inverseDiagonal_[i] = D.determinant() > 0.0 ? Block3(D.inverse()) : Block3(Block3::Zero());
  }
  const bool fromY = y.size() == static_cast<size_t>(n);
  if (start == PcgStart::Guess && fromY) {
    startFromGuess(A, b, filter, y);
  } else {
    if (start == PcgStart::Again && fromY) {
      for (int i = 0; i < n; ++i) y[i] = filter.prescribed[i] + filter.apply(i, y[i]);
    } else {
      y = filter.prescribed;
    }
    A.multiply(y, q_);
    for (int i = 0; i < n; ++i) r_[i] = filter.apply(i, b[i] - q_[i]);
  }
  for (int i = 0; i < n; ++i) s_[i] = filter.apply(i, b[i]);
  if (coarse_ && (coarse == CoarseMatrix::Build || !coarseBuilt_)) coarse_->prepare(A, filter), coarseBuilt_ = true;
  // (S b)^T P^-1 (S b), then c = P^-1 r and r^T P^-1 r.
  applyCoarse(s_);
  bScaled_ = 0.0;
  for (int i = 0; i < n; ++i) bScaled_ += s_[i].dot(precondition(filter, i, s_[i]));
  applyCoarse(r_);
  delta_ = 0.0;
  for (int i = 0; i < n; ++i) {
    c_[i] = precondition(filter, i, r_[i]);
    delta_ += r_[i].dot(c_[i]);
  }
}

void FilteredPcg::startFromGuess(const BlockSparseMatrix& A, const std::vector<Vec3>& b, const NodeFilter& filter,
                                 std::vector<Vec3>& y) {
  const int n = A.rows();
  // g = S y in c_, its product A g in s_; z in y, the residual S (b - A z) in r_.
  for (int i = 0; i < n; ++i) c_[i] = filter.apply(i, y[i]);
  A.multiply(c_, s_);
  y = filter.prescribed;
  A.multiply(y, q_);
  double along = 0.0, energy = 0.0;  // g^T S (b - A z) and g^T A g
  for (int i = 0; i < n; ++i) {
    r_[i] = filter.apply(i, b[i] - q_[i]);
    along += c_[i].dot(r_[i]);
    energy += c_[i].dot(s_[i]);
  }
  const double alpha = energy > 0.0 ? along / energy : 0.0;
  if (alpha == 0.0) return;
  for (int i = 0; i < n; ++i) {
    y[i] += alpha * c_[i];
    r_[i] -= alpha * filter.apply(i, s_[i]);
  }
}

void FilteredPcg::applyCoarse(const std::vector<Vec3>& r) {
  if (!coarse_) return;
  const int m = coarse_->aggregates();
  coarseResidual_.resize(m);
  for (int a = 0; a < m; ++a) coarse_->restrictTo(a, r, coarseResidual_);
  coarse_->solve(coarseResidual_, coarseCorrection_);
}

PcgReport FilteredPcg::solve(const BlockSparseMatrix& A, const std::vector<Vec3>& b, const NodeFilter& filter,
                             const PcgStop& stop, std::vector<Vec3>& y, PcgStart start, CoarseMatrix coarse) {
  prepare(A, b, filter, y, start, coarse);
  const int n = A.rows();
  const int chunks = (n + kChunk - 1) / kChunk;
  curvaturePartial_.assign(chunks, 0.0);
  deltaPartial_.assign(chunks, 0.0);
  const double target = stop.relative * stop.relative * bScaled_;
  PcgReport report;
  // One parallel region for the whole loop (starting threads costs about an iteration);
  // every thread runs the same iterations and takes the same decisions from the same sums.
#pragma omp parallel if (n >= kParallelSolveNodes)
  {
    double delta = delta_;
    int iterations = 0;
    while (delta > target && iterations < stop.maxIterations) {
#pragma omp for schedule(static)
      for (int k = 0; k < chunks; ++k) {  // q = S A c
        double sum = 0.0;
        for (int i = k * kChunk; i < chunkEnd(k, n); ++i) {
          q_[i] = filter.apply(i, A.multiplyRow(i, c_));
          sum += c_[i].dot(q_[i]);
        }
        curvaturePartial_[k] = sum;
      }
      const double curvature = total(curvaturePartial_);
      if (!(curvature > 0.0)) break;
      const double alpha = delta / curvature;
#pragma omp for schedule(static)
      for (int i = 0; i < n; ++i) y[i] += alpha * c_[i], r_[i] -= alpha * q_[i];
      if (coarse_) {
#pragma omp for schedule(static)
        for (int a = 0; a < coarse_->aggregates(); ++a) coarse_->restrictTo(a, r_, coarseResidual_);
#pragma omp single
        coarse_->solve(coarseResidual_, coarseCorrection_);
      }
#pragma omp for schedule(static)
      for (int k = 0; k < chunks; ++k) {
        double sum = 0.0;
        for (int i = k * kChunk; i < chunkEnd(k, n); ++i) {
          s_[i] = precondition(filter, i, r_[i]);
          sum += r_[i].dot(s_[i]);
        }
        deltaPartial_[k] = sum;
      }
      const double next = total(deltaPartial_);
#pragma omp for schedule(static)
      for (int i = 0; i < n; ++i) c_[i] = s_[i] + (next / delta) * c_[i];
      delta = next;
      ++iterations;
    }
#pragma omp single
    {
      report.iterations = iterations;
      report.converged = delta <= target;
    }
  }
  return report;
}

}  // namespace figment
