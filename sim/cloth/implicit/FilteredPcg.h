#pragma once
// Conjugate gradients with constraints, after Baraff & Witkin, "Large steps in cloth
// simulation" (SIGGRAPH 1998), section 5.3: solve A y = b for the nodes' velocity
// changes where some nodes are constrained. Each node's filter S_i projects onto the
// directions it is free to move in: I (free), I - n n^T (held on a surface of normal n),
// 0 (pinned). The answer is y = z + w with z the prescribed part (in the constrained
// directions) and w = S w solving S (A (z + w) - b) = 0.
//
// Preconditioner: the inverse of A's 3x3 diagonal blocks, filtered on both sides
// (S P^-1 S: symmetric, positive definite on the free directions). Stops when
// r^T P^-1 r <= relative^2 (S b)^T P^-1 (S b), or after maxIterations. (A floor on
// the residual, to end the near-rest steps early, was tried and left out: where the
// membrane's stiffness dominates P a small r^T P^-1 r does not mean a small error in
// the garment's smooth motions, and a floor low enough to keep a slow slide on an
// incline never acted on the default dress.)
// The iterations run in one parallel region, rows split among the threads; the dot
// products are summed over fixed chunks in a fixed order, so the result does not
// depend on the thread count.

#include <memory>
#include <vector>

#include "sim/cloth/implicit/CoarseCorrection.h"

namespace figment {

struct PcgStop {
  double relative = 1e-2;
  int maxIterations = 300;
};

struct PcgReport {
  int iterations = 0;
  bool converged = false;
};

// Where a solve's iterations start (its prescribed part is always the filter's).
enum class PcgStart {
  Zero,   // the free part zero
  Again,  // y's free part: y holds the answer of this matrix's last solve, the filter
          // changed since at a few nodes
  // y's free part g = S y scaled by alpha = g^T S (b - A z) / g^T A g, the factor that
  // leaves the least error energy along g: y holds a guess from a nearby system (the
  // last step's velocity change), and the start is never worse than Zero's in the
  // A-norm, however poor the guess.
  Guess,
};

// The coarse matrix a two-level solve applies.
enum class CoarseMatrix {
  Build,  // built from this A and filter, and factored
  // The last one built (Build when there is none): any positive definite coarse matrix
  // keeps the preconditioner symmetric positive definite on the free directions, so a
  // solve still converges to the same stop, in more iterations the farther A or the
  // filter moved on since (a friction re-solve of the same A keeps it).
  Keep,
};

class FilteredPcg {
 public:
  // Block Jacobi alone.
  FilteredPcg() = default;
  // Block Jacobi plus a coarse correction over aggregates of the pattern's nodes
  // (CoarseCorrection.h): the two-level preconditioner.
  explicit FilteredPcg(const BlockSparseMatrix& pattern);
  ~FilteredPcg();
  FilteredPcg(FilteredPcg&&) noexcept;
  FilteredPcg& operator=(FilteredPcg&&) noexcept;

  // Solves for y (resized), starting as `start` says from the prescribed part and y.
  // The stop is relative to S b, whatever the start: a warm start saves iterations, it
  // does not loosen the answer.
  PcgReport solve(const BlockSparseMatrix& A, const std::vector<Vec3>& b, const NodeFilter& filter, const PcgStop& stop,
                  std::vector<Vec3>& y, PcgStart start = PcgStart::Zero, CoarseMatrix coarse = CoarseMatrix::Build);

 private:
  // The preconditioner, the starting point y, residual r and direction c, and the sums
  // the loop starts from.
  void prepare(const BlockSparseMatrix& A, const std::vector<Vec3>& b, const NodeFilter& filter, std::vector<Vec3>& y,
               PcgStart start, CoarseMatrix coarse);
  // y = z + alpha S y (PcgStart::Guess); r_ = S (b - A y).
  void startFromGuess(const BlockSparseMatrix& A, const std::vector<Vec3>& b, const NodeFilter& filter,
                      std::vector<Vec3>& y);
  // Node i of P^-1 r, after applyCoarse(r) (two levels: its coarse part).
  Vec3 precondition(const NodeFilter& filter, int i, const Vec3& r) const {
    const Vec3 jacobi = filter.apply(i, inverseDiagonal_[i] * filter.apply(i, r));
    return coarse_ ? Vec3(jacobi + filter.apply(i, coarseCorrection_[coarse_->aggregateOf(i)])) : jacobi;
  }
  // The coarse correction of r (one thread).
  void applyCoarse(const std::vector<Vec3>& r);

  std::vector<Block3> inverseDiagonal_;
  std::vector<Vec3> r_, c_, q_, s_;
  double delta_ = 0.0, bScaled_ = 0.0;  // r^T P^-1 r and (S b)^T P^-1 (S b) at the start
  std::vector<double> curvaturePartial_, deltaPartial_;
  std::unique_ptr<CoarseCorrection> coarse_;
  bool coarseBuilt_ = false;
  std::vector<Vec3> coarseResidual_, coarseCorrection_;  // per aggregate
};

}  // namespace figment
