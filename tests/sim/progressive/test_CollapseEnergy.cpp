// What an edge collapse costs on a flat grid, where the surface term is zero: with the
// homogeneity term off an interior collapse costs nothing, with it on it costs the squared
// areas it leaves; an edge whose collapse would join the boundary to the inside is refused.
#include <gtest/gtest.h>

#include <optional>

#include "sim/progressive/CollapseEnergy.h"
#include "sim/progressive/CollapseNeighbourhood.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {

// 5 x 5 vertices, vertex (i, j) = i + 5 j: 12 and 13 are inside, 0 and 1 on the edge.
const TriangleMesh kGrid = meshes::grid(4, 4, 0.4, 0.4);

TEST(CollapseEnergy, AFlatInteriorCollapseCostsOnlyItsHomogeneity) {
  const CollapseNeighbourhood mesh(kGrid);
  const std::optional<Collapse> free =
      CollapseEnergy(kGrid, {.perimeterWeight = 0.0, .homogeneity = 0.0}).best(mesh, 12, 13);
  ASSERT_TRUE(free.has_value());
  EXPECT_NEAR(free->cost, 0.0, 1e-18);  // m^4: a flat surface stays where it was
  EXPECT_NEAR(free->position.z(), 0.0, 1e-12);
  const std::optional<Collapse> even = CollapseEnergy(kGrid, {.perimeterWeight = 0.0}).best(mesh, 12, 13);
  ASSERT_TRUE(even.has_value());
  EXPECT_GT(even->cost, 0.0);  // the sections round the result are larger: they cost
  EXPECT_TRUE((even->kept == 12 && even->removed == 13) || (even->kept == 13 && even->removed == 12));
}

TEST(CollapseEnergy, TheBoundaryIsNotPulledInside) {
  const CollapseNeighbourhood mesh(kGrid);
  const CollapseEnergy energy(kGrid, {});
  // Vertex 6 is inside, 1 on the edge: only a collapse into 1 keeps the boundary where it is.
  const std::optional<Collapse> inward = energy.best(mesh, 1, 6);
  if (inward) {
    EXPECT_EQ(inward->kept, 1);
    EXPECT_EQ(inward->position, kGrid.vertices[1]);
  }
  // Along the boundary a collapse stays on it.
  const std::optional<Collapse> along = energy.best(mesh, 1, 2);
  ASSERT_TRUE(along.has_value());
  EXPECT_NEAR(along->position.y(), kGrid.vertices[1].y(), 1e-12);
}

}  // namespace
