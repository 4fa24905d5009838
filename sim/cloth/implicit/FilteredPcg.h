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

#include "sim/cloth/implicit/BlockSparseMatrix.h"

#include <vector>

namespace figment {

struct NodeFilter {
  enum Kind : char { Free, Sliding, Fixed };
  std::vector<char> kind;      // per node
  std::vector<Vec3> normal;    // per node, unit: the constrained direction of a Sliding node
  std::vector<Vec3> prescribed;  // z per node: Sliding along normal, Fixed any; Free zero

  void reset(size_t nodes);
  Vec3 apply(int i, const Vec3& v) const {
    switch (kind[i]) {
      case Free: return v;
      case Sliding: return v - normal[i].dot(v) * normal[i];
      default: return Vec3::Zero();
    }
  }
};

struct PcgStop {
  double relative = 1e-2;
  int maxIterations = 300;
};

struct PcgReport {
  int iterations = 0;
  bool converged = false;
};

class FilteredPcg {
 public:
  // Solves for y (resized). The iterations start from the prescribed part, plus y's
  // free part when warmStart (y then holds a guess of the answer).
  PcgReport solve(const BlockSparseMatrix& A, const std::vector<Vec3>& b, const NodeFilter& filter,
                  const PcgStop& stop, std::vector<Vec3>& y, bool warmStart = false);

 private:
  // The preconditioner, the starting point y, residual r and direction c, and the sums
  // the loop starts from.
  void prepare(const BlockSparseMatrix& A, const std::vector<Vec3>& b, const NodeFilter& filter,
               std::vector<Vec3>& y, bool warmStart);
  Vec3 precondition(const NodeFilter& filter, int i, const Vec3& r) const {
    return filter.apply(i, inverseDiagonal_[i] * filter.apply(i, r));
  }

  std::vector<Block3> inverseDiagonal_;
  std::vector<Vec3> r_, c_, q_, s_;
  double delta_ = 0.0, bScaled_ = 0.0;  // r^T P^-1 r and (S b)^T P^-1 (S b) at the start
  std::vector<double> curvaturePartial_, deltaPartial_;
};

}  // namespace figment
