// A fit map's scene: the body by name and the garment coloured per vertex by its band, in
// Coin's text; a band list that does not match the garment is refused and nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/FitMapScene.h"
#include "support/TempDir.h"

using namespace figment;

TEST(FitMapScene, TheGarmentIsColouredByItsBands) {
  const test::TempDir dir;
  const std::string path = (dir.path() / "M.iv").string();
  const TriangleMesh garment{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {{0, 1, 2}}};
  writeFitMapScene(path, garment, {0, 3, 7}, "body.obj");
  std::stringstream text;
  text << std::ifstream(path).rdbuf();
  EXPECT_EQ(text.str().rfind("#Inventor V2.1 ascii\n", 0), 0u);
  for (const char* part :
       {"MeshFile { fileName \"body.obj\" }", "MaterialBinding { value PER_VERTEX_INDEXED }", "diffuseColor [ 0 0 1,",
        ", 1 0 0 ]", "0, 1, 2, -1,", "materialIndex [\n        0, 3, 7, -1,"})
    EXPECT_NE(text.str().find(part), std::string::npos) << part << " in\n" << text.str();
}

TEST(FitMapScene, BandsThatDoNotMatchAreRefused) {
  const test::TempDir dir;
  const std::string path = (dir.path() / "M.iv").string();
  const TriangleMesh garment{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {{0, 1, 2}}};
  EXPECT_THROW(writeFitMapScene(path, garment, {0, 3}, "body.obj"), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(path));
}
