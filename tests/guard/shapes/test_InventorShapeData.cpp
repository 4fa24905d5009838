// An Inventor shape reads only the data it has: an index past the coordinates, a FaceSet
// counting more vertices than there are, each one line naming node, field and entry; a shape
// within its data passes.
#include <Inventor/nodes/SoIndexedShape.h>
#include <Inventor/nodes/SoNonIndexedShape.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "guard/shapes/InventorShapeData.h"
#include "support/ShapeDataSupport.h"

namespace test_InventorShapeData {

using namespace figment::guard::shapes;

namespace {

std::string indexed(const SoShape& shape, SoState* state) {
  return indexedShapeProblem(static_cast<const SoIndexedShape&>(shape), state);
}

std::string counted(const SoShape& shape, SoState* state) {
  return countedShapeProblem(static_cast<const SoNonIndexedShape&>(shape), state);
}

constexpr const char* kPoints = "#Inventor V2.1 ascii\nSeparator { Coordinate3 { point [ 0 0 0, 1 0 0, 0 1 0 ] }\n";

TEST(InventorShapeData, AnIndexPastTheCoordinatesIsNamed) {
  const std::vector<std::string> problems =
      test::problemsOfShapes(std::string(kPoints) +
                                 "DEF Good IndexedFaceSet { coordIndex [ 0, 1, 2, -1 ] }\n"
                                 "DEF Bad IndexedFaceSet { coordIndex [ 0, 1, 2, -1, 2, 1, 3, -1 ] } }\n",
                             indexed);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0], "");
  EXPECT_EQ(problems[1].rfind("IndexedFaceSet 'Bad': coordIndex[6] = 3 is not a ", 0), 0u) << problems[1];
}

TEST(InventorShapeData, AFaceSetCountingMoreVerticesThanThereAreIsNamed) {
  const std::vector<std::string> problems = test::problemsOfShapes(
      std::string(kPoints) + "DEF Good FaceSet { numVertices 3 }\nDEF Bad FaceSet { numVertices [ 3, 3 ] } }\n",
      counted);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0], "");
  EXPECT_EQ(problems[1].rfind("FaceSet 'Bad': ", 0), 0u) << problems[1];
  EXPECT_NE(problems[1].find("numVertices"), std::string::npos) << problems[1];
}

}  // namespace

}  // namespace test_InventorShapeData
