// The studies' methods and schedules from the command line: a method as DrapeMethod reads it,
// kept with its text, set onto an engine's fields (a limit only where the method gives one);
// a bad text is one line on stderr and a false, for the studies' exit status 2.
#include <gtest/gtest.h>

#include <stdexcept>

#include "bench/MethodSpec.h"
#include "support/SceneTestSupport.h"

using namespace figment;
using namespace figment::bench;

namespace {
// An engine held for the test (engines are reference counted, as nodes are).
struct HeldEngine {
  ClothEngine* engine = new ClothEngine;
  HeldEngine() { engine->ref(); }
  ~HeldEngine() { engine->unref(); }
};
}  // namespace

TEST(MethodSpec, AMethodKeepsItsTextAndSetsTheEnginesFields) {
  test::initCoin();
  const Method m = parseMethod("HEUN:1.5e-4:clamp:25");
  EXPECT_EQ(m.text, "HEUN:1.5e-4:clamp:25");
  EXPECT_EQ(m.drape.text(), "heun:0.00015:clamp:25");
  const HeldEngine held;
  ClothEngine& engine = *held.engine;
  configure(engine, m);
  EXPECT_EQ(engine.integrator.getValue(), ClothEngine::HEUN);
  EXPECT_EQ(engine.accelerationLimiter.getValue(), ClothEngine::CLAMP);
  EXPECT_EQ(engine.contactModel.getValue(), ClothEngine::CONSTRAINTS);
  EXPECT_DOUBLE_EQ(engine.accelerationLimit.getValue(), 25.0);
  EXPECT_DOUBLE_EQ(engine.timeStep.getValue(), 1.5e-4);
  configure(engine, parseMethod("implicit+penalty:0.05"));
  EXPECT_EQ(engine.integrator.getValue(), ClothEngine::IMPLICIT);
  EXPECT_EQ(engine.contactModel.getValue(), ClothEngine::PENALTY);
  EXPECT_EQ(engine.accelerationLimiter.getValue(), ClothEngine::NONE);
  EXPECT_DOUBLE_EQ(engine.accelerationLimit.getValue(), 25.0);  // no limit given: the field as it was
  EXPECT_DOUBLE_EQ(engine.timeStep.getValue(), 0.05);
}

TEST(MethodSpec, SchedulesAsTheStudiesNameThem) {
  const Schedule s = parseSchedule("0.25:3000");
  EXPECT_EQ(s.text, "0.25:3000");
  EXPECT_DOUBLE_EQ(s.beginShare, 0.25);
  EXPECT_DOUBLE_EQ(s.rate, 3000.0);
  EXPECT_THROW(parseSchedule("all"), std::invalid_argument);
}

TEST(MethodSpec, ABadTextIsOneLineAndFalse) {
  testing::internal::CaptureStderr();
  EXPECT_FALSE(parsesOrReports([] { parseMethod("verlet:0.05"); }));
  const std::string said = testing::internal::GetCapturedStderr();
  EXPECT_EQ(said,
            "figment-bench: method \"verlet:0.05\": no integrator verlet "
            "(expected INTEGRATOR[+CONTACTS]:DT[:MAX_DT | :LIMITER:LIMIT_G])\n");
  EXPECT_TRUE(parsesOrReports([] { parseMethod("implicit:0.05"); }));
}
