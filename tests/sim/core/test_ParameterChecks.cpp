// The checks at sim/'s API: each refusal is one std::invalid_argument naming the field, its
// value as written, and the rule.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "sim/core/ParameterChecks.h"
#include "support/Refusal.h"

using namespace figment;
using figment::test::refusal;

namespace {

TEST(ParameterChecks, PositiveRefusesZeroAndNamesFieldAndValue) {
  EXPECT_EQ(refusal([] { requirePositive("thickness", 0.001); }), "");
  EXPECT_EQ(refusal([] { requirePositive("thickness", -0.001); }), "thickness = -0.001 must be > 0");
  EXPECT_EQ(refusal([] { requirePositive("thickness", 0.0); }), "thickness = 0 must be > 0");
}

TEST(ParameterChecks, NonNegativeAcceptsZero) {
  EXPECT_EQ(refusal([] { requireNonNegative("friction", 0.0); }), "");
  EXPECT_EQ(refusal([] { requireNonNegative("friction", -1.0); }), "friction = -1 must be >= 0");
}

TEST(ParameterChecks, OpenRangeRefusesItsEnds) {
  EXPECT_EQ(refusal([] { requireOpenRange("poissonRatio", 0.3, -1.0, 0.5); }), "");
  EXPECT_EQ(refusal([] { requireOpenRange("poissonRatio", 0.5, -1.0, 0.5); }),
            "poissonRatio = 0.5 must be in (-1, 0.5)");
  EXPECT_EQ(refusal([] { requireOpenRange("poissonRatio", -1.0, -1.0, 0.5); }),
            "poissonRatio = -1 must be in (-1, 0.5)");
}

TEST(ParameterChecks, EveryCheckRefusesWhatIsNotANumber) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(refusal([&] { requireFinite("timeStep", inf); }), "timeStep = inf must be a finite number");
  EXPECT_EQ(refusal([&] { requirePositive("timeStep", nan); }), "timeStep = nan must be a finite number");
  EXPECT_EQ(refusal([&] { requireNonNegative("timeStep", -inf); }), "timeStep = -inf must be a finite number");
  EXPECT_EQ(refusal([&] { requireOpenRange("timeStep", nan, 0.0, 1.0); }), "timeStep = nan must be a finite number");
}

TEST(ParameterChecks, FormatNumberIsTheShortestTextThatReadsBack) {
  EXPECT_EQ(formatNumber(0.001), "0.001");
  EXPECT_EQ(formatNumber(0.0005), "5e-04");  // shorter than 0.0005
  EXPECT_EQ(formatNumber(-1e-05), "-1e-05");
  EXPECT_EQ(formatNumber(0.1), "0.1");
  const double third = 1.0 / 3.0;
  EXPECT_EQ(std::stod(formatNumber(third)), third);
}

}  // namespace

TEST(ParameterChecksWholeNumber, TheWholeTextOrNothing) {
  EXPECT_EQ(figment::wholeNumber("0.05"), 0.05);
  EXPECT_EQ(figment::wholeNumber("1.5e-4"), 1.5e-4);
  EXPECT_EQ(figment::wholeNumber("-3"), -3.0);
  for (const char* bad : {"", "x", "0.05s", "1e", " "}) EXPECT_FALSE(figment::wholeNumber(bad)) << '"' << bad << '"';
}
