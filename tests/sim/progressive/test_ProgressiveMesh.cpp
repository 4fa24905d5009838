// A level of a decimated grid moves up by its splits back to the whole garment: every vertex
// and face active again, at their rest positions and with their corners.
#include <gtest/gtest.h>

#include <vector>

#include "sim/progressive/Decimation.h"
#include "sim/progressive/ProgressiveMesh.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {

TEST(ProgressiveMesh, SplittingToTheLastLevelRestoresTheGarment) {
  const TriangleMesh garment = meshes::grid(6, 6, 0.3, 0.3);
  const ProgressiveMesh progressive = decimate(garment, DecimationOptions{.targetFaces = 12});
  ASSERT_GT(progressive.levels(), 0);
  MeshLevel level(progressive);
  EXPECT_EQ(level.level(), 0);
  EXPECT_LT(level.activeFaces(), int(garment.triangles.size()));
  const int coarseVertices = level.activeVertices();
  const std::vector<int> added = level.splitTo(progressive.levels());
  EXPECT_EQ(level.level(), progressive.levels());
  EXPECT_EQ(int(added.size()), progressive.levels());  // one vertex a split
  EXPECT_EQ(coarseVertices + progressive.levels(), int(garment.vertices.size()));
  EXPECT_EQ(level.activeFaces(), int(garment.triangles.size()));
  for (size_t v = 0; v < garment.vertices.size(); ++v) {
    EXPECT_TRUE(level.vertexActive(int(v))) << v;
    EXPECT_EQ(level.rest(int(v)), garment.vertices[v]) << v;
  }
  for (size_t f = 0; f < garment.triangles.size(); ++f) EXPECT_EQ(level.corners(int(f)), garment.triangles[f]) << f;
}

TEST(ProgressiveMesh, RestMeshIsTheActivePartWithItsFullIndices) {
  const TriangleMesh garment = meshes::grid(4, 4, 0.2, 0.2);
  const ProgressiveMesh progressive = decimate(garment, DecimationOptions{.targetFaces = 8});
  const MeshLevel level(progressive);
  std::vector<int> fullIndex;
  const TriangleMesh coarse = level.restMesh(fullIndex);
  EXPECT_EQ(int(coarse.vertices.size()), level.activeVertices());
  EXPECT_EQ(int(coarse.triangles.size()), level.activeFaces());
  ASSERT_EQ(fullIndex.size(), coarse.vertices.size());
  for (size_t i = 0; i < fullIndex.size(); ++i) {
    EXPECT_TRUE(level.vertexActive(fullIndex[i]));
    EXPECT_EQ(coarse.vertices[i], level.rest(fullIndex[i]));
  }
}

}  // namespace
