// A VRML97 shape indexes only the data its own fields hold: a coordIndex entry past the
// coord's points is one line naming node, field, entry and value.
#include <Inventor/VRMLnodes/SoVRMLGeometry.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "guard/shapes/VrmlShapeData.h"
#include "support/ShapeDataSupport.h"

using namespace figment::guard::shapes;

namespace {

std::string vrml(const SoShape& shape, SoState*) {
  return shape.isOfType(SoVRMLGeometry::getClassTypeId()) ? vrmlShapeProblem(static_cast<const SoVRMLGeometry&>(shape))
                                                          : "not a VRML geometry";
}

TEST(VrmlShapeData, ACoordIndexPastThePointsIsNamed) {
  const std::vector<std::string> problems = test::problemsOfShapes(
      "#VRML V2.0 utf8\n"
      "Shape { geometry DEF Good IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 0 0, 0 1 0 ] }"
      " coordIndex [ 0, 1, 2, -1 ] } }\n"
      "Shape { geometry DEF Bad IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 0 0, 0 1 0 ] }"
      " coordIndex [ 0, 1, 5, -1 ] } }\n",
      vrml);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0], "");
  EXPECT_EQ(problems[1].rfind("VRMLIndexedFaceSet 'Bad': coordIndex[2] = 5", 0), 0u) << problems[1];
}

}  // namespace
