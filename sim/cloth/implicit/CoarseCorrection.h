#pragma once
// The coarse part of a two-level preconditioner for the filtered conjugate gradients
// (FilteredPcg.h). Block Jacobi sees one node at a time, so the garment's smooth
// motions, where the stiff membrane moves whole regions together, take most of the
// iterations (about sqrt(dt^2 k / m) of them). The nodes are grouped once into
// aggregates (a node and its free neighbours in the matrix's graph, about 7 nodes);
// each aggregate may translate as a whole, filtered by its nodes' constraints:
//
//   prolongation P: (aggregate a, axis d) -> S_i e_d at each node i of a
//   coarse matrix   A_c = P^T A P          (3x3 blocks between neighbouring aggregates)
//   correction      z  += P A_c^-1 P^T r   (added to block Jacobi's z: additive,
//                                          symmetric and positive definite)
//
// A_c is built and factored (sparse LDL^T, Eigen) once per solve; its pattern once.

#include <Eigen/SparseCholesky>
#include <vector>

#include "sim/cloth/BlockSparseMatrix.h"
#include "sim/cloth/implicit/NodeFilter.h"

namespace figment {

class CoarseCorrection {
 public:
  CoarseCorrection() = default;
  // Aggregates from the matrix's pattern (its rows' columns).
  explicit CoarseCorrection(const BlockSparseMatrix& pattern);

  int aggregates() const { return static_cast<int>(members_.size()); }
  // A_c for this matrix and filter, factored.
  void prepare(const BlockSparseMatrix& A, const NodeFilter& filter);
  // rc[a] = sum over a's nodes of S_i r_i (r filtered already: S_i r_i = r_i).
  void restrictTo(int aggregate, const std::vector<Vec3>& r, std::vector<Vec3>& rc) const;
  // ec = A_c^-1 rc.
  void solve(const std::vector<Vec3>& rc, std::vector<Vec3>& ec);
  int aggregateOf(int node) const { return aggregate_[node]; }

 private:
  std::vector<int> aggregate_;             // per node
  std::vector<std::vector<int>> members_;  // per aggregate, its nodes
  Eigen::SparseMatrix<double> coarse_;     // 3 aggregates() square
  std::vector<int> coarseBlockOf_;         // per fine block: its coarse (row, column) pair's index
  std::vector<std::pair<int, int>> coarseBlocks_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor_;
  bool analysed_ = false;
  Eigen::VectorXd rhs_, answer_;
};

}  // namespace figment
