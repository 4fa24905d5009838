// CatalogueGarment: a catalogue name read from a scene gives the style cut for that size
// (the same garment figment-size drapes), its colour and fabric, or for a pattern style the
// size's pattern cut and placed on the size's chart body with its seams; a bad name is a
// read error naming the node, the field, the value and the accepted names. Made garments
// are skipped when MakeHuman's data is absent (scripts/setup.sh fetches it).

#include <gtest/gtest.h>

#include <algorithm>

#include "io/GarmentCatalogue.h"
#include "io/MakeHumanFiles.h"
#include "io/PatternFile.h"
#include "io/TargetLibrary.h"
#include "nodes/cloth/CatalogueGarment.h"
#include "sim/body/MeasuredBody.h"
#include "sim/garment/GarmentStyle.h"
#include "sim/pattern/PatternCutting.h"
#include "sim/pattern/PatternPlacement.h"
#include "support/SceneTestSupport.h"

using namespace figment::test;

namespace {

SceneRoot readGarment(const std::string& name) {
  initCoin();
  return readString("#Inventor V2.1 ascii\nSeparator { DEF Item CatalogueGarment { garment \"" + name + "\" } }\n");
}

// The women's M chart body, as SizeFitter makes it.
figment::TriangleMesh womensM(const std::string& dir) {
  figment::TargetLibrary library(dir);
  const figment::HumanModel model = figment::loadHumanModel(dir, library);
  figment::HumanParameters female;
  female.macro.gender = 0.0;
  return figment::makeMeasuredBody(
             model, female, {{"stature", 1.68}, {"bust_girth", 0.88}, {"waist_girth", 0.72}, {"hip_girth", 0.96}})
      .body;
}

}  // namespace

TEST(CatalogueGarment, ABadNameIsAReadErrorNamingWhatIsAccepted) {
  initCoin();  // before the errors are captured
  CapturedErrors errors;
  SceneRoot root = readGarment("pencil:Q");
  EXPECT_FALSE(root);
  EXPECT_NE(errors.all().find("CatalogueGarment 'Item': garment \"pencil:Q\": no size Q of pencil (female XXS, XS, S, "
                              "M, L, XL, XXL, 3XL, 4XL, 5XL, 6XL, 7XL)"),
            std::string::npos)
      << errors.all();
}

TEST(CatalogueGarment, IsTheStyleCutForItsSizesChartBody) {
  const std::string dir = figment::findMakeHumanData();
  if (dir.empty()) GTEST_SKIP() << "MakeHuman's data not found";
  SceneRoot root = readGarment("pencil:M:1F3A93");
  ASSERT_TRUE(root);
  auto* garment = find<CatalogueGarment>(root.get());
  ASSERT_NE(garment, nullptr);
  // The same garment SizeFitter grades: the pencil skirt cut round the women's M chart body.
  const figment::TriangleMesh body = womensM(dir);
  const figment::TriangleMesh cut = figment::cutGarment(*figment::findStyle("pencil"), body);
  ASSERT_EQ(garment->point.getNum(), int(cut.vertices.size()));
  for (int i = 0; i < garment->point.getNum(); i += 97)
    EXPECT_NEAR(garment->point[i][1], cut.vertices[i].y(), 1e-5) << i;
  EXPECT_EQ(garment->coordIndex.getNum(), 4 * int(cut.triangles.size()));
  const SbColor colour = garment->colour.getValue();  // 1f3a93
  EXPECT_NEAR(colour[0], 0x1f / 255.0, 1e-6);
  EXPECT_NEAR(colour[1], 0x3a / 255.0, 1e-6);
  EXPECT_NEAR(colour[2], 0x93 / 255.0, 1e-6);
  EXPECT_STREQ(garment->fabric.getValue().getString(), "cotton");
  EXPECT_EQ(garment->seams.getNum(), 0);  // generated: nothing to sew
  EXPECT_EQ(garment->panelPoint.getNum(), 0);
  // Another size is another garment: the L is wider at the hem.
  garment->garment = "pencil:L";
  ASSERT_EQ(garment->point.getNum(), int(cut.vertices.size()));  // graded from one pattern
  double wider = 0;
  for (int i = 0; i < garment->point.getNum(); ++i)
    wider = std::max(wider, double(garment->point[i][0]) - cut.vertices[i].x());
  EXPECT_GT(wider, 0.002);
}

// A pattern style's name gives its size's pattern, cut as figment-size cuts it (2 cm) and
// placed around the size's chart body, with each point's panel coordinates and the seams a
// ClothEngine sews.
TEST(CatalogueGarment, APatternStyleIsItsSizesPatternPlacedOnItsChartBody) {
  const std::string dir = figment::findMakeHumanData();
  if (dir.empty()) GTEST_SKIP() << "MakeHuman's data not found";
  SceneRoot root = readGarment("pencilskirt:38");
  ASSERT_TRUE(root);
  auto* garment = find<CatalogueGarment>(root.get());
  ASSERT_NE(garment, nullptr);
  const figment::GarmentCatalogue catalogue(figment::defaultCataloguePath());
  const figment::CatalogueItem item = catalogue.resolve("pencilskirt:38");
  const figment::UnsewnGarment cut = figment::cutPattern(
      figment::placed(figment::readPatternFile(item.patternFile), figment::placementOn(womensM(dir), 1.68)), 0.02);
  ASSERT_EQ(garment->point.getNum(), int(cut.placed.vertices.size()));
  for (int i = 0; i < garment->point.getNum(); i += 37)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(garment->point[i][k], cut.placed.vertices[i][k], 1e-5) << i;
  EXPECT_EQ(garment->coordIndex.getNum(), 4 * int(cut.placed.triangles.size()));
  ASSERT_EQ(garment->panelPoint.getNum(), garment->point.getNum());
  EXPECT_NEAR(garment->panelPoint[5][0], cut.flat[5].x(), 1e-6);
  ASSERT_GT(cut.seams.size(), 0u);
  ASSERT_EQ(garment->seams.getNum(), 2 * int(cut.seams.size()));
  EXPECT_EQ(garment->seams[0], cut.seams[0][0]);
  EXPECT_EQ(garment->seams[1], cut.seams[0][1]);
  EXPECT_STREQ(garment->fabric.getValue().getString(), "cotton");
  // A generated style after it: nothing left to sew.
  garment->garment = "pencil:M";
  EXPECT_EQ(garment->seams.getNum(), 0);
  EXPECT_GT(garment->point.getNum(), 0);
}
