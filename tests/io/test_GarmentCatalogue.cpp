// The garment catalogue's files: the shipped one lists every style with the chart's sizes
// and its colours, names resolve to a style, a chart size and a colour, and a bad name or
// file is refused naming the value and what is accepted.

#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>
#include <string>

#include "io/GarmentCatalogue.h"
#include "support/TempDir.h"

namespace {

using figment::CatalogueItem;
using figment::GarmentCatalogue;
using figment::Sex;

const GarmentCatalogue& shipped() {
  static const GarmentCatalogue catalogue(figment::defaultCataloguePath());
  return catalogue;
}

// The message `name` is refused with ("" when it resolves).
std::string refusal(const std::string& name) {
  try {
    shipped().resolve(name);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST(GarmentCatalogue, TheShippedOneSellsEveryStyleInTheChartsSizes) {
  const GarmentCatalogue& catalogue = shipped();
  ASSERT_EQ(catalogue.styles().size(), figment::garmentStyles().size());
  for (const figment::GarmentStyle& style : figment::garmentStyles()) {
    const figment::CatalogueStyle* sold = catalogue.style(style.name);
    ASSERT_NE(sold, nullptr) << style.name;
    EXPECT_FALSE(sold->colours.empty()) << style.name;
    for (const Sex sex : sold->sexes) EXPECT_EQ(sold->sizes(sex).size(), catalogue.chart().sizes(sex).size());
  }
  EXPECT_EQ(catalogue.style("tshirt")->sexes.front(), Sex::Male);
  EXPECT_EQ(catalogue.style("dress")->sexes.front(), Sex::Female);
}

TEST(GarmentCatalogue, ANameIsAStyleASizeAndAColour) {
  const CatalogueItem dress = shipped().resolve("dress:M");
  EXPECT_STREQ(dress.style->name, "dress");
  EXPECT_EQ(dress.sex, Sex::Female);
  EXPECT_EQ(dress.sizeName, "M");
  EXPECT_EQ(shipped().chart().sizes(Sex::Female)[dress.size].number, "38");
  EXPECT_EQ(dress.colour, shipped().style("dress")->colours.front());  // the default
  EXPECT_EQ(dress.name(), "dress:M:" + dress.colour);
  // A letter code names the sex the style lists first; a number either sex.
  EXPECT_EQ(shipped().resolve("tshirt:M").sex, Sex::Male);
  const CatalogueItem womens = shipped().resolve("tshirt:38");
  EXPECT_EQ(womens.sex, Sex::Female);
  EXPECT_EQ(womens.sizeName, "M");
  EXPECT_EQ(shipped().resolve("tshirt:M", Sex::Female).sex, Sex::Female);  // a request's sex
  EXPECT_EQ(shipped().resolve("pencil:S:1F3A93").colour, "1f3a93");
}

TEST(GarmentCatalogue, ABadNameSaysWhatIsAccepted) {
  EXPECT_NE(refusal("dress:Q").find("\"dress:Q\": no size Q of dress (female XXS, XS, S, M, L, XL)"), std::string::npos)
      << refusal("dress:Q");
  EXPECT_NE(refusal("coat:M").find("no style coat (styles dress, skirt, pencil, tshirt)"), std::string::npos)
      << refusal("coat:M");
  EXPECT_NE(refusal("dress").find("is not style:size[:rrggbb]"), std::string::npos);
  EXPECT_NE(refusal("dress:M:blue").find("colour blue is not six hex digits"), std::string::npos);
  EXPECT_NE(refusal("dress:48").find("no size 48"), std::string::npos);  // the men's M: dresses are women's
  EXPECT_NE(refusal("tshirt:XXS").find("male XS, S, M, L, XL, XXL; female XXS"), std::string::npos)
      << refusal("tshirt:XXS");
}

TEST(GarmentCatalogue, ABadFileIsRefusedNamingItsLine) {
  const figment::test::TempDir dir;
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream((dir.path() / name).string()) << text;
  };
  write("index.txt", "chart " + std::string(FIGMENT_SOURCE_DIR) + "/scenes/sizes/chart.txt\nstyle coat.txt\n");
  write("coat.txt", "style coat\nfemale M\ncolours 222222\n");
  const std::string index = (dir.path() / "index.txt").string();
  const auto message = [&] {
    try {
      GarmentCatalogue catalogue(index);
    } catch (const std::runtime_error& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  EXPECT_NE(message().find("coat.txt:1: style coat is not one of"), std::string::npos) << message();
  write("coat.txt", "style dress\nfemale M XXXL\ncolours 222222\n");
  EXPECT_NE(message().find("coat.txt:2: the size chart has no female size XXXL"), std::string::npos) << message();
  write("coat.txt", "style dress\nfemale M\ncolours red\n");
  EXPECT_NE(message().find("coat.txt:3: colour red is not six hex digits"), std::string::npos) << message();
  write("coat.txt", "style dress\nfemale M\ncolours 222222\n");
  EXPECT_EQ(message(), "");
  EXPECT_EQ(GarmentCatalogue(index).resolve("dress:38").sizeName, "M");
  EXPECT_NE(GarmentCatalogue(index).style("dress"), nullptr);
}
