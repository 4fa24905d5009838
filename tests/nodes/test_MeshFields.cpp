// A mesh into a node's fields, the form ClothEngine and ClothingLayer read: points in float
// and each triangle ended by -1; a cut pattern's panel coordinates and seams as outputs that
// are never written to a file.
#include <Inventor/SoDB.h>
#include <Inventor/fields/SoMFInt32.h>
#include <Inventor/fields/SoMFVec2f.h>
#include <Inventor/fields/SoMFVec3f.h>
#include <gtest/gtest.h>

#include <vector>

#include "nodes/MeshFields.h"
#include "sim/pattern/UnsewnGarment.h"

using namespace figment;

namespace {

TEST(MeshFields, TrianglesEndEachWithMinusOne) {
  SoDB::init();
  TriangleMesh square;
  square.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5}, {0, 1, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  SoMFVec3f points;
  SoMFInt32 coordIndex;
  setMeshFields(square, points, coordIndex);
  ASSERT_EQ(points.getNum(), 4);
  EXPECT_EQ(points[2], SbVec3f(1, 1, 0.5f));
  ASSERT_EQ(coordIndex.getNum(), 8);
  const std::vector<int32_t> expected = {0, 1, 2, -1, 0, 2, 3, -1};
  EXPECT_EQ(std::vector<int32_t>(coordIndex.getValues(0), coordIndex.getValues(0) + 8), expected);
}

TEST(MeshFields, PanelFieldsAreDefaultSoNeverWritten) {
  SoDB::init();
  UnsewnGarment cut;
  cut.flat = {{0, 0}, {0.5, 0}, {0, 0.25}};
  cut.seams = {{0, 2}, {1, 2}};
  SoMFVec2f panelPoints;
  SoMFInt32 seams;
  setPanelFields(cut, panelPoints, seams);
  ASSERT_EQ(panelPoints.getNum(), 3);
  EXPECT_EQ(panelPoints[1], SbVec2f(0.5f, 0));
  ASSERT_EQ(seams.getNum(), 4);
  EXPECT_EQ(seams[0], 0);
  EXPECT_EQ(seams[1], 2);
  EXPECT_EQ(seams[3], 2);
  EXPECT_TRUE(panelPoints.isDefault());
  EXPECT_TRUE(seams.isDefault());
  clearPanelFields(panelPoints, seams);
  EXPECT_EQ(panelPoints.getNum(), 0);
  EXPECT_EQ(seams.getNum(), 0);
  EXPECT_TRUE(seams.isDefault());
}

}  // namespace
