// A NURBS shape reads only the control points there are: a curve counting more than the
// coordinates, or with a knot vector too short for them, is one line naming node and field.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "guard/shapes/NurbsShapeData.h"
#include "support/ShapeDataSupport.h"

using namespace figment::guard::shapes;

namespace {

constexpr const char* kPoints =
    "#Inventor V2.1 ascii\nSeparator { Coordinate3 { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0 ] }\n";

TEST(NurbsShapeData, ControlPointsAndKnotsMustMatchTheCoordinates) {
  const std::vector<std::string> problems = test::problemsOfShapes(
      std::string(kPoints) +
          "DEF Good NurbsCurve { numControlPoints 4 knotVector [ 0, 0, 0, 0, 1, 1, 1, 1 ] }\n"
          "DEF TooMany NurbsCurve { numControlPoints 6 knotVector [ 0, 0, 0, 0, 1, 2, 3, 3, 3, 3 ] }\n"
          "DEF ShortKnots NurbsCurve { numControlPoints 4 knotVector [ 0, 1, 2 ] } }\n",
      nurbsShapeProblem);
  ASSERT_EQ(problems.size(), 3u);
  EXPECT_EQ(problems[0], "");
  EXPECT_EQ(problems[1].rfind("NurbsCurve 'TooMany': ", 0), 0u) << problems[1];
  EXPECT_NE(problems[1].find("numControlPoints"), std::string::npos) << problems[1];
  EXPECT_EQ(problems[2].rfind("NurbsCurve 'ShortKnots': ", 0), 0u) << problems[2];
  EXPECT_NE(problems[2].find("knotVector"), std::string::npos) << problems[2];
}

TEST(NurbsShapeData, OtherShapesHaveNothingToCheck) {
  const std::vector<std::string> problems =
      test::problemsOfShapes(std::string(kPoints) + "Cube { } }\n", nurbsShapeProblem);
  EXPECT_EQ(problems, std::vector<std::string>{""});
}

}  // namespace
