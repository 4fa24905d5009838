// The assembly of two edge elements sharing a node: slots laid out element by element, each
// block and node vector the sum of its slots, the diagonal's mass added.
#include <gtest/gtest.h>

#include <vector>

#include "sim/cloth/AssemblyPlan.h"

using namespace figment;

namespace {

// Elements (0 1) and (1 2): node 1 is shared. A third, vector-only element (2) has no blocks.
const std::vector<std::vector<int>> kElements = {{0, 1}, {1, 2}, {2}};
const std::vector<char> kWithBlocks = {1, 1, 0};

TEST(AssemblyPlan, LaysOutEachElementsSlotsInTurn) {
  const AssemblyPlan plan(3, kElements, kWithBlocks);
  EXPECT_EQ(plan.blockOffset(0), 0);
  EXPECT_EQ(plan.blockOffset(1), 4);  // 2 x 2 blocks each
  EXPECT_EQ(plan.blockOffset(2), 8);
  EXPECT_EQ(plan.blockSlots(), 8);  // none for the vector-only element
  EXPECT_EQ(plan.vectorOffset(2), 4);
  EXPECT_EQ(plan.vectorSlots(), 5);
  EXPECT_EQ(plan.pattern().rows(), 3);
  EXPECT_EQ(plan.pattern().find(0, 2), -1);  // no element holds both
  EXPECT_GE(plan.pattern().find(0, 1), 0);
}

TEST(AssemblyPlan, GathersTheSumOfEachPlacesSlots) {
  const AssemblyPlan plan(3, kElements, kWithBlocks);
  std::vector<Block3> blocks(plan.blockSlots());
  for (int s = 0; s < plan.blockSlots(); ++s) blocks[s] = (s + 1) * Block3::Identity();
  BlockSparseMatrix A = plan.pattern();
  plan.gatherBlocks(blocks, {10, 20, 30}, A);
  // Element 0's local (1, 1) is slot 3 (value 4), element 1's local (0, 0) is slot 4 (value 5):
  // node 1's diagonal is 4 + 5 plus its mass 20.
  EXPECT_EQ(A.diagonal(1), 29 * Block3::Identity());
  EXPECT_EQ(A.diagonal(0), 11 * Block3::Identity());         // slot 0 (1) + 10
  EXPECT_EQ(A.block(A.find(0, 1)), 2 * Block3::Identity());  // element 0's local (0, 1): slot 1
  EXPECT_EQ(A.block(A.find(2, 1)), 7 * Block3::Identity());  // element 1's local (1, 0): slot 6
  std::vector<Vec3> vectors = {{1, 0, 0}, {2, 0, 0}, {0, 3, 0}, {0, 4, 0}, {0, 0, 5}};
  std::vector<Vec3> out;
  plan.gatherVectors(vectors, out);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[0], Vec3(1, 0, 0));
  EXPECT_EQ(out[1], Vec3(2, 3, 0));  // element 0's second and element 1's first
  EXPECT_EQ(out[2], Vec3(0, 4, 5));  // element 1's second and the vector-only element's
}

}  // namespace
