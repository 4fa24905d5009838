// Every scene in scenes/examples/ (the examples of docs/authoring.md, one per node) is
// read and rendered by figment-view, and draws something: one test per file, found by
// listing the folder, so a new example is covered without touching this file.
#include <Inventor/SbImage.h>
#include <Inventor/SoDB.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io/MakeHumanFiles.h"
#include "support/ProgramRun.h"
#include "support/TempDir.h"

namespace fs = std::filesystem;

namespace {

using figment::test::quote;

const fs::path kExamples = FIGMENT_SOURCE_DIR "/scenes/examples";

// The example scenes' names (file stems), sorted: the test's parameters.
std::vector<std::string> exampleNames() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(kExamples))
    if (entry.is_regular_file() && entry.path().extension() == ".iv") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Pixels of `png` that differ from figment-view's grey background (0.8).
int drawnPixels(const std::string& png) {
  SoDB::init();  // SbImage reads through Coin's image loaders
  SbImage image;
  if (!image.readFile(png.c_str())) return -1;
  SbVec2s size;
  int bytesPerPixel = 0;
  const unsigned char* data = image.getValue(size, bytesPerPixel);
  if (!data || bytesPerPixel < 3) return -1;
  constexpr int kGrey = 204;
  int drawn = 0;
  for (int i = 0; i < size[0] * size[1]; ++i) {
    const unsigned char* p = data + i * bytesPerPixel;
    drawn += std::abs(p[0] - kGrey) > 3 || std::abs(p[1] - kGrey) > 3 || std::abs(p[2] - kGrey) > 3;
  }
  return drawn;
}

class ExampleScene : public ::testing::TestWithParam<std::string> {};

// Drapes for real (--no-cache): each example drapes in about 1 s or less on one core
// (speed is figment-bench's to measure, not a test's).
TEST_P(ExampleScene, RendersNonEmptyPixels) {
  if ((GetParam() == "HumanBody" || GetParam() == "CatalogueGarment") && figment::findMakeHumanData().empty())
    GTEST_SKIP() << "MakeHuman's data not found (scripts/setup.sh fetches it)";
  const figment::test::TempDir dir;
  const std::string scene = (kExamples / (GetParam() + ".iv")).string();
  const std::string png = (dir.path() / "example.png").string();
  const std::string err = (dir.path() / "stderr.txt").string();
  constexpr int kWidth = 160, kHeight = 120;
  const int raw = std::system((quote(FIGMENT_VIEW_EXECUTABLE) + " " + quote(scene) + " -o " + quote(png) + " --size " +
                               std::to_string(kWidth) + "x" + std::to_string(kHeight) + " --no-cache 2> " + quote(err) +
                               " > /dev/null")
                                  .c_str());
  std::stringstream message;
  message << std::ifstream(err).rdbuf();
  ASSERT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << scene << ": " << message.str();
  // At least 1 % of the picture is the scene: the framing puts the whole scene in view.
  EXPECT_GT(drawnPixels(png), kWidth * kHeight / 100) << scene;
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleScene, ::testing::ValuesIn(exampleNames()),
                         [](const ::testing::TestParamInfo<std::string>& scene) { return scene.param; });

}  // namespace
