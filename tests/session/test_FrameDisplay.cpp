// A recorded state shown in place of the drape: every point field the engine feeds holds it,
// its connection kept but disabled, and nothing simulates again.
#include <gtest/gtest.h>

#include <vector>

#include "session/FrameDisplay.h"
#include "support/FallingSquare.h"

using namespace figment;

namespace {

TEST(FrameDisplay, ThePointsHoldTheFrameAndStopFollowingTheEngine) {
  const test::FallingSquare square(0.05);
  ASSERT_TRUE(square.read());
  square.drape();
  ASSERT_EQ(square.engine().evaluationCount(), 1);
  const std::vector<SbVec3f> frame = {{0, 2, 0}, {1, 2, 0}, {1, 2, 1}, {0, 2, 1}};
  session::showPositions(square.engine(), frame);
  SoMFVec3f& points = square.points().point;
  EXPECT_TRUE(points.isConnected());  // kept, so the drape can be shown again
  EXPECT_FALSE(points.isConnectionEnabled());
  ASSERT_EQ(points.getNum(), 4);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(points[i], frame[i]) << i;
  EXPECT_EQ(square.engine().evaluationCount(), 1);
}

}  // namespace
