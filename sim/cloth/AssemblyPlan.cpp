#include "sim/cloth/AssemblyPlan.h"

namespace figment {

namespace {
// Compressed lists: targets[s] for each source s -> for each target, its sources in
// increasing order (a counting sort, so the order is fixed).
void invert(const std::vector<int>& targets, int targetCount, std::vector<int>& start, std::vector<int>& sources) {
  start.assign(targetCount + 1, 0);
  for (int t : targets) ++start[t + 1];
  for (int t = 0; t < targetCount; ++t) start[t + 1] += start[t];
  sources.assign(targets.size(), 0);
  std::vector<int> next(start.begin(), start.end() - 1);
  for (int s = 0; s < static_cast<int>(targets.size()); ++s) sources[next[targets[s]]++] = s;
}
}  // namespace

AssemblyPlan::AssemblyPlan(int nodes, const std::vector<std::vector<int>>& elementNodes,
                           const std::vector<char>& withBlocks) {
  const auto hasBlocks = [&](size_t e) { return withBlocks.empty() || withBlocks[e]; };
  std::vector<std::vector<int>> columns(nodes);
  for (size_t e = 0; e < elementNodes.size(); ++e)
    if (hasBlocks(e))
      for (int i : elementNodes[e]) columns[i].insert(columns[i].end(), elementNodes[e].begin(), elementNodes[e].end());
  pattern_ = BlockSparseMatrix(std::move(columns));
  std::vector<int> blockTarget, vectorTarget;
  for (size_t e = 0; e < elementNodes.size(); ++e) {
    const std::vector<int>& element = elementNodes[e];
    const int k = static_cast<int>(element.size());
    const int blocks = hasBlocks(e) ? k : 0;
    for (int a = 0; a < k; ++a) {
      vectorTarget.push_back(element[a]);
      for (int b = 0; b < blocks; ++b) blockTarget.push_back(pattern_.find(element[a], element[b]));
    }
    blockOffset_.push_back(blockOffset_.back() + blocks * blocks);
    vectorOffset_.push_back(vectorOffset_.back() + k);
  }
  invert(blockTarget, static_cast<int>(pattern_.blockCount()), blockSourceStart_, blockSource_);
  invert(vectorTarget, nodes, vectorSourceStart_, vectorSource_);
}

void AssemblyPlan::gatherBlocks(const std::vector<Block3>& slots, const std::vector<double>& diagonal,
                                BlockSparseMatrix& A) const {
  const int n = pattern_.rows();
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i)
    for (int k = pattern_.rowStart(i); k < pattern_.rowStart(i + 1); ++k) {
      Block3 sum = pattern_.column(k) == i ? Block3(diagonal[i] * Block3::Identity()) : Block3(Block3::Zero());
      for (int s = blockSourceStart_[k]; s < blockSourceStart_[k + 1]; ++s) sum += slots[blockSource_[s]];
      A.block(k) = sum;
    }
}

void AssemblyPlan::gatherVectors(const std::vector<Vec3>& slots, std::vector<Vec3>& out) const {
  const int n = pattern_.rows();
  out.resize(n);
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    Vec3 sum = Vec3::Zero();
    for (int s = vectorSourceStart_[i]; s < vectorSourceStart_[i + 1]; ++s) sum += slots[vectorSource_[s]];
    out[i] = sum;
  }
}

}  // namespace figment
