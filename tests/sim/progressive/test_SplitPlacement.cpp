// Where a split puts its vertices in the draped garment: for a garment moved rigidly (turned
// and shifted, no strain) the deformation gradient is the rotation, so both vertices land
// where the same motion takes their rest positions; both take the ring's mean velocity.
#include <gtest/gtest.h>

#include <vector>

#include "sim/progressive/Decimation.h"
#include "sim/progressive/SplitPlacement.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {

TEST(SplitPlacement, ARigidMotionCarriesTheRestOffsets) {
  const TriangleMesh garment = meshes::grid(4, 4, 0.2, 0.2);
  const ProgressiveMesh progressive = decimate(garment, DecimationOptions{.targetFaces = 8});
  ASSERT_GT(progressive.levels(), 0);
  const MeshLevel level(progressive);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 shift(0.1, -0.3, 0.2);
  std::vector<Vec3> x(garment.vertices.size()), v(garment.vertices.size(), Vec3(1, 2, 3));
  for (size_t i = 0; i < x.size(); ++i) x[i] = turn * level.rest(int(i)) + shift;
  const VertexSplit& split = progressive.splits.front();
  placeSplit(split, level, x, v);
  EXPECT_TRUE(x[split.added].isApprox(turn * split.addedRest + shift, 1e-12)) << x[split.added].transpose();
  EXPECT_TRUE(x[split.kept].isApprox(turn * split.keptRest + shift, 1e-12)) << x[split.kept].transpose();
  EXPECT_EQ(v[split.added], Vec3(1, 2, 3));
  EXPECT_EQ(v[split.kept], Vec3(1, 2, 3));
}

TEST(SplitPlacement, TheVelocityIsTheMeanOfTheKeptVertexAndItsRing) {
  const TriangleMesh garment = meshes::grid(4, 4, 0.2, 0.2);
  const ProgressiveMesh progressive = decimate(garment, DecimationOptions{.targetFaces = 8});
  const MeshLevel level(progressive);
  std::vector<Vec3> x(garment.vertices.size()), v(garment.vertices.size(), Vec3::Zero());
  for (size_t i = 0; i < x.size(); ++i) x[i] = level.rest(int(i));
  const VertexSplit& split = progressive.splits.front();
  v[split.kept] = Vec3(0, 0, 6);
  int ring = 0;
  std::vector<char> seen(x.size(), 0);
  for (int f : level.facesOf(split.kept))
    for (int n : level.corners(f))
      if (n != split.kept && !seen[n]) seen[n] = 1, ++ring;
  placeSplit(split, level, x, v);
  EXPECT_TRUE(v[split.added].isApprox(Vec3(0, 0, 6.0 / (ring + 1)), 1e-12)) << v[split.added].transpose();
  // Unstrained: each lands on its own rest position.
  EXPECT_TRUE(x[split.added].isApprox(split.addedRest, 1e-12));
}

}  // namespace
