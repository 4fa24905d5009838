// Every reproducer of a Coin bug (docs/coin-bugs.md; each crashes or hangs
// figment_coin_reproducer, a plain Coin program) is refused by the guard in one line, or, where
// the guard's input keeps Coin from the bug itself, read without harm.

#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "guard/Guard.h"
#include "support/SceneTestSupport.h"

namespace {

struct Reproducer {
  std::string file;
  std::string refusal;  // what the one line must hold; "" where the guard reads it without harm
  friend void PrintTo(const Reproducer& r, std::ostream* out) { *out << r.file; }
};

class CoinBugReproducer : public ::testing::TestWithParam<Reproducer> {};

// The guard's two calls, as SceneSession makes them: "" when the scene could be drawn.
std::string guarded(const std::string& path) {
  figment::test::initCoin();
  std::string error;
  SoSeparator* root = figment::guard::readScene(path, error);
  if (!root) return error;
  error = figment::guard::checkShapes(root);
  root->unref();
  return error;
}

}  // namespace

TEST_P(CoinBugReproducer, IsRefusedInOneLineOrReadWithoutHarm) {
  const Reproducer& r = GetParam();
  const std::string line = guarded(std::string(FIGMENT_SOURCE_DIR "/tests/guard/coin-bugs/") + r.file);
  EXPECT_EQ(line.find('\n'), std::string::npos) << line;
  if (r.refusal.empty())
    EXPECT_EQ(line, "");
  else
    EXPECT_NE(line.find(r.refusal), std::string::npos) << r.refusal << " in: " << line;
}

TEST(CoinBugReproducers, EveryFileInTheFolderIsListed) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(FIGMENT_SOURCE_DIR "/tests/guard/coin-bugs"))
    files += entry.path().extension() == ".iv" || entry.path().extension() == ".wrl";
  EXPECT_EQ(files, 12) << "a reproducer without a case below";
}

INSTANTIATE_TEST_SUITE_P(
    CoinBugs, CoinBugReproducer,
    ::testing::Values(Reproducer{"field-declaration.iv",
                                 "line 5: Cube: fields [ SFFloat wobble ] declares a field Cube does not have"},
                      Reproducer{"file-includes-itself.iv", "includes a file already being read"},
                      Reproducer{"file-names-a-device.iv", "File { name \"/dev/zero\" } is not a regular file"},
                      Reproducer{"use-inside-its-own-definition.iv", "USE Loop inside the definition of Loop"},
                      Reproducer{"prototype-inside-itself.wrl", "Loop { } inside the definition of PROTO Loop"},
                      Reproducer{"time-counter-step-zero.iv", "TimeCounter { step 0 } divides by zero"},
                      Reproducer{"image-larger-than-the-file.iv", "image 30000 x 30000 declares 900000000 pixels"},
                      Reproducer{"three-d-studio-bytes.iv", "a 3D Studio file"},
                      Reproducer{"vrml-coord-holds-a-material.iv", "VRMLIndexedLineSet: coord holds a VRMLMaterial"},
                      Reproducer{"texture-unit-below-zero.iv", "TextureUnit: unit = -5 is not a texture unit"},
                      Reproducer{"face-index-of-two-to-the-31.iv", "coordIndex[2] = 2147483647 is not a vertex"},
                      // The guard's input holds the engine the failed connection would have freed.
                      Reproducer{"engine-freed-by-a-failed-connection.iv", ""}),
    [](const ::testing::TestParamInfo<Reproducer>& reproducer) {
      std::string name = reproducer.param.file.substr(0, reproducer.param.file.find('.'));
      for (char& c : name)
        if (c == '-') c = '_';
      return name;
    });
