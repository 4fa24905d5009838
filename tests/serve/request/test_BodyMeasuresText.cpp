// A measured body's four measurements as both requests read them: the ranges are the size
// chart's bodies widened by two sizes (8 cm) each side, statures MakeHuman's adults'; a value
// is a plain number within its range, kept to the millimetre; a refusal names the parameter
// as the request gave it and the range.

#include <gtest/gtest.h>

#include "serve/request/BodyMeasuresText.h"
#include "support/SmallSizeChart.h"

namespace test_BodyMeasuresText {

using namespace figment;
using namespace figment::serve;

namespace {

// Women's S and M, men's M and L.
SizeChart chart() {
  return test::smallSizeChart(2, 0, 2);
}

}  // namespace

TEST(BodyMeasuresText, RangesAreTheChartsWidenedByTwoSizes) {
  const std::vector<MeasureRange> men = BodyMeasuresText::ranges(chart(), Sex::Male);
  ASSERT_EQ(men.size(), 4u);
  EXPECT_EQ(men[0].name, "stature");
  EXPECT_EQ(men[0].minimum, 1.45);
  EXPECT_EQ(men[0].maximum, 1.95);
  EXPECT_EQ(men[1].name, "bust");
  EXPECT_NEAR(men[1].minimum, 0.88, 1e-9);
  EXPECT_NEAR(men[1].maximum, 1.08, 1e-9);
  EXPECT_NEAR(men[3].maximum, 1.12, 1e-9);
}

TEST(BodyMeasuresText, ReadsANumberWithinItsRangeToTheMillimetre) {
  const MeasureRange bust{"bust", 0.76, 0.96, 0};
  double value = 0;
  EXPECT_FALSE(BodyMeasuresText::read("chest", "0.8804", bust, value));
  EXPECT_EQ(value, 0.88);
  EXPECT_FALSE(BodyMeasuresText::read("chest", "0.96", bust, value));  // the bound is in range
  EXPECT_EQ(value, 0.96);
}

TEST(BodyMeasuresText, RefusesNamingTheParameterAsGivenAndTheRange) {
  const MeasureRange bust{"bust", 0.76, 0.96, 0};
  double value = 0.5;
  const std::optional<ParameterError> out = BodyMeasuresText::read("chest", "0.97", bust, value);
  ASSERT_TRUE(out);
  EXPECT_EQ(out->parameter, "chest");
  EXPECT_EQ(out->error, "out of range");
  EXPECT_EQ(out->value, "0.97");
  EXPECT_EQ(out->accepted, "0.76 to 0.96 (metres)");
  for (const char* text : {"", "x", "0.9m", " 0.9", "1e-1", "inf", "nan"}) {
    const std::optional<ParameterError> bad = BodyMeasuresText::read("bust", text, bust, value);
    ASSERT_TRUE(bad) << text;
    EXPECT_EQ(bad->error, "not a number") << text;
  }
  EXPECT_EQ(value, 0.5);  // untouched by a refusal
}

}  // namespace test_BodyMeasuresText
