// Sizes graded beyond a chart's ends by its own end steps, and the 60 measurement sets the
// made bodies are checked over (issue 30): dimensions, names and numbers, and refusals.
#include <gtest/gtest.h>

#include "sim/garment/SizeGrading.h"
#include "support/SmallSizeChart.h"

using namespace figment;

namespace {

// Women's S to L, men's L to XXL.
SizeChart chart() {
  return test::smallSizeChart(3, 1, 3);
}

}  // namespace

TEST(SizeGrading, SizesBeyondEachEndStepAsTheChartsEnds) {
  const std::vector<ChartSize> women = gradedSizes(chart(), Sex::Female, 2);
  ASSERT_EQ(women.size(), 7u);
  EXPECT_EQ(women[0].name, "S-2");
  EXPECT_EQ(women[0].number, "32");
  EXPECT_NEAR(women[0].bust, 0.76, 1e-12);
  EXPECT_NEAR(women[0].waist, 0.60, 1e-12);
  EXPECT_NEAR(women[0].hip, 0.84, 1e-12);
  EXPECT_NEAR(women[0].stature, 1.68, 1e-12);
  EXPECT_EQ(women[1].name, "S-1");
  EXPECT_EQ(women[2].name, "S");  // the chart's own sizes between, as they are
  EXPECT_EQ(women[6].name, "L+2");
  EXPECT_EQ(women[6].number, "44");
  EXPECT_NEAR(women[6].hip, 1.08, 1e-12);
  // the men's last step is 2 cm in stature and 6 cm in waist: so are the sizes above it
  const std::vector<ChartSize> men = gradedSizes(chart(), Sex::Male, 2);
  EXPECT_EQ(men.back().number, "58");
  EXPECT_NEAR(men.back().stature, 1.86, 1e-12);
  EXPECT_NEAR(men.back().waist, 1.10, 1e-12);
  EXPECT_NEAR(men.front().stature, 1.71, 1e-12);  // below: the first step, 3 cm
  EXPECT_NEAR(men.front().waist, 0.80, 1e-12);
  // still a chart: every girth grows from size to size
  EXPECT_NO_THROW(SizeChart(gradedSizes(chart(), Sex::Female, 2)));
  EXPECT_EQ(gradedSizes(chart(), Sex::Female, 0).size(), 3u);
}

TEST(SizeGrading, MeasurementSetsAreEachSizeAtEachStatureOffset) {
  const std::vector<ChartSize> sets = measurementSets(chart(), 2, {-0.08, 0.0, 0.08});
  ASSERT_EQ(sets.size(), (7u + 7u) * 3u);
  EXPECT_EQ(sets[0].sex, Sex::Female);
  EXPECT_NEAR(sets[0].stature, 1.60, 1e-12);
  EXPECT_NEAR(sets[1].stature, 1.68, 1e-12);
  EXPECT_NEAR(sets[2].stature, 1.76, 1e-12);
  EXPECT_EQ(sets[2].name, sets[0].name);
  EXPECT_EQ(sets.back().sex, Sex::Male);
  EXPECT_NEAR(sets.back().stature, 1.94, 1e-12);
  // a chart of 6 + 6 sizes gives 48 sets: two sizes below each sex's smallest, none above its
  // largest (issue 43: the widened chart's largest are as far as MakeHuman reaches)
  std::vector<ChartSize> twelve;
  // appended, not "F" + std::to_string(i): GCC 12 warns (-Wrestrict) on that operator+
  const auto named = [](char sex, int i) { return std::string(1, sex).append(std::to_string(i)); };
  for (int i = 0; i < 6; ++i) {
    twelve.push_back({Sex::Female, named('F', i), std::to_string(32 + 2 * i), 1.68, 0.76 + 0.04 * i, 0.60 + 0.04 * i,
                      0.84 + 0.04 * i});
    twelve.push_back({Sex::Male, named('M', i), std::to_string(44 + 2 * i), 1.68 + 0.03 * i, 0.88 + 0.04 * i,
                      0.76 + 0.04 * i, 0.92 + 0.04 * i});
  }
  const std::vector<ChartSize> checked = bodyCheckSets(SizeChart(twelve));
  ASSERT_EQ(checked.size(), 48u);
  EXPECT_EQ(checked[0].number, "28");
  EXPECT_EQ(checked[23].number, "42");  // the women's largest, 8 cm taller: the last women's set
  EXPECT_NEAR(checked[23].stature, 1.76, 1e-12);
  EXPECT_EQ(checked.back().number, "54");
}

TEST(SizeGrading, SizesBelowAndAboveAreCountedApart) {
  const std::vector<ChartSize> women = gradedSizes(chart(), Sex::Female, 2, 0);
  ASSERT_EQ(women.size(), 5u);
  EXPECT_EQ(women.front().name, "S-2");
  EXPECT_EQ(women.back().name, "L");
  const std::vector<ChartSize> men = gradedSizes(chart(), Sex::Male, 0, 1);
  ASSERT_EQ(men.size(), 4u);
  EXPECT_EQ(men.front().name, "L");
  EXPECT_EQ(men.back().name, "XXL+1");
  EXPECT_NEAR(men.back().waist, 1.04, 1e-12);  // the men's last step: 6 cm of waist
  EXPECT_EQ(measurementSets(chart(), 2, 0, {0.0}).size(), 5u + 5u);
  EXPECT_THROW(gradedSizes(chart(), Sex::Female, 0, -1), std::invalid_argument);
}

TEST(SizeGrading, AChartTooShortOrGradedBelowZeroIsRefused) {
  const SizeChart one(
      {{Sex::Female, "M", "38", 1.68, 0.88, 0.72, 0.96}, {Sex::Male, "M", "48", 1.74, 0.96, 0.84, 1.0}});
  EXPECT_THROW(gradedSizes(one, Sex::Female, 2), std::invalid_argument);
  EXPECT_THROW(gradedSizes(chart(), Sex::Female, -1), std::invalid_argument);
  EXPECT_THROW(gradedSizes(chart(), Sex::Female, 30), std::invalid_argument);  // a waist of 0.68 - 30 x 0.04 m
  EXPECT_THROW(measurementSets(chart(), 0, {-2.0}), std::invalid_argument);
  // numbers that are no whole numbers: the graded size's name stands for its number
  const SizeChart lettered({{Sex::Female, "S", "S", 1.68, 0.84, 0.68, 0.92},
                            {Sex::Female, "M", "M", 1.68, 0.88, 0.72, 0.96},
                            {Sex::Male, "M", "M", 1.74, 0.96, 0.84, 1.0},
                            {Sex::Male, "L", "L", 1.77, 1.0, 0.88, 1.04}});
  EXPECT_EQ(gradedSizes(lettered, Sex::Female, 1).front().number, "S-1");
}
