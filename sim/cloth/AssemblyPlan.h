#pragma once
// Deterministic parallel assembly. Each element (sim/cloth/ClothModel.h lists them)
// writes its local 3x3 blocks and node vectors into slots of its own, in parallel with
// the others; the plan then sums, for each matrix block and each node, the slots that
// belong there, in one fixed order (by slot index). No two threads ever add into the
// same place, so the result is the same, bit for bit, whatever the thread count.

#include <vector>

#include "sim/cloth/BlockSparseMatrix.h"

namespace figment {

class AssemblyPlan {
 public:
  AssemblyPlan() = default;
  // `elementNodes[e]`: the nodes of element e (its local order), each < nodes. Elements
  // with withBlocks[e] == 0 write node vectors only (no blocks, no matrix pattern);
  // an empty withBlocks: every element has blocks.
  AssemblyPlan(int nodes, const std::vector<std::vector<int>>& elementNodes, const std::vector<char>& withBlocks = {});

  // Element e's local block (a, b) lives at blockOffset(e) + a k + b (k: its node count),
  // its local vector a at vectorOffset(e) + a.
  int blockOffset(int e) const { return blockOffset_[e]; }
  int vectorOffset(int e) const { return vectorOffset_[e]; }
  int blockSlots() const { return blockOffset_.back(); }
  int vectorSlots() const { return vectorOffset_.back(); }

  // A matrix with the elements' pattern (every block zero).
  const BlockSparseMatrix& pattern() const { return pattern_; }
  // A(i, j) = the sum of its slots, plus diagonal[i] I on the diagonal.
  void gatherBlocks(const std::vector<Block3>& slots, const std::vector<double>& diagonal, BlockSparseMatrix& A) const;
  // out[i] = the sum of node i's vector slots.
  void gatherVectors(const std::vector<Vec3>& slots, std::vector<Vec3>& out) const;

 private:
  BlockSparseMatrix pattern_;
  std::vector<int> blockOffset_{0}, vectorOffset_{0};
  std::vector<int> blockSourceStart_, blockSource_;    // per matrix block, its slots
  std::vector<int> vectorSourceStart_, vectorSource_;  // per node, its slots
};

}  // namespace figment
