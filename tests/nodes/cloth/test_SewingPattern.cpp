// SewingPattern: a pattern file read from a scene gives its panels cut into cloth, their
// panel coordinates and the seam pairs; a ClothEngine given them sews the panels shut. A
// pattern that does not read, or a spacing out of range, is a read error naming the node.

#include <Inventor/engines/SoEngineOutput.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "nodes/cloth/ClothEngine.h"
#include "nodes/cloth/SewingPattern.h"
#include "support/SceneTestSupport.h"
#include "support/TempDir.h"

namespace test_SewingPattern {

using namespace figment::test;

namespace {

const std::string kPencil = std::string(FIGMENT_SOURCE_DIR) + "/tests/io/data/patterns/pencil-f-46_specification.json";

SceneRoot readPattern(const std::string& file, const std::string& fields = "") {
  initCoin();
  return readString("#Inventor V2.1 ascii\nSeparator { DEF Skirt SewingPattern { fileName \"" + file + "\" " + fields +
                    " } }\n");
}

// Two 40 x 30 cm panels 40 cm apart, front facing +z, back facing -z (its outline runs
// clockwise seen from +z), their sides stitched: a tube (GarmentCode's JSON, cm).
const char* kTube = R"({"pattern": {"panels": {
  "front": {"translation": [-20, 60, 20], "rotation": [0, 0, 0],
            "vertices": [[0, 0], [40, 0], [40, 30], [0, 30]],
            "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3]}, {"endpoints": [3, 0]}]},
  "back": {"translation": [-20, 60, -20], "rotation": [0, 0, 0],
           "vertices": [[0, 0], [0, 30], [40, 30], [40, 0]],
           "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3]}, {"endpoints": [3, 0]}]}},
  "stitches": [[{"panel": "front", "edge": 1}, {"panel": "back", "edge": 2}],
               [{"panel": "front", "edge": 3}, {"panel": "back", "edge": 0}]]},
 "properties": {"units_in_meter": 100}})";

}  // namespace

TEST(SewingPattern, OffersThePanelsTheirPanelPointsAndTheSeams) {
  SceneRoot root = readPattern(kPencil);
  ASSERT_TRUE(root);
  auto* pattern = find<SewingPattern>(root.get());
  ASSERT_NE(pattern, nullptr);
  const int n = pattern->point.getNum();
  ASSERT_GT(n, 100);
  EXPECT_EQ(pattern->panelPoint.getNum(), n);
  ASSERT_GT(pattern->seams.getNum(), 0);
  EXPECT_EQ(pattern->seams.getNum() % 2, 0);
  for (int i = 0; i < pattern->seams.getNum(); ++i) {
    EXPECT_GE(pattern->seams[i], 0);
    EXPECT_LT(pattern->seams[i], n);
  }
  // Placed rigidly: each triangle's edges are as long as in its flat panel (single precision).
  ASSERT_EQ(pattern->coordIndex.getNum() % 4, 0);
  for (int f = 0; f < pattern->coordIndex.getNum(); f += 4)
    for (int k = 0; k < 3; ++k) {
      const int a = pattern->coordIndex[f + k], b = pattern->coordIndex[f + (k + 1) % 3];
      const float placed = (pattern->point[a] - pattern->point[b]).length();
      const float flat = (pattern->panelPoint[a] - pattern->panelPoint[b]).length();
      ASSERT_NEAR(placed, flat, 1e-5f) << "triangle " << f / 4;
    }
  // Outputs, not settings: a written pattern node is as small as the one read (its
  // declaration of the fields, its fileName), not its 1,800 points' values (tens of KB).
  EXPECT_LT(writeString(root.get()).size(), 1000u);
}

TEST(SewingPattern, ABadPatternIsAReadErrorNamingTheNodeAndThePanel) {
  const TempDir dir;
  const std::string path = (dir.path() / "bad.json").string();
  std::string text = kTube;
  text.replace(text.find("{\"endpoints\": [1, 2]}"), 21,
               R"({"endpoints": [1, 2], "curvature": {"type": "spline", "params": []}})");
  std::ofstream(path) << text;
  initCoin();
  CapturedErrors errors;
  EXPECT_FALSE(readPattern(path));
  EXPECT_NE(errors.all().find("SewingPattern 'Skirt': "), std::string::npos) << errors.all();
  EXPECT_NE(errors.all().find("spline"), std::string::npos) << errors.all();
}

TEST(SewingPattern, ASpacingOutOfRangeIsAReadError) {
  initCoin();
  CapturedErrors errors;
  EXPECT_FALSE(readPattern(kPencil, "spacing 0.5"));
  EXPECT_NE(errors.all().find("SewingPattern 'Skirt': spacing = 0.5 must be within [0.005, 0.1] m"), std::string::npos)
      << errors.all();
}

TEST(SewingPattern, AClothEngineSewsItsSeamsShut) {
  const TempDir dir;
  const std::string path = (dir.path() / "tube.json").string();
  std::ofstream(path) << kTube;
  initCoin();
  SceneRoot root = readString(
      "#Inventor V2.1 ascii\nSeparator {\n"
      "  Switch { whichChild -1  DEF Tube SewingPattern { fileName \"" +
      path +
      "\"  spacing 0.04 } }\n"
      "  Coordinate3 { point = DEF Drape ClothEngine {\n"
      "    restPoints = USE Tube.point  coordIndex = USE Tube.coordIndex\n"
      "    panelPoints = USE Tube.panelPoint  seams = USE Tube.seams\n"
      "    maxTime 0.5 } . positions }\n"
      "}\n");
  ASSERT_TRUE(root);
  auto* tube = find<SewingPattern>(root.get());
  ASSERT_NE(tube, nullptr);
  auto* engine = static_cast<ClothEngine*>(SoBase::getNamedBase("Drape", ClothEngine::getClassTypeId()));
  ASSERT_NE(engine, nullptr);
  SoMFVec3f drape;
  drape.connectFrom(&engine->positions);
  ASSERT_EQ(drape.getNum(), tube->point.getNum());
  EXPECT_EQ(engine->lastError(), "");
  // The control: the seams start 40 cm open; sewn, each pair ends at one place.
  const int a = tube->seams[0], b = tube->seams[1];
  EXPECT_NEAR((tube->point[a] - tube->point[b]).length(), 0.4f, 1e-4f);
  for (int i = 0; i < tube->seams.getNum(); i += 2)
    EXPECT_LT((drape[tube->seams[i]] - drape[tube->seams[i + 1]]).length(), 1e-6f) << "pair " << i / 2;
}

}  // namespace test_SewingPattern
