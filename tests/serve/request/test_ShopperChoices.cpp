// The Mannequin's choices and the shared ones: the JSON GET /api/catalogue sends lists the
// Mannequin's styles (the paper's patterns, in no sizes) with their colours, its poses and
// ranges, and every body's lights and skin tones; measurements at the Mannequin's own give
// factors of 1.

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "io/GarmentCatalogue.h"
#include "serve/request/ShopperChoices.h"

namespace test_ShopperChoices {

using namespace figment::serve;

TEST(ShopperChoices, ListsTheMannequinsStylesInNoSizesWithTheirColours) {
  const nlohmann::json json = ShopperChoices::mannequinJson();
  ASSERT_EQ(json["styles"].size(), ShopperChoices::styles().size());
  for (const nlohmann::json& style : json["styles"]) {
    EXPECT_NE(ShopperChoices::style(style["name"]), nullptr);
    EXPECT_FALSE(style.contains("sizes")) << style.dump();  // the paper's patterns as cut
    EXPECT_FALSE(style["colours"].empty());
  }
  EXPECT_EQ(json["poses"].size(), ShopperChoices::poses().size());
  EXPECT_EQ(json["measurements"]["stature"]["unit"], "m");
  const nlohmann::json shared = ShopperChoices::sharedJson();
  EXPECT_EQ(shared["lights"].size(), ShopperChoices::lights().size());
  EXPECT_EQ(shared["skinTones"].size(), ShopperChoices::skinTones().size());
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

// The Mannequin's styles are sold in the garment catalogue too (scenes/catalogue/,
// io/GarmentCatalogue.h): its default colour is the catalogue's first for it, and each of
// the catalogue's colours for it is one the service suggests.
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

}  // namespace test_ShopperChoices
