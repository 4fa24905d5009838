// What a worker reads once from its scenes folder: the shipped folder gives the body, its
// volumes, the patterns and the garment catalogue (scenes/catalogue/), which sells every
// service style; a folder whose catalogue disagrees with the service's styles (a default
// colour that is not the catalogue's first) is refused in one line naming the file.

#include <Inventor/SoDB.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/GarmentCatalogue.h"
#include "nodes/Init.h"
#include "serve/scene/Wardrobe.h"
#include "support/TempDir.h"

namespace fs = std::filesystem;
using figment::serve::Wardrobe;

namespace {

const fs::path kScenes = FIGMENT_SOURCE_DIR "/scenes";

void initCoin() {
  SoDB::init();
  figment::init();
}

}  // namespace

TEST(Wardrobe, ReadsTheScenesFoldersCatalogue) {
  initCoin();
  Wardrobe wardrobe;
  ASSERT_EQ(wardrobe.read(kScenes.string()), "");
  ASSERT_NE(wardrobe.catalogue(), nullptr);
  EXPECT_EQ(wardrobe.catalogue()->style("dress")->colours.front(), "1f40b3");
  EXPECT_EQ(wardrobe.catalogue()->resolve("dress:M").sizeName, "M");
}

TEST(Wardrobe, RefusesACatalogueThatDisagreesWithItsStyles) {
  initCoin();
  // The shipped folder, but for a catalogue whose dress comes first in another colour.
  const figment::test::TempDir dir;
  for (const auto& entry : fs::directory_iterator(kScenes))
    if (entry.path().filename() != "catalogue") fs::create_symlink(entry.path(), dir.path() / entry.path().filename());
  fs::create_directory(dir.path() / "catalogue");
  for (const auto& entry : fs::directory_iterator(kScenes / "catalogue"))
    fs::copy_file(entry.path(), dir.path() / "catalogue" / entry.path().filename());
  std::ofstream(dir.path() / "catalogue" / "dress.txt") << "style dress\nfemale S M L\ncolours 222222 1f40b3\n";
  Wardrobe wardrobe;
  const std::string error = wardrobe.read(dir.path().string());
  EXPECT_NE(error.find("catalogue/index.txt: dress's first colour is not 1f40b3"), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos);
}
