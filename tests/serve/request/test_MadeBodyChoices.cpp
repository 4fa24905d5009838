// A made body's choices from the shipped catalogue: the styles the service dresses per sex
// (cut and sewn styles sold in that sex's sizes), the default body (the chart's M) and
// garment, and GET /api/catalogue's part listing each style's sizes per sex.

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

TEST(MadeBodyChoices, TheStylesOfASexAreThoseSoldInItsSizesCutOrSewn) {
  for (const Sex sex : {Sex::Female, Sex::Male}) {
    size_t expected = 0;
    for (const CatalogueStyle& style : sold().styles()) expected += !style.sizes(sex).empty();
    const std::vector<const CatalogueStyle*> styles = MadeBodyChoices::styles(sold(), sex);
    EXPECT_EQ(styles.size(), expected) << sexName(sex);
    for (const CatalogueStyle* style : styles) EXPECT_FALSE(style->sizes(sex).empty()) << style->name;
  }
  EXPECT_EQ(MadeBodyChoices::styleNames(sold(), Sex::Female),
            "dress, skirt, pencil, tshirt, tee, shirt, trousers, pencilskirt, circleskirt, sundress");
  EXPECT_EQ(MadeBodyChoices::styleNames(sold(), Sex::Male), "tshirt, tee, shirt, trousers");
}

TEST(MadeBodyChoices, AStyleNotDressedIsRefusedSayingWhy) {
  const auto refusal = [](Sex sex, const std::string& name) {
    auto found = MadeBodyChoices::style(sold(), sex, name, "style", name);
    EXPECT_TRUE(std::holds_alternative<ParameterError>(found)) << name;
    return std::holds_alternative<ParameterError>(found) ? std::get<ParameterError>(found) : ParameterError{};
  };
  EXPECT_EQ(refusal(Sex::Female, "cape").error, "no style named cape");
  EXPECT_EQ(refusal(Sex::Male, "pencil").error, "pencil is not sold in male sizes");
  EXPECT_EQ(refusal(Sex::Male, "sundress").error, "sundress is not sold in male sizes");
  EXPECT_EQ(refusal(Sex::Male, "cape").accepted, "male styles tshirt, tee, shirt, trousers");
  EXPECT_EQ(refusal(Sex::Male, "cape").parameter, "style");
  auto dress = MadeBodyChoices::style(sold(), Sex::Female, "dress", "style", "dress");
  ASSERT_TRUE(std::holds_alternative<const CatalogueStyle*>(dress));
  EXPECT_EQ(std::get<const CatalogueStyle*>(dress)->name, "dress");
  auto sundress = MadeBodyChoices::style(sold(), Sex::Female, "sundress", "style", "sundress");
  ASSERT_TRUE(std::holds_alternative<const CatalogueStyle*>(sundress));
  EXPECT_TRUE(std::get<const CatalogueStyle*>(sundress)->sewn());
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
  ASSERT_EQ(json["styles"].size(), sold().styles().size());
  for (const nlohmann::json& style : json["styles"]) {
    const CatalogueStyle* own = sold().style(style["name"]);
    ASSERT_NE(own, nullptr);
    for (const Sex sex : {Sex::Female, Sex::Male}) {
      const std::vector<std::string> listed = style["sizes"].value(sexName(sex), std::vector<std::string>{});
      EXPECT_EQ(listed, own->sizes(sex)) << own->name << " " << sexName(sex);
    }
    EXPECT_EQ(style["defaultColour"], own->colours.front());
    // A shopper's line for each, and whether it is sewn from a pattern.
    EXPECT_EQ(style["about"], own->about);
    EXPECT_FALSE(own->about.empty()) << own->name;
    EXPECT_EQ(style["sewn"], own->sewn());
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
