// Files a scene names are found beside the .iv file that names them first, then along the
// other folders in order; the .iv file's folder comes first in the search list.
#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/lists/SbStringList.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "nodes/SceneFiles.h"
#include "support/TempDir.h"

using namespace figment;
namespace fs = std::filesystem;

namespace {

TEST(SceneFiles, TheSceneFilesFolderComesFirst) {
  SoDB::init();
  const test::TempDir dir;
  const std::string scene = dir.file("scenes/a.iv", "#Inventor V2.1 ascii\n\nSeparator { }\n");
  SoInput in;
  ASSERT_TRUE(in.openFile(scene.c_str()));
  const std::vector<std::string> dirs = sceneSearchDirectories(&in);
  ASSERT_FALSE(dirs.empty());
  EXPECT_TRUE(fs::equivalent(dirs.front(), dir.path() / "scenes")) << dirs.front();
  for (const std::string& d : dirs) EXPECT_TRUE(fs::path(d).is_absolute()) << d;
}

TEST(SceneFiles, WithoutAFileTheSearchListIsCoinsAlone) {
  SoDB::init();
  const std::vector<std::string> dirs = sceneSearchDirectories(nullptr);
  EXPECT_EQ(dirs.size(), size_t(SoInput::getDirectories().getLength()));
}

TEST(SceneFiles, ResolvesInTheFirstFolderThatHasTheFile) {
  const test::TempDir dir;
  dir.file("first/other.obj", "o x\n");
  const std::string second = dir.file("second/mesh.obj", "o x\n");
  dir.file("third/mesh.obj", "o x\n");
  const std::vector<std::string> dirs = {(dir.path() / "first").string(), (dir.path() / "second").string(),
                                         (dir.path() / "third").string()};
  EXPECT_TRUE(fs::equivalent(resolveSceneFile("mesh.obj", dirs), second));
  EXPECT_EQ(resolveSceneFile("figment-no-such-file-anywhere.obj", dirs), "");
}

}  // namespace
