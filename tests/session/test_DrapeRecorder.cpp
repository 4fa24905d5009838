// The recorder as a drape context's step observer, on an engine draping with that context
// directly (no session): frames at their times, the last state after the run, nothing for an
// engine it did not see, and the context's observer gone with the recorder.
#include <gtest/gtest.h>

#include <vector>

#include "session/DrapeRecorder.h"
#include "support/FallingSquare.h"

using namespace figment;

namespace {

TEST(DrapeRecorder, KeepsTheFramesOfTheEnginesItObserves) {
  const test::FallingSquare square(0.2);
  ASSERT_TRUE(square.read());
  const test::FallingSquare unseen(0.2);  // drapes with a context of its own
  ASSERT_TRUE(unseen.read());
  session::DrapeRecorder recorder(square.context(), {0.0, 0.15, 1.0}, 0.0);
  square.drape();
  unseen.drape();
  ASSERT_EQ(square.engine().lastError(), "");
  ASSERT_TRUE(recorder.observed(square.engine()));
  EXPECT_FALSE(recorder.observed(unseen.engine()));
  EXPECT_TRUE(recorder.frame(unseen.engine(), 0).empty());
  ASSERT_EQ(recorder.frame(square.engine(), 0).size(), 4u);
  EXPECT_FLOAT_EQ(recorder.frame(square.engine(), 0)[2][1], 1.0f);  // the rest shape
  // Free fall for 0.15 s under g (and a little air): below 1 m, by at most g t^2 / 2.
  const float fallen = 1.0f - recorder.frame(square.engine(), 1)[2][1];
  EXPECT_GT(fallen, 0.0f);
  EXPECT_LE(fallen, 0.5f * 9.81f * 0.15f * 0.15f + 1e-3f);
  // After the run (0.2 s): its last state, which is the engine's output.
  EXPECT_EQ(recorder.frame(square.engine(), 2)[2], square.points().point[2]);
  EXPECT_TRUE(recorder.windSamples(square.engine()).empty());  // none asked for
}

TEST(DrapeRecorder, LeavesTheContextWithoutAnObserver) {
  const test::FallingSquare square(0.01);
  ASSERT_TRUE(square.read());
  { const session::DrapeRecorder recorder(square.context(), {}, 0.0); }
  EXPECT_FALSE(square.context()->stepObserver);
}

}  // namespace
