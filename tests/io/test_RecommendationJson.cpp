// A recommendation's JSON and its warnings, from a recommendation made by hand.

#include <gtest/gtest.h>

#include "io/RecommendationJson.h"

namespace figment {
namespace {

SizeFit sizeNamed(std::string name, bool atRest) {
  SizeFit fit;
  fit.size = std::move(name);
  fit.drape.report.run.atRest = atRest;
  return fit;
}

Recommendation twoSizes(bool smallRests, bool largeRests) {
  Recommendation r;
  r.recommended = std::string(1, 'M');
  r.sizes.push_back(sizeNamed(std::string(1, 'S'), smallRests));
  r.sizes.push_back(sizeNamed(std::string(1, 'M'), largeRests));
  return r;
}

TEST(RecommendationJson, EachSizeSaysWhetherItsDrapeRested) {
  const std::string json = recommendationJson(twoSizes(true, false));
  EXPECT_NE(json.find("\"recommended\": \"M\""), std::string::npos) << json;
  const size_t small = json.find("\"S\": {"), large = json.find("\"M\": {");
  ASSERT_NE(small, std::string::npos) << json;
  ASSERT_NE(large, std::string::npos) << json;
  EXPECT_NE(json.find("\"at_rest\": true", small), std::string::npos) << json;
  EXPECT_NE(json.find("\"at_rest\": false", large), std::string::npos) << json;
}

TEST(RecommendationJson, ASizeStillMovingAtMaxTimeIsSaidOnceAndRestedOnesNot) {
  EXPECT_TRUE(unrestedSizeLines(twoSizes(true, true), "skirt", 10).empty());
  const std::vector<std::string> lines = unrestedSizeLines(twoSizes(true, false), "skirt", 10);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], "skirt size M was not at rest after 10 s: its fit may still change");
}

}  // namespace
}  // namespace figment
