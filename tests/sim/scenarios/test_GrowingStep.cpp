// The implicit step that grows while the cloth is quiet (ImplicitSolverParameters::
// maxTimeStep, ClothSolver.h): it comes to the same rest as the fixed step in fewer
// steps, grows by kStepGrowth up to its largest, halves after a step the step control
// had to halve, and a run ends at maxTime exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "sim/cloth/ClothSolver.h"
#include "sim/collision/MeshCollider.h"
#include "support/SheetOnBall.h"
#include "support/TestMeshes.h"

namespace test_GrowingStep {

using namespace figment;

namespace {
using sheetonball::ball;
using sheetonball::kRadius;
using sheetonball::sheetAboveBall;

ClothParameters implicitDrape(double timeStep, double maxTimeStep) {
  ClothParameters p;
  p.integrator = Integrator::Implicit;
  p.timeStep = timeStep;
  p.implicitSolver.maxTimeStep = maxTimeStep;
  p.maxTime = 6.0;
  return p;
}

// A strip 5 cm wide and 50 cm long hanging from its top row.
struct HangingStrip {
  TriangleMesh mesh = meshes::grid(2, 20, 0.05, 0.5);
  DrapeResult result;
  std::vector<Vec3> positions;
};

HangingStrip hang(const ClothParameters& p) {
  HangingStrip strip;
  ClothSolver solver(strip.mesh, p, nullptr);
  for (int i = 0; i <= 2; ++i) solver.pin(i);
  strip.result = solver.run();
  strip.positions = solver.positions();
  return strip;
}

// Each step's size, from the solver's clock, whether the step control halved it and its
// fastest node (|x' - x| / dt, the rest rule's speed), filled in by the observer `watch`
// gives the solver.
struct StepLog {
  std::vector<double> sizes, fastest;
  std::vector<bool> halved;
  double time = 0.0;
  long halvings = 0;
  std::vector<Vec3> positions;

  void watch(ClothSolver& solver) {
    time = solver.time();
    halvings = solver.implicitCosts().halvedSteps;
    positions = solver.positions();
    solver.setStepObserver([this](const ClothSolver& s) {
      if (s.time() == time) return;  // run()'s call before the first step
      const double dt = s.time() - time;
      double speed = 0.0;
      for (size_t i = 0; i < positions.size(); ++i)
        speed = std::max(speed, (s.positions()[i] - positions[i]).norm() / dt);
      sizes.push_back(dt);
      fastest.push_back(speed);
      halved.push_back(s.implicitCosts().halvedSteps != halvings);
      time = s.time();
      halvings = s.implicitCosts().halvedSteps;
      positions = s.positions();
    });
  }
};
}  // namespace

// Without contacts the strip's rest is one shape (its equilibrium under gravity): the
// growing step finds it, to the rest rule's millimetres, in a fraction of the steps.
TEST(GrowingStep, AHangingStripRestsWhereTheFixedStepRestsInFewerSteps) {
  const HangingStrip fixed = hang(implicitDrape(0.01, 0.0));
  const HangingStrip grown = hang(implicitDrape(0.01, 0.4));
  ASSERT_TRUE(fixed.result.atRest);
  ASSERT_TRUE(grown.result.atRest);
  double worst = 0.0;
  for (size_t i = 0; i < fixed.positions.size(); ++i)
    worst = std::max(worst, (fixed.positions[i] - grown.positions[i]).norm());
  EXPECT_LT(worst, 2e-3);  // m
  EXPECT_LE(grown.result.iterations, fixed.result.iterations / 2)
      << grown.result.iterations << " against " << fixed.result.iterations;
  RecordProperty("steps fixed", fixed.result.iterations);
  RecordProperty("steps grown", grown.result.iterations);
}

// Dropped on the ball with friction, the sheet rests outside it, held up by the ball's
// top, in fewer steps than at the fixed step.
TEST(GrowingStep, ASheetDroppedOnABallRestsOutsideItInFewerSteps) {
  auto body = ball();
  ClothParameters fixedStep = implicitDrape(1.0 / 30.0, 0.0), grownStep = implicitDrape(1.0 / 30.0, 0.4);
  fixedStep.maxTime = grownStep.maxTime = 8.0;
  ClothSolver fixed(sheetAboveBall(), fixedStep, body), grown(sheetAboveBall(), grownStep, body);
  const DrapeResult fixedRun = fixed.run(), grownRun = grown.run();
  ASSERT_TRUE(fixedRun.atRest);
  ASSERT_TRUE(grownRun.atRest);
  EXPECT_LT(grownRun.iterations, fixedRun.iterations / 2) << grownRun.iterations << " against " << fixedRun.iterations;
  double highest = -std::numeric_limits<double>::infinity(), deepest = std::numeric_limits<double>::infinity();
  for (const Vec3& x : grown.positions()) {
    highest = std::max(highest, x.y());
    Contact contact;
    if (body->contact(x, grownStep.clearance, 1.0, contact)) deepest = std::min(deepest, contact.distance);
  }
  EXPECT_NEAR(highest, kRadius + grownStep.clearance, 0.01);
  EXPECT_GT(deepest, grownStep.clearance - 1e-6);
  EXPECT_LT(grown.positions()[0].y(), 0.0);  // the corners hang past the ball
}

// A quiet step (kept whole by the step control, its fastest node slower than the step
// before's; the first step has none before it) makes the next 1.5 times longer, up to the largest; any other the next
// half as long, never under timeStep. The sheet at 0.2 s overshoots in its first step (the step control halves it) and
// then grows, so the run has both.
TEST(GrowingStep, GrowsByHalfWhileQuietUpToTheLargestAndHalvesOtherwise) {
  ClothParameters p = implicitDrape(0.2, 1.6);
  p.rest.speedThreshold = 0.0;  // never at rest: the run goes to maxTime
  ClothSolver solver(sheetAboveBall(), p, ball());
  StepLog log;
  log.watch(solver);
  solver.run();
  ASSERT_GT(log.sizes.size(), 3u);
  int halved = 0, grew = 0;
  for (size_t k = 0; k + 2 < log.sizes.size(); ++k) {  // the last step is cut to maxTime
    SCOPED_TRACE(testing::Message() << "step " << k + 1 << " of " << log.sizes[k] << " s");
    const double before = k == 0 ? 0.0 : log.fastest[k - 1];  // the first step has none before it: not quiet
    const bool quiet = !log.halved[k] && log.fastest[k] < before;
    const double expected =
        quiet ? std::min(p.implicitSolver.maxTimeStep, 1.5 * log.sizes[k]) : std::max(p.timeStep, 0.5 * log.sizes[k]);
    EXPECT_NEAR(log.sizes[k + 1], expected, 1e-12);
    halved += log.halved[k] ? 1 : 0;
    grew += quiet ? 1 : 0;
  }
  EXPECT_GT(halved, 0);
  EXPECT_GT(grew, 0);
  EXPECT_NEAR(*std::max_element(log.sizes.begin(), log.sizes.end()), p.implicitSolver.maxTimeStep, 1e-12);
  // The run stops at maxTime itself, its last step cut to end there.
  EXPECT_NEAR(solver.time(), p.maxTime, 1e-9);
}

// Off (0, the default), every step is timeStep.
TEST(GrowingStep, OffEveryStepIsTheTimeStep) {
  ClothParameters p = implicitDrape(0.05, 0.0);
  p.maxTime = 1.0;
  p.rest.speedThreshold = 0.0;
  ClothSolver solver(sheetAboveBall(), p, ball());
  StepLog log;
  log.watch(solver);
  solver.run();
  ASSERT_EQ(log.sizes.size(), 20u);
  for (const double size : log.sizes) EXPECT_NEAR(size, 0.05, 1e-12);
}

TEST(GrowingStep, RefusesALargestStepItCannotTakeNamingTheField) {
  const auto refusal = [](ClothParameters p) -> std::string {
    try {
      p.validate();
    } catch (const std::invalid_argument& error) {
      return error.what();
    }
    return "accepted";
  };
  EXPECT_EQ(refusal(implicitDrape(0.05, 0.02)), "maxTimeStep = 0.02 must not be under timeStep = 0.05 (0: no growth)");
  EXPECT_EQ(refusal(implicitDrape(0.05, 7.0)), "accepted");  // past maxTime: the last step is cut to it
  EXPECT_EQ(refusal(implicitDrape(0.05, -1.0)), "maxTimeStep = -1 must be >= 0");
  ClothParameters heun = implicitDrape(1.5e-4, 0.4);
  heun.integrator = Integrator::Heun;
  EXPECT_EQ(refusal(heun), "maxTimeStep = 0.4 needs integrator IMPLICIT (an explicit step's bound is its stability)");
  EXPECT_EQ(refusal(implicitDrape(0.05, 0.05)), "accepted");  // as large as the first: a fixed step
  EXPECT_EQ(refusal(implicitDrape(0.05, 0.0)), "accepted");
}

}  // namespace test_GrowingStep
