// A size chart: sizes by sex in growing order, found by name or number, the nearest to a
// body's girths and its neighbours as the candidates; a chart whose sizes do not grow is
// refused with the size named.
#include <gtest/gtest.h>

#include "sim/garment/SizeChart.h"
#include "support/SmallSizeChart.h"

namespace test_SizeChart {

using namespace figment;

namespace {

// Women's S to L, men's M alone.
SizeChart chart() {
  return test::smallSizeChart(3, 0, 1);
}

}  // namespace

TEST(SizeChart, SizesBySexFoundByNameOrNumber) {
  const SizeChart c = chart();
  EXPECT_EQ(c.sizes(Sex::Female).size(), 3u);
  EXPECT_EQ(c.sizes(Sex::Male).size(), 1u);
  EXPECT_EQ(c.find(Sex::Female, "M"), 1);
  EXPECT_EQ(c.find(Sex::Female, "40"), 2);
  EXPECT_EQ(c.find(Sex::Male, "S"), -1);
}

TEST(SizeChart, TheNearestSizeAndItsNeighboursAreTheCandidates) {
  const SizeChart c = chart();
  EXPECT_EQ(c.nearest(Sex::Female, 0.885, 0.725, 0.955), 1);
  EXPECT_EQ(c.candidates(Sex::Female, 0.885, 0.725, 0.955), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(c.candidates(Sex::Female, 0.80, 0.64, 0.88), (std::vector<int>{0, 1}));  // below the chart
  EXPECT_EQ(c.candidates(Sex::Female, 1.00, 0.84, 1.08), (std::vector<int>{1, 2}));  // above it
  EXPECT_EQ(c.candidates(Sex::Male, 0.5, 0.5, 0.5), (std::vector<int>{0}));
}

TEST(SizeChart, SizesThatDoNotGrowAreRefused) {
  try {
    SizeChart({{Sex::Female, "S", "36", 1.68, 0.84, 0.68, 0.92}, {Sex::Female, "M", "38", 1.68, 0.88, 0.66, 0.96}});
    FAIL();
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "size female M is not larger than S in every girth");
  }
  EXPECT_THROW(SizeChart({{Sex::Male, "M", "48", 1.74, 0.96, 0.84, 0.0}}), std::invalid_argument);
  EXPECT_THROW(
      SizeChart({{Sex::Male, "M", "48", 1.74, 0.96, 0.84, 1.0}, {Sex::Male, "M", "50", 1.77, 1.0, 0.88, 1.04}}),
      std::invalid_argument);
}

}  // namespace test_SizeChart
