// Coin evaluates an engine once more as it destroys it (SoEngine::destroy). A scene that fails
// to read after its ClothEngine destroys the engine unread, and that used to drape the whole
// maxTime first: a read error took as long as the drape (found by tests/fuzz/fuzz_scene, where
// a mangled scene took 17 s; here, free fall for 1e7 steps, minutes). The engine now skips a
// drape nothing can read.
#include "nodes/cloth/ClothEngine.h"
#include "support/SceneTestSupport.h"

#include <gtest/gtest.h>

#include <chrono>
#include <string>

namespace {

TEST(ClothEngineDestroyedUnread, AReadErrorAfterAnEngineComesAtOnceWithoutDraping) {
  figment::test::initCoin();
  const figment::test::Grid g = figment::test::grid(5, 0.4, 1.0);
  // No body and no rest: the cloth falls until maxTime, 1e7 steps.
  const std::string text = "#Inventor V2.1 ascii\nSeparator {\n"
                           "  DEF Rest Coordinate3 { point [ " + g.points + " ] }\n"
                           "  Coordinate3 { point = DEF Drape ClothEngine {\n"
                           "    restPoints = USE Rest.point\n"
                           "    coordIndex [ " + g.coordIndex + " ]\n"
                           "    timeStep 1e-4  maxTime 1000\n"
                           "  } . positions }\n"
                           "  Cube { width \"not a number\" }\n"
                           "}\n";
  figment::test::CapturedErrors errors;
  const auto start = std::chrono::steady_clock::now();
  const figment::test::SceneRoot root = figment::test::readString(text);
  const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
  EXPECT_EQ(root, nullptr);
  EXPECT_NE(errors.all().find("width"), std::string::npos) << errors.all();
  EXPECT_LT(wall.count(), 5.0);
}

}  // namespace
