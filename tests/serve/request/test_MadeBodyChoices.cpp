// A made body's choices from the shipped catalogue: the styles the service dresses per sex
// (cut styles sold in that sex's sizes; sewn ones refused saying so), the default body (the
// chart's M) and garment, and GET /api/catalogue's part listing each style's sizes per sex.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "serve/request/MadeBodyChoices.h"
#include "support/ShippedCatalogue.h"

using namespace figment;
using namespace figment::serve;

namespace {

const GarmentCatalogue& sold() {
  return test::shippedCatalogue();
}

}  // namespace

TEST(MadeBodyChoices, TheStylesOfASexAreTheCutOnesSoldInItsSizes) {
  for (const Sex sex : {Sex::Female, Sex::Male}) {
    size_t expected = 0;
    for (const CatalogueStyle& style : sold().styles()) expected += !style.sewn() && !style.sizes(sex).empty();
    const std::vector<const CatalogueStyle*> styles = MadeBodyChoices::styles(sold(), sex);
    EXPECT_EQ(styles.size(), expected) << sexName(sex);
    for (const CatalogueStyle* style : styles) {
      EXPECT_FALSE(style->sewn()) << style->name;
      EXPECT_FALSE(style->sizes(sex).empty()) << style->name;
    }
  }
  EXPECT_EQ(MadeBodyChoices::styleNames(sold(), Sex::Female), "dress, skirt, pencil, tshirt");
  EXPECT_EQ(MadeBodyChoices::styleNames(sold(), Sex::Male), "tshirt");
}

TEST(MadeBodyChoices, AStyleNotDressedIsRefusedSayingWhy) {
  const auto refusal = [](Sex sex, const std::string& name) {
    auto found = MadeBodyChoices::style(sold(), sex, name, "style", name);
    EXPECT_TRUE(std::holds_alternative<ParameterError>(found)) << name;
    return std::holds_alternative<ParameterError>(found) ? std::get<ParameterError>(found) : ParameterError{};
  };
  EXPECT_EQ(refusal(Sex::Female, "cape").error, "no style named cape");
  EXPECT_EQ(refusal(Sex::Male, "pencil").error, "pencil is not sold in male sizes");
  EXPECT_NE(refusal(Sex::Female, "sundress").error.find("sewn from a pattern"), std::string::npos);
  EXPECT_EQ(refusal(Sex::Male, "cape").accepted, "male styles tshirt");
  EXPECT_EQ(refusal(Sex::Male, "cape").parameter, "style");
  auto dress = MadeBodyChoices::style(sold(), Sex::Female, "dress", "style", "dress");
  ASSERT_TRUE(std::holds_alternative<const CatalogueStyle*>(dress));
  EXPECT_EQ(std::get<const CatalogueStyle*>(dress)->name, "dress");
}

TEST(MadeBodyChoices, TheDefaultBodyIsTheChartsMInTheFirstStyleSold) {
  for (const Sex sex : {Sex::Female, Sex::Male}) {
    const ChartSize& m = sold().chart().sizes(sex)[size_t(sold().chart().find(sex, "M"))];
    const BodyMeasures body = MadeBodyChoices::defaultBody(sold(), sex);
    EXPECT_DOUBLE_EQ(body.stature, m.stature);
    EXPECT_DOUBLE_EQ(body.bust, m.bust);
    EXPECT_DOUBLE_EQ(body.waist, m.waist);
    EXPECT_DOUBLE_EQ(body.hips, m.hip);
  }
  EXPECT_EQ(MadeBodyChoices::defaultGarment(sold(), Sex::Female),
            std::make_pair(std::string("dress"), std::string("M")));
  EXPECT_EQ(MadeBodyChoices::defaultGarment(sold(), Sex::Male),
            std::make_pair(std::string("tshirt"), std::string("M")));
}

TEST(MadeBodyChoices, TheCatalogueListsEachStylesSizesPerSexFromTheCatalogue) {
  const nlohmann::json json = MadeBodyChoices::toJson(sold());
  size_t styles = 0;
  for (const CatalogueStyle& style : sold().styles()) styles += !style.sewn();
  ASSERT_EQ(json["styles"].size(), styles);
  for (const nlohmann::json& style : json["styles"]) {
    const CatalogueStyle* own = sold().style(style["name"]);
    ASSERT_NE(own, nullptr);
    for (const Sex sex : {Sex::Female, Sex::Male}) {
      const std::vector<std::string> listed = style["sizes"].value(sexName(sex), std::vector<std::string>{});
      EXPECT_EQ(listed, own->sizes(sex)) << own->name << " " << sexName(sex);
    }
    EXPECT_EQ(style["defaultColour"], own->colours.front());
  }
  for (const Sex sex : {Sex::Female, Sex::Male}) {
    EXPECT_EQ(json["sizes"][sexName(sex)].size(), sold().chart().sizes(sex).size());
    EXPECT_DOUBLE_EQ(json["measurements"][sexName(sex)]["bust"]["default"].get<double>(),
                     MadeBodyChoices::defaultBody(sold(), sex).bust);
  }
  EXPECT_EQ(json["poses"].size(), 5u);
  EXPECT_EQ(json["underwear"]["default"], "on");
  EXPECT_EQ(json["underwear"]["values"], nlohmann::json({"on", "off"}));
}
