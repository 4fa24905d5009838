// A garment's rest shape: a mesh's own, or flat pieces whose joints rest flat.
#include <gtest/gtest.h>

#include "sim/cloth/BendingJoint.h"
#include "sim/cloth/RestShape.h"
#include "support/TestMeshes.h"

namespace figment {
namespace {

TEST(RestShape, OfAMeshHasItsVerticesAsCornersAndItsDihedralsAtTheJoints) {
  TriangleMesh folded = meshes::grid(1, 1, 1.0, 1.0);  // two triangles sharing (1, 2)
  folded.vertices[3].z() = 0.5;                        // folded along the diagonal
  const RestShape rest(folded);
  ASSERT_NE(rest.mesh(), nullptr);
  EXPECT_EQ(rest.nodeCount(), 4u);
  for (size_t t = 0; t < 2; ++t)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(rest.corners(t)[k], folded.vertices[folded.triangles[t][k]]);
  // Sections (0, 2, 1) and (1, 2, 3) share the edge 2 -> 1 ... as A = (1, 2, 0).
  const std::array<int, 4> corners{1, 2, 0, 3};
  const BendingJoint joint(corners, rest.hinge(1, 0, corners));
  const BendingJoint fromMesh(1, 2, 0, 3, folded.vertices);
  EXPECT_EQ(joint.restAngle(), fromMesh.restAngle());
  EXPECT_GT(std::abs(joint.restAngle()), 0.1);  // the control: the mesh's joint is not flat
}

TEST(RestShape, FlatPiecesRestFlatAcrossAJointBetweenTwoPanels) {
  // Two triangles of two panels, each in its own frame (a seam between them): at rest their
  // joint is flat, whatever the panels' frames.
  const std::vector<Triangle> triangles{{0, 1, 2}, {1, 0, 3}};
  const std::vector<std::array<Vec3, 3>> corners{
      {Vec3(0, 0, 0), Vec3(0.1, 0, 0), Vec3(0.05, 0.08, 0)},
      {Vec3(2.0, 1.0, 0), Vec3(2.0, 0.9, 0), Vec3(1.93, 0.95, 0)}};  // the same edge, rotated
  const RestShape rest = RestShape::flatPieces(triangles, corners, 4);
  EXPECT_EQ(rest.mesh(), nullptr);
  const std::array<int, 4> joint{0, 1, 2, 3};
  const std::array<Vec3, 4> hinge = rest.hinge(0, 1, joint);
  const BendingJoint flat(joint, hinge);
  ASSERT_TRUE(flat.valid());
  EXPECT_EQ(flat.restAngle(), 0.0);
  // The opposite corners lie either side of the edge, at their own heights off it.
  EXPECT_NEAR(hinge[2].y(), 0.08, 1e-12);
  EXPECT_NEAR(hinge[3].y(), -0.07, 1e-12);
}

TEST(RestShape, RefusesCountsThatDisagreeAndNodesOutOfRange) {
  EXPECT_THROW(RestShape::flatPieces({{0, 1, 2}}, {}, 3), std::invalid_argument);
  try {
    RestShape::flatPieces({{0, 1, 5}}, {{Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY()}}, 3);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "rest shape: node 5 is out of range [0, 3)");
  }
}

}  // namespace
}  // namespace figment
