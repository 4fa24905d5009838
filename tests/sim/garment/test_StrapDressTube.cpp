// The strap dress's tube round a box torso (sections: 20 x 16 cm rectangles about the y axis):
// its rows from the top edge to the hem, each clear of the box by the clearance, arc lengths
// that invert each other, and no rise without a neckline.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/body/BodySlices.h"
#include "sim/garment/StrapDressTube.h"
#include "support/BoxFigure.h"

using namespace figment;

namespace {

constexpr double kClearance = 0.01;  // m

StrapDressTube tubeRoundABox() {
  const TriangleMesh torso = mannequin::boxMesh({{-0.1, 0.5, -0.08}, {0.1, 1.5, 0.08}});
  return StrapDressTube(torso, 1.3, 0.7, 1.4, 6, kClearance, 0.0, SliceOptions{}, Neckline{});
}

TEST(StrapDressTube, RowsRunFromTheTopEdgeToTheHemClearOfTheBody) {
  const StrapDressTube tube = tubeRoundABox();
  ASSERT_GE(tube.rowCount(), 2);
  EXPECT_NEAR(tube.height(0), 1.3, 1e-12);
  EXPECT_NEAR(tube.height(tube.rowCount() - 1), 0.7, 1e-12);
  for (int row = 0; row < tube.rowCount(); ++row) {
    // Along +x the box's side is 0.1 m from the axis, along +z 0.08 m: the tube at least the
    // clearance beyond.
    EXPECT_GE(tube.radius(row, 0.0), 0.1 + kClearance - 1e-9) << row;
    EXPECT_GE(tube.radius(row, M_PI / 2), 0.08 + kClearance - 1e-9) << row;
    EXPECT_GE(tube.perimeter(row), 2 * (0.2 + 0.16)) << row;  // round the rectangle
    EXPECT_EQ(tube.rise(row, M_PI / 2), 0.0);                 // no neckline asked for
  }
}

TEST(StrapDressTube, ArcLengthAndAngleInvertEachOther) {
  const StrapDressTube tube = tubeRoundABox();
  for (double angle : {0.3, 1.2, 2.5, 4.0}) {
    const double arc = tube.arcTo(2, angle);
    EXPECT_GE(arc, 0.0);
    EXPECT_LE(arc, tube.perimeter(2));
    // Arcs start at the front centre, so an angle comes back up to a whole turn on.
    EXPECT_NEAR(std::remainder(tube.angleAtArc(2, arc) - angle, 2 * M_PI), 0.0, 1e-6) << angle;
  }
}

}  // namespace
