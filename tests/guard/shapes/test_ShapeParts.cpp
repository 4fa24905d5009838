// Vertices, parts and faces as Coin counts them for each kind of vertex shape, on literal
// index lists and counts.
#include <Inventor/SoDB.h>
#include <Inventor/nodes/SoFaceSet.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoIndexedLineSet.h>
#include <Inventor/nodes/SoIndexedTriangleStripSet.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoPointSet.h>
#include <Inventor/nodes/SoQuadMesh.h>
#include <gtest/gtest.h>

#include <vector>

#include "guard/shapes/ShapeParts.h"

using namespace figment::guard::shapes;

namespace {

void expectParts(const ShapeParts& got, std::int64_t vertices, std::int64_t parts, std::int64_t faces) {
  EXPECT_EQ(got.vertices, vertices);
  EXPECT_EQ(got.parts, parts);
  EXPECT_EQ(got.faces, faces);
}

TEST(ShapeParts, IndexedShapesCountTheirRunsByKind) {
  SoDB::init();
  const int32_t index[] = {0, 1, 2, 3, -1, 4, 5, 6};  // runs of 4 and 3 (the last ends at the end)
  auto* faces = new SoIndexedFaceSet;
  auto* lines = new SoIndexedLineSet;
  auto* strips = new SoIndexedTriangleStripSet;
  for (SoIndexedShape* shape : std::vector<SoIndexedShape*>{faces, lines, strips}) {
    shape->ref();
    shape->coordIndex.setValues(0, 8, index);
  }
  expectParts(indexedShapeParts(*faces), 7, 2, 2);   // a part and a face per polygon
  expectParts(indexedShapeParts(*lines), 7, 5, 2);   // parts: the 3 + 2 segments; faces: polylines
  expectParts(indexedShapeParts(*strips), 7, 2, 3);  // parts: strips; faces: 2 + 1 triangles
  for (SoIndexedShape* shape : std::vector<SoIndexedShape*>{faces, lines, strips}) shape->unref();
}

TEST(ShapeParts, CountedShapesTakeTheRestOfTheCoordinatesForMinusOne) {
  SoDB::init();
  auto* faces = new SoFaceSet;
  faces->ref();
  faces->numVertices.setValues(0, 2, std::vector<int32_t>{3, -1}.data());
  faces->startIndex = 2;
  expectParts(countedShapeParts(*faces, 10), 8, 2, 2);  // 3, then the 5 left of 8 from index 2
  faces->unref();
  auto* lines = new SoLineSet;
  lines->ref();
  lines->numVertices.setValue(4);
  expectParts(countedShapeParts(*lines, 4), 4, 3, 1);
  lines->unref();
  auto* mesh = new SoQuadMesh;
  mesh->ref();
  mesh->verticesPerColumn = 3;
  mesh->verticesPerRow = 4;
  expectParts(countedShapeParts(*mesh, 12), 12, 2, 6);  // 2 rows of 3 quads
  mesh->unref();
  auto* points = new SoPointSet;
  points->ref();
  points->numPoints = -1;
  expectParts(countedShapeParts(*points, 5), 5, 5, 5);
  points->unref();
}

}  // namespace
