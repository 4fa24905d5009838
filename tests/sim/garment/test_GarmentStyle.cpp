// The catalogue's styles: found by name, listed in their fixed order, each with a fabric that
// is a material preset, regions its fit may be told for, and its ease as designed.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "sim/cloth/MaterialPresets.h"
#include "sim/fit/FitRegion.h"
#include "sim/garment/GarmentStyle.h"

using namespace figment;

namespace {

TEST(GarmentStyle, FindsEachStyleByNameAndNoOther) {
  EXPECT_EQ(styleNames(), "dress, skirt, tshirt, pencil");
  for (const GarmentStyle& style : garmentStyles()) EXPECT_EQ(findStyle(style.name), &style) << style.name;
  EXPECT_EQ(findStyle("Dress"), nullptr);
  EXPECT_EQ(findStyle(""), nullptr);
  EXPECT_EQ(findStyle("skirt")->kind, StyleKind::FlaredSkirt);
  EXPECT_FALSE(findStyle("skirt")->warmStarts);  // held by friction alone: no warm start
}

TEST(GarmentStyle, EachStylesFabricAndRegionsAreKnown) {
  const std::vector<std::string>& regions = fitRegionNames();
  for (const GarmentStyle& style : garmentStyles()) {
    EXPECT_TRUE(materialPreset(style.fabric).has_value()) << style.name << ": " << style.fabric;
    EXPECT_FALSE(style.regions.empty()) << style.name;
    for (const std::string& region : style.regions)
      EXPECT_NE(std::find(regions.begin(), regions.end(), region), regions.end()) << style.name << ": " << region;
  }
}

TEST(GarmentStyle, ASkirtHasNoBustEase) {
  for (const char* skirt : {"skirt", "pencil"}) EXPECT_EQ(findStyle(skirt)->ease.bust, 0.0) << skirt;
  EXPECT_DOUBLE_EQ(findStyle("pencil")->ease.hip, 0.04);  // m of girth: docs/sizes.md
}

}  // namespace
