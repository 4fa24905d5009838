// The hooks figment-view watches a drape through, in its session's drape context: the
// progress callback (the progress bar) and the step observer (frames of a time span, the
// wind force), and the DrapeRecorder built on the observer.

#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "headless/InitHeadless.h"
#include "io/DrapeCache.h"
#include "session/DrapeRecorder.h"
#include "session/FrameDisplay.h"
#include "session/SceneSession.h"
#include "sim/cloth/ClothSolver.h"
#include "sim/drape/DrapeReport.h"
#include "support/TempDir.h"

using namespace figment::session;

namespace {

// A horizontal square of cloth, 1 m^2, falling for `seconds` at steps of 1 ms (Heun),
// with `fields` added to its engine.
std::string fallingSquare(double seconds, const std::string& fields = "") {
  return "#Inventor V2.1 ascii\nSeparator {\n  DEF Points Coordinate3 { point = DEF Drape ClothEngine {\n"
         "    restPoints [ -0.5 1 -0.5, 0.5 1 -0.5, 0.5 1 0.5, -0.5 1 0.5 ]\n"
         "    coordIndex [ 0 3 2 1 -1 ]  timeStep 0.001  maxTime " +
         std::to_string(seconds) + "\n    " + fields +
         "\n  } . positions }\n  IndexedFaceSet { coordIndex [ 0 3 2 1 -1 ] }\n}\n";
}

class DrapeObservation : public ::testing::Test {
 protected:
  void SetUp() override { figment::initHeadless(); }
  // Loads `text` into the session; its one engine.
  ClothEngine& load(const std::string& text) {
    EXPECT_TRUE(session_.load(dir_.file("scene.iv", text))) << session_.loadError();
    EXPECT_EQ(session_.engines().size(), 1u);
    return *session_.engines().front();
  }
  figment::test::TempDir dir_;
  SceneSession session_;
};

}  // namespace

TEST_F(DrapeObservation, ProgressComesEvery64StepsWithAZeroInterval) {
  ClothEngine& engine = load(fallingSquare(0.5));  // 500 steps
  std::vector<ClothEngine::Progress> reports;
  session_.context().progress = [&](const ClothEngine& from, const ClothEngine::Progress& p) {
    EXPECT_EQ(&from, &engine);
    reports.push_back(p);
  };
  session_.context().progressInterval = 0.0;
  ASSERT_EQ(session_.drape().front()->lastError(), "");
  ASSERT_EQ(reports.size(), 500u / 64u);  // steps 64, 128, ..., 448
  for (size_t i = 0; i < reports.size(); ++i) {
    EXPECT_EQ(reports[i].iterations, 64 * int(i + 1));
    EXPECT_NEAR(reports[i].simulatedSeconds, 0.064 * (i + 1), 1e-9);
    EXPECT_DOUBLE_EQ(reports[i].maxTime, 0.5);
    EXPECT_GT(reports[i].maxSpeed, 0.0);  // it falls
  }
}

TEST_F(DrapeObservation, TheObserverSeesTheStartAndEveryStepAndTheCacheIsNotRead) {
  // A kept drape of this very scene would otherwise be read in place of simulating it.
  session_.context().cache = std::make_shared<figment::DrapeCache>(dir_.path() / "cache", 1u << 20);
  load(fallingSquare(0.05));
  ASSERT_EQ(session_.drape().front()->lastError(), "");
  ASSERT_FALSE(session_.engines().front()->lastRun().fromCache);
  SceneSession again(session_.sharedContext());  // the same cache
  ASSERT_TRUE(again.load(dir_.file("scene.iv", fallingSquare(0.05))));
  std::vector<double> times;
  std::vector<int> steps;
  again.context().stepObserver = [&](const ClothEngine&, const figment::ClothSolver& solver) {
    times.push_back(solver.time());
    steps.push_back(solver.iterations());
  };
  ASSERT_EQ(again.drape().front()->lastError(), "");
  EXPECT_FALSE(again.engines().front()->lastRun().fromCache);
  ASSERT_EQ(times.size(), 51u);  // before the first step, then after each of 50
  for (size_t i = 0; i < times.size(); ++i) {
    EXPECT_EQ(steps[i], int(i));
    EXPECT_NEAR(times[i], 0.001 * i, 1e-12);
  }
}

TEST_F(DrapeObservation, TheRecorderKeepsTheStateAtEachFrameTimeAndTheLastAfterTheRun) {
  ClothEngine& engine = load(fallingSquare(0.2));
  DrapeRecorder recorder(session_.sharedContext(), {0.0, 0.1, 0.2, 0.5}, 0.0);
  ASSERT_EQ(session_.drape().front()->lastError(), "");
  ASSERT_TRUE(recorder.observed(engine));
  const auto height = [&](size_t k) { return recorder.frame(engine, k).at(0)[1]; };
  EXPECT_FLOAT_EQ(height(0), 1.0f);  // the start: the rest shape
  EXPECT_LT(height(1), 1.0f);        // falling
  EXPECT_LT(height(2), height(1));
  EXPECT_EQ(recorder.frame(engine, 3), recorder.frame(engine, 2));  // after the run: its end
  // The drape's own output is its end too.
  EXPECT_FLOAT_EQ(height(2), static_cast<SoCoordinate3*>(SoNode::getByName("Points"))->point[0][1]);
  EXPECT_TRUE(recorder.windSamples(engine).empty());  // no wind asked for, none blowing
}

TEST_F(DrapeObservation, AFrameShownReplacesTheDrapeWhereItIsDrawn) {
  ClothEngine& engine = load(fallingSquare(0.1));
  DrapeRecorder recorder(session_.sharedContext(), {0.0, 0.1}, 0.0);
  ASSERT_EQ(session_.drape().front()->lastError(), "");
  auto* points = static_cast<SoCoordinate3*>(SoNode::getByName("Points"));
  ASSERT_NE(points, nullptr);
  showPositions(engine, recorder.frame(engine, 0));
  EXPECT_FLOAT_EQ(points->point[0][1], 1.0f);
  showPositions(engine, recorder.frame(engine, 1));
  EXPECT_LT(points->point[0][1], 1.0f);
  EXPECT_EQ(engine.evaluationCount(), 1) << "showing a frame simulates nothing again";
}

TEST_F(DrapeObservation, WindSamplesAreTheModelsForceOnTheWholeGarment) {
  // The square falls flat, face-on to a vertical wind: every section catches p(t) A, so
  // the force is p(t) * 1 m^2 along +y.
  ClothEngine& engine =
      load(fallingSquare(1.0, "windDirection 0 1 0 windAmplitude 0.5 windFrequency 2 windPhaseInterval 0.25"));
  DrapeRecorder recorder(session_.sharedContext(), {}, 0.01);
  ASSERT_EQ(session_.drape().front()->lastError(), "");
  const std::vector<WindSample>& samples = recorder.windSamples(engine);
  ASSERT_GE(samples.size(), 100u);
  ASSERT_LE(samples.size(), 101u);
  figment::WindParameters parameters;
  parameters.direction = figment::Vec3::UnitY();
  parameters.amplitude = 0.5;
  parameters.frequency = 2.0;
  parameters.meanPhaseInterval = 0.25;
  const figment::Wind wind(parameters);
  for (const WindSample& s : samples) {
    EXPECT_NEAR(s.pressure, wind.pressure(s.time), 1e-12);
    EXPECT_NEAR(s.force.y(), s.pressure, 1e-6) << "t = " << s.time;
    EXPECT_NEAR(s.force.x(), 0.0, 1e-9);
    EXPECT_NEAR(s.force.z(), 0.0, 1e-9);
  }
}
