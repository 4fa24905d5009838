// A shop's own garments (issue 44): every style of the shipped GarmentCode patterns
// (scenes/patterns/), in the chart's middle size of each sex it is made for and in one of the
// sizes past the old chart (women's 44-54, men's 56-62), placed on that size's chart body
// (MakeHuman's, made to the chart's stature and girths), sewn shut and draped as figment-sew
// and a ClothEngine with seams do. Each sews closed (every seam pair merged: no gap left),
// rests, leaves no node inside the body and no edge past the tear bound. One test per
// pattern, so ctest spreads them over its jobs. Every shipped size is sewn by
// scripts/pattern-figures.py (docs/patterns.csv); the large sizes here are one a style and
// sex, the largest each style lists, to keep the suite's time to about a minute more.
// Skipped when MakeHuman's data is absent (scripts/setup.sh fetches it).
#include <gtest/gtest.h>

#include <string>

#include "support/SewnOnChartBody.h"

using namespace figment;

namespace {

// file: under scenes/patterns/.
using ShippedPattern = test::ChartPattern;
class SewnPatterns : public test::ChartBodyPatterns {};

TEST_P(SewnPatterns, SewsClosedAndRestsOnItsSizesChartBody) {
  const ShippedPattern& shipped = GetParam();
  test::expectSewsClosedAndRests(*bodies_, std::string(FIGMENT_SOURCE_DIR) + "/scenes/patterns/" + shipped.file,
                                 shipped.sex, shipped.size);
}

INSTANTIATE_TEST_SUITE_P(MiddleSizes, SewnPatterns,
                         ::testing::Values(ShippedPattern{"tshirt/tshirt-f-38_specification.json", Sex::Female, "M"},
                                           ShippedPattern{"tshirt/tshirt-m-48_specification.json", Sex::Male, "M"},
                                           ShippedPattern{"shirt/shirt-f-38_specification.json", Sex::Female, "M"},
                                           // Placed with its shoulders on the body's and its sleeves clear of
                                           // the forearms (sim/pattern/ShoulderRest.h, LimbClearance.h): torn
                                           // and open before.
                                           ShippedPattern{"shirt/shirt-m-48_specification.json", Sex::Male, "M"},
                                           ShippedPattern{"trousers/trousers-f-38_specification.json", Sex::Female,
                                                          "M"},
                                           ShippedPattern{"trousers/trousers-m-48_specification.json", Sex::Male, "M"},
                                           ShippedPattern{"pencil/pencil-f-38_specification.json", Sex::Female, "M"},
                                           ShippedPattern{"circle/circle-f-38_specification.json", Sex::Female, "M"},
                                           ShippedPattern{"dress/dress-f-38_specification.json", Sex::Female, "M"}));

// The largest size each style lists (scenes/catalogue/): the chart's largest (women's 54,
// men's 62), or the largest that ships (the trousers: women's 52, men's 56) and sews clean
// (both shirts and the dress: docs/patterns.md, known limits).
INSTANTIATE_TEST_SUITE_P(
    LargestSizes, SewnPatterns,
    ::testing::Values(ShippedPattern{"tshirt/tshirt-f-54_specification.json", Sex::Female, "7XL"},
                      ShippedPattern{"tshirt/tshirt-m-62_specification.json", Sex::Male, "6XL"},
                      ShippedPattern{"shirt/shirt-f-50_specification.json", Sex::Female, "5XL"},
                      ShippedPattern{"shirt/shirt-m-60_specification.json", Sex::Male, "5XL"},
                      ShippedPattern{"trousers/trousers-f-52_specification.json", Sex::Female, "6XL"},
                      ShippedPattern{"trousers/trousers-m-56_specification.json", Sex::Male, "3XL"},
                      ShippedPattern{"pencil/pencil-f-54_specification.json", Sex::Female, "7XL"},
                      ShippedPattern{"circle/circle-f-54_specification.json", Sex::Female, "7XL"},
                      ShippedPattern{"dress/dress-f-50_specification.json", Sex::Female, "5XL"}));

}  // namespace
