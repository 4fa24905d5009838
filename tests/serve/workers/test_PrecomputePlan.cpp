// What figment-precompute queues: a request file's lines as canonical requests (comments
// and blank lines skipped, each request once, a bad line named by file and line); the
// catalogue's grid as every style × size × body × pose × view.

#include <gtest/gtest.h>

#include <set>

#include "serve/request/RenderRequest.h"
#include "serve/request/ShopperChoices.h"
#include "serve/workers/PrecomputePlan.h"

using namespace figment::serve;

TEST(PrecomputePlan, ReadsOneRequestALineInCanonicalText) {
  const auto plan = PrecomputePlan::fromLines(
      "# a comment\n\noutfit=dress:M&view=front\r\n  outfit=skirt%3AL&size=64x80\noutfit=dress:M&view=0,0\n",
      "jobs.txt");
  ASSERT_EQ(plan.index(), 0u) << std::get<1>(plan);
  const PrecomputePlan::Requests& requests = std::get<0>(plan);
  ASSERT_EQ(requests.size(), 2u);  // front is 0,0: the third line is the first again
  for (const std::string& request : requests) {
    auto parsed = RenderRequest::parseCanonical(request);
    ASSERT_EQ(parsed.index(), 0u) << request;
    EXPECT_EQ(std::get<RenderRequest>(parsed).canonical(), request);
  }
  const RenderRequest skirt = std::get<RenderRequest>(RenderRequest::parseCanonical(requests[1]));
  ASSERT_EQ(skirt.outfit.size(), 1u);
  EXPECT_EQ(skirt.outfit[0].style, "skirt");
  EXPECT_EQ(skirt.outfit[0].size, "L");
  EXPECT_EQ(skirt.width, 64);
}

TEST(PrecomputePlan, ABadLineIsNamedByFileAndLine) {
  const auto plan = PrecomputePlan::fromLines("outfit=dress:M\n\nstature=3\n", "jobs.txt");
  ASSERT_EQ(plan.index(), 1u);
  const std::string& error = std::get<1>(plan);
  EXPECT_EQ(error.rfind("jobs.txt:3: stature=3: ", 0), 0u) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos);
}

TEST(PrecomputePlan, TheCatalogueGridIsEveryStyleSizeBodyPoseAndView) {
  PrecomputePlan::Grid grid;
  grid.bodies = {"1.60,0.85,0.68,0.92", "1.75,0.95,0.80,1.00"};
  grid.poses = {"rest"};
  grid.views = {"front", "back", "45,10"};
  grid.size = "64x80";
  const auto plan = PrecomputePlan::fromCatalogue(grid);
  ASSERT_EQ(plan.index(), 0u) << std::get<1>(plan);
  const PrecomputePlan::Requests& requests = std::get<0>(plan);
  const size_t expected = ShopperChoices::styles().size() * ShopperChoices::sizes().size() * 2 * 1 * 3;
  EXPECT_EQ(requests.size(), expected);
  EXPECT_EQ(std::set<std::string>(requests.begin(), requests.end()).size(), expected);
  for (const std::string& request : requests) {
    const RenderRequest parsed = std::get<RenderRequest>(RenderRequest::parseCanonical(request));
    ASSERT_EQ(parsed.outfit.size(), 1u);
    EXPECT_EQ(parsed.outfit[0].colour, ShopperChoices::style(parsed.outfit[0].style)->defaultColour);
    EXPECT_EQ(parsed.pose, "rest");
  }
  PrecomputePlan::Grid defaults;
  const auto every = PrecomputePlan::fromCatalogue(defaults);
  ASSERT_EQ(every.index(), 0u);
  EXPECT_EQ(std::get<0>(every).size(),
            ShopperChoices::styles().size() * ShopperChoices::sizes().size() * ShopperChoices::poses().size());
}

TEST(PrecomputePlan, ABadBodyOrPoseIsNamed) {
  PrecomputePlan::Grid grid;
  grid.bodies = {"1.60,0.85"};
  ASSERT_EQ(PrecomputePlan::fromCatalogue(grid).index(), 1u);
  EXPECT_EQ(std::get<1>(PrecomputePlan::fromCatalogue(grid)).rfind("--body 1.60,0.85: ", 0), 0u);
  grid.bodies = {};
  grid.poses = {"cartwheel"};
  ASSERT_EQ(PrecomputePlan::fromCatalogue(grid).index(), 1u);
  EXPECT_EQ(std::get<1>(PrecomputePlan::fromCatalogue(grid)).rfind("pose=cartwheel: ", 0), 0u);
}
