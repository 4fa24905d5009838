// Coin evaluates an engine once more as it destroys it (SoEngine::destroy). A scene that fails
// to read after its ClothEngine destroys the engine unread, and that used to drape the whole
// maxTime first: a read error took as long as the drape (found by tests/fuzz/fuzz_scene, where
// a mangled scene took 17 s). The engine now skips a drape nothing can read.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "nodes/SceneSearch.h"
#include "nodes/cloth/ClothEngine.h"
#include "support/SceneTestSupport.h"

namespace {

// A ClothEngine on a 5 x 5 grid whose youngsModulus makes any drape fail at once with a
// message naming the engine and the field, so whether it draped is seen without a clock;
// with `thenABadCube`, a Cube after it fails to read.
std::string engineScene(bool thenABadCube) {
  const figment::test::Grid g = figment::test::grid(5, 0.4, 1.0);
  return "#Inventor V2.1 ascii\nSeparator {\n"
         "  DEF Rest Coordinate3 { point [ " +
         g.points +
         " ] }\n"
         "  Coordinate3 { point = DEF Drape ClothEngine {\n"
         "    restPoints = USE Rest.point\n"
         "    coordIndex [ " +
         g.coordIndex +
         " ]\n"
         "    youngsModulus -1\n"
         "  } . positions }\n" +
         std::string(thenABadCube ? "  Cube { width \"not a number\" }\n" : "") + "}\n";
}

TEST(ClothEngineDestroyedUnread, AReadErrorAfterAnEngineComesWithoutDraping) {
  figment::test::initCoin();
  figment::test::CapturedErrors errors;
  const figment::test::SceneRoot root = figment::test::readString(engineScene(true));
  EXPECT_EQ(root, nullptr);
  // Only the Cube's error may come out.
  EXPECT_NE(errors.all().find("width"), std::string::npos) << errors.all();
  EXPECT_EQ(errors.all().find("youngsModulus"), std::string::npos) << "the engine draped: " << errors.all();
}

TEST(ClothEngineDestroyedUnread, TheSameEngineReadDrapesAndReportsTheField) {
  // The control: read whole and evaluated, the engine does report its youngsModulus.
  figment::test::initCoin();
  figment::test::CapturedErrors errors;
  const figment::test::SceneRoot root = figment::test::readString(engineScene(false));
  ASSERT_NE(root, nullptr) << errors.all();
  const std::vector<ClothEngine*> engines = figment::findClothEngines(root.get());
  ASSERT_EQ(engines.size(), 1u);
  ClothEngine* engine = engines.front();
  engine->positions[0]->evaluate();
  EXPECT_NE(engine->lastError().find("youngsModulus"), std::string::npos) << engine->lastError();
}

}  // namespace
