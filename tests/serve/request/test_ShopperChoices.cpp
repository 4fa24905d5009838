// The shopper's choices: the JSON GET /api/catalogue sends lists every style with its sizes and
// colours; measurements at the default body's own give factors of 1.

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "io/GarmentCatalogue.h"
#include "serve/request/ShopperChoices.h"

using namespace figment::serve;

TEST(ShopperChoices, ListsEveryStyleWithSizesAndColours) {
  const nlohmann::json json = ShopperChoices::toJson();
  ASSERT_EQ(json["styles"].size(), ShopperChoices::styles().size());
  for (const nlohmann::json& style : json["styles"]) {
    EXPECT_NE(ShopperChoices::style(style["name"]), nullptr);
    EXPECT_EQ(style["sizes"].size(), ShopperChoices::sizes().size());
    EXPECT_FALSE(style["colours"].empty());
  }
  EXPECT_GE(json["lights"].size(), 3u);
  EXPECT_EQ(json["poses"].size(), ShopperChoices::poses().size());
  EXPECT_EQ(json["measurements"]["stature"]["unit"], "m");
}

TEST(ShopperChoices, TheDefaultBodysMeasurementsAreFactorsOfOne) {
  const auto reference = [](const char* name) { return ShopperChoices::measure(name).reference; };
  const BodyFactors same =
      ShopperChoices::bodyFactors({reference("stature"), reference("bust"), reference("waist"), reference("hips")});
  EXPECT_DOUBLE_EQ(same.height, 1.0);
  EXPECT_DOUBLE_EQ(same.chest, 1.0);
  EXPECT_DOUBLE_EQ(same.waist, 1.0);
  EXPECT_DOUBLE_EQ(same.hips, 1.0);
  // Each range stays inside the Mannequin's accepted factors [0.5, 2].
  for (const MeasureRange& range : ShopperChoices::measures()) {
    EXPECT_GT(range.minimum / range.reference, 0.5) << range.name;
    EXPECT_LT(range.maximum / range.reference, 2.0) << range.name;
  }
}

// The service's styles are the garment catalogue's (scenes/catalogue/, io/GarmentCatalogue.h):
// each is sold there, its default colour is the catalogue's first for it, and each of the
// catalogue's colours for it is one the service offers.
TEST(ShopperChoices, ItsStylesAndColoursAreTheGarmentCataloguesFiles) {
  const figment::GarmentCatalogue catalogue(figment::defaultCataloguePath());
  const std::vector<std::string>& offered = ShopperChoices::colours();
  for (const GarmentStyle& style : ShopperChoices::styles()) {
    const figment::CatalogueStyle* sold = catalogue.style(style.name);
    ASSERT_NE(sold, nullptr) << style.name;
    EXPECT_EQ(style.defaultColour, sold->colours.front()) << style.name;
    for (const std::string& colour : sold->colours)
      EXPECT_NE(std::find(offered.begin(), offered.end(), colour), offered.end()) << style.name << " " << colour;
  }
}
