// ClothParameters::validate: the run's length in steps is bounded, so a slip of the
// exponent (timeStep 1e-30, found by fuzzing figment-view, issue 15) is said, not run.

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "sim/cloth/ClothParameters.h"

using namespace figment;

namespace {

std::string message(const ClothParameters& p) {
  try {
    p.validate();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ClothParameters, TheDefaultsAreValid) {
  EXPECT_EQ(message(ClothParameters{}), "");
}

TEST(ClothParameters, RefusesATimeStepThatWouldTakeMoreThanTenMillionSteps) {
  ClothParameters p;
  p.maxTime = 5.0;
  p.timeStep = 1e-30;
  EXPECT_EQ(message(p), "timeStep = 1e-30 would take 5e+30 steps to maxTime = 5, more than 1e+07");
  p.timeStep = 4e-7;  // 12.5 million steps
  EXPECT_EQ(message(p).rfind("timeStep = 4e-07 would take", 0), 0u) << message(p);
  p.timeStep = 1e-6;  // 5 million
  EXPECT_EQ(message(p), "");
  p.timeStep = 5e-310;  // so small that maxTime / timeStep is infinite
  EXPECT_EQ(message(p).rfind("timeStep = 5e-310 would take", 0), 0u) << message(p);
}
