// What figment-precompute queues: a request file's lines as canonical requests (comments
// and blank lines skipped, each request once, a bad line named by file and line), checked
// against the shipped garment catalogue as the server checks them; the catalogue's grid as
// every style × the sizes it is sold in × sex × body × pose × view.

#include <gtest/gtest.h>

#include <set>

#include "serve/request/MadeBodyChoices.h"
#include "serve/request/RenderRequest.h"
#include "serve/workers/PrecomputePlan.h"
#include "tests/support/ShippedCatalogue.h"

using namespace figment::serve;
using figment::test::shippedCatalogue;

namespace {

RenderRequest parsed(const std::string& canonical) {
  return std::get<RenderRequest>(RenderRequest::parseCanonical(canonical, &shippedCatalogue()));
}

// Every style sold to `sex` × each of its sizes.
size_t garmentsFor(figment::Sex sex) {
  size_t count = 0;
  for (const figment::CatalogueStyle* style : MadeBodyChoices::styles(shippedCatalogue(), sex))
    count += style->sizes(sex).size();
  return count;
}

}  // namespace

TEST(PrecomputePlan, ReadsOneRequestALineInCanonicalText) {
  const auto plan = PrecomputePlan::fromLines(
      "# a comment\n\noutfit=dress:M&view=front\r\n  outfit=skirt%3AL&size=64x80\noutfit=dress:M&view=0,0\n"
      "body=mannequin&outfit=skirt\n",
      "jobs.txt", &shippedCatalogue());
  ASSERT_EQ(plan.index(), 0u) << std::get<1>(plan);
  const PrecomputePlan::Requests& requests = std::get<0>(plan);
  ASSERT_EQ(requests.size(), 3u);  // front is 0,0: the third line is the first again
  for (const std::string& request : requests) {
    auto again = RenderRequest::parseCanonical(request, &shippedCatalogue());
    ASSERT_EQ(again.index(), 0u) << request;
    EXPECT_EQ(std::get<RenderRequest>(again).canonical(), request);
  }
  const RenderRequest skirt = parsed(requests[1]);
  ASSERT_EQ(skirt.outfit.size(), 1u);
  EXPECT_EQ(skirt.outfit[0].style, "skirt");
  EXPECT_EQ(skirt.outfit[0].size, "L");
  EXPECT_EQ(skirt.sex, "female");  // the made body by default
  EXPECT_EQ(skirt.width, 64);
  EXPECT_TRUE(parsed(requests[2]).mannequin());
}

TEST(PrecomputePlan, ABadLineIsNamedByFileAndLine) {
  const auto plan = PrecomputePlan::fromLines("outfit=dress:M\n\nstature=3\n", "jobs.txt", &shippedCatalogue());
  ASSERT_EQ(plan.index(), 1u);
  const std::string& error = std::get<1>(plan);
  EXPECT_EQ(error.rfind("jobs.txt:3: stature=3: ", 0), 0u) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos);
  // Without a catalogue only the Mannequin's requests pass.
  const auto mannequin = PrecomputePlan::fromLines("body=mannequin\noutfit=dress:M\n", "jobs.txt", nullptr);
  ASSERT_EQ(mannequin.index(), 1u);
  EXPECT_EQ(std::get<1>(mannequin).rfind("jobs.txt:2: body=made: ", 0), 0u) << std::get<1>(mannequin);
}

TEST(PrecomputePlan, TheCatalogueGridIsEverySoldStyleSizeSexBodyPoseAndView) {
  PrecomputePlan::Grid grid;
  grid.sexes = {"female"};
  grid.bodies = {"1.60,0.85,0.68,0.92", "1.75,0.95,0.80,1.00"};
  grid.poses = {"rest"};
  grid.views = {"front", "back", "45,10"};
  grid.size = "64x80";
  const auto plan = PrecomputePlan::fromCatalogue(grid, shippedCatalogue());
  ASSERT_EQ(plan.index(), 0u) << std::get<1>(plan);
  const PrecomputePlan::Requests& requests = std::get<0>(plan);
  const size_t expected = garmentsFor(figment::Sex::Female) * 2 * 1 * 3;
  EXPECT_EQ(requests.size(), expected);
  EXPECT_EQ(std::set<std::string>(requests.begin(), requests.end()).size(), expected);
  for (const std::string& request : requests) {
    const RenderRequest made = parsed(request);
    ASSERT_EQ(made.outfit.size(), 1u);
    EXPECT_EQ(made.sex, "female");
    EXPECT_EQ(made.outfit[0].colour, shippedCatalogue().style(made.outfit[0].style)->colours.front());
    EXPECT_EQ(made.pose, "rest");
  }
  // By default: both sexes, each at its default body, at rest, from the front; the men's
  // sizes of the tshirt as well as the women's.
  const auto every = PrecomputePlan::fromCatalogue(PrecomputePlan::Grid{}, shippedCatalogue());
  ASSERT_EQ(every.index(), 0u) << std::get<1>(every);
  EXPECT_EQ(std::get<0>(every).size(), garmentsFor(figment::Sex::Female) + garmentsFor(figment::Sex::Male));
  size_t men = 0;
  for (const std::string& request : std::get<0>(every)) men += parsed(request).sex == "male";
  EXPECT_EQ(men, garmentsFor(figment::Sex::Male));
  EXPECT_GT(men, 0u);
  // Posed, a sewn style is left out (it is sewn on the standing body); the cut ones are posed.
  PrecomputePlan::Grid walking;
  walking.sexes = {"male"};
  walking.poses = {"rest", "walking"};
  const auto posed = PrecomputePlan::fromCatalogue(walking, shippedCatalogue());
  ASSERT_EQ(posed.index(), 0u) << std::get<1>(posed);
  size_t cut = 0, sewnWalking = 0;
  for (const figment::CatalogueStyle* style : MadeBodyChoices::styles(shippedCatalogue(), figment::Sex::Male))
    cut += style->sewn() ? 0 : style->sizes(figment::Sex::Male).size();
  for (const std::string& request : std::get<0>(posed)) {
    const RenderRequest made = parsed(request);
    sewnWalking += made.pose == "walking" && shippedCatalogue().style(made.outfit[0].style)->sewn();
  }
  EXPECT_EQ(sewnWalking, 0u);
  EXPECT_EQ(std::get<0>(posed).size(), garmentsFor(figment::Sex::Male) + cut);
  EXPECT_GT(cut, 0u);
}

TEST(PrecomputePlan, ABadSexBodyOrPoseIsNamed) {
  PrecomputePlan::Grid grid;
  grid.bodies = {"1.60,0.85"};
  const auto body = PrecomputePlan::fromCatalogue(grid, shippedCatalogue());
  ASSERT_EQ(body.index(), 1u);
  EXPECT_EQ(std::get<1>(body).rfind("--body 1.60,0.85: ", 0), 0u) << std::get<1>(body);
  grid.bodies = {};
  grid.poses = {"cartwheel"};
  const auto pose = PrecomputePlan::fromCatalogue(grid, shippedCatalogue());
  ASSERT_EQ(pose.index(), 1u);
  EXPECT_EQ(std::get<1>(pose).rfind("pose=cartwheel: ", 0), 0u) << std::get<1>(pose);
  grid.poses = {};
  grid.sexes = {"other"};
  const auto sex = PrecomputePlan::fromCatalogue(grid, shippedCatalogue());
  ASSERT_EQ(sex.index(), 1u);
  EXPECT_EQ(std::get<1>(sex).rfind("--sex other: ", 0), 0u) << std::get<1>(sex);
}
