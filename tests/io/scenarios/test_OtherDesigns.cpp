// Patterns the shipped catalogue does not contain (issue 44): GarmentCode designs made by
// FIGMENT's own design programs with GarmentCode's library (tests/io/data/designs/,
// scripts/designs/make-designs.py): sleeveless tops, a sleeveless dress with bust darts,
// a six-gore skirt, a yoke skirt with a gathered tier and shorts, women's and men's. Each,
// on its size's chart body, sews and drapes as the shipped ones do (test_SewnPatterns.cpp),
// with the same reader, placement and sewing: closed, at rest, nothing inside the body, no
// edge past the tear bound. A missing file fails; skipped only when MakeHuman's data is
// absent (scripts/setup.sh fetches it).
#include <gtest/gtest.h>

#include <string>

#include "support/SewnOnChartBody.h"

using namespace figment;

namespace {

// file: under tests/io/data/designs/.
using Design = test::ChartPattern;
class OtherDesigns : public test::ChartBodyPatterns {};

TEST_P(OtherDesigns, SewsClosedAndRestsOnItsSizesChartBody) {
  const Design& design = GetParam();
  test::expectSewsClosedAndRests(*bodies_, std::string(FIGMENT_SOURCE_DIR) + "/tests/io/data/designs/" + design.file,
                                 design.sex, design.size);
}

INSTANTIATE_TEST_SUITE_P(Designs, OtherDesigns,
                         ::testing::Values(Design{"tank-f-38_specification.json", Sex::Female, "M"},
                                           Design{"tank-m-48_specification.json", Sex::Male, "M"},
                                           Design{"dress-f-38_specification.json", Sex::Female, "M"},
                                           Design{"gores-f-38_specification.json", Sex::Female, "M"},
                                           Design{"yoke-f-38_specification.json", Sex::Female, "M"},
                                           Design{"shorts-f-38_specification.json", Sex::Female, "M"},
                                           Design{"shorts-m-48_specification.json", Sex::Male, "M"}));

}  // namespace
