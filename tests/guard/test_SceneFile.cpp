// The guard's read of a scene file, as any Coin program makes it: a refusal is one line and
// releases what was read; Coin's warnings wait for the read's end and reach the program's own
// handler only when it succeeds; the program's handlers are its own again afterwards.

#include <Inventor/errors/SoDebugError.h>
#include <Inventor/errors/SoReadError.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "guard/SceneFile.h"
#include "support/SceneTestSupport.h"

namespace test_SceneFile {

using figment::guard::readScene;

namespace {

const std::string kHeader = "#Inventor V2.1 ascii\n";

// The volumes file of issue 28: its first CapsuleVolume declares a field the node does not have.
const std::string kVolumes = kHeader +
                             "Group {\n  CapsuleVolume {\n    fields [ SFString part, SFFloat r1e308 ]\n"
                             "    part \"head\"\n  }\n  CapsuleVolume { fields [ SFString part ] part \"neck\" }\n}\n";

class SceneFileTest : public ::testing::Test {
 protected:
  void SetUp() override { figment::test::initCoin(); }
  std::string write(const std::string& name, const std::string& text) const { return dir_.file(name, text); }
  figment::test::TempDir dir_;
};

}  // namespace

TEST_F(SceneFileTest, ReadsAShippedScene) {
  std::string error;
  SoSeparator* root = readScene(FIGMENT_SOURCE_DIR "/scenes/examples/CapsuleVolume.iv", error);
  ASSERT_NE(root, nullptr) << error;
  EXPECT_EQ(root->getRefCount(), 1);
  root->unref();
}

TEST_F(SceneFileTest, RefusesAFieldDeclarationInAnIncludedFileInOneLine) {
  write("volumes.iv", kVolumes);
  const std::string scene = write("scene.iv", kHeader + "Separator {\n  File { name \"volumes.iv\" }\n  Cube { }\n}\n");
  std::string error;
  EXPECT_EQ(readScene(scene, error), nullptr);
  EXPECT_EQ(error.rfind("line 4: CapsuleVolume: fields [ SFFloat r1e308 ] declares a field CapsuleVolume does not "
                        "have (in ",
                        0),
            0u)
      << error;
  // Read directly, and again: the class was left as it was, and a good file still reads.
  EXPECT_EQ(readScene((dir_.path() / "volumes.iv").string(), error), nullptr);
  EXPECT_EQ(error, "line 4: CapsuleVolume: fields [ SFFloat r1e308 ] declares a field CapsuleVolume does not have");
  SoSeparator* good = readScene(
      write("good.iv", kHeader + "CapsuleVolume { fields [ SFString part, SFFloat r1 ] part \"head\" r1 0.5 }\n"),
      error);
  ASSERT_NE(good, nullptr) << error;
  good->unref();
}

TEST_F(SceneFileTest, PassesCoinsWarningsOnOnlyWhenTheReadSucceeds) {
  figment::test::CapturedErrors program;  // the program's own handlers
  // Coin warns of the File's missing name, then reads on.
  std::string error;
  SoSeparator* root = readScene(write("warned.iv", kHeader + "Separator { File { } Cube { } }\n"), error);
  ASSERT_NE(root, nullptr) << error;
  root->unref();
  ASSERT_EQ(program.messages.size(), 1u) << program.all();
  EXPECT_NE(program.messages[0].find("SoFile::readNamedFile"), std::string::npos) << program.all();
  // The same warning on the way to a failed read: the refusal's line alone says what happened.
  program.messages.clear();
  EXPECT_EQ(readScene(write("failed.iv", kHeader + "Separator {\n  File { }\n  Cube { width }\n"), error), nullptr);
  EXPECT_EQ(error, "line 4: Couldn't read value for field \"width\" of Cube");
  EXPECT_TRUE(program.messages.empty()) << program.all();
  // The program's handlers are its own again after each read.
  SoDebugError::postWarning("test", "after");
  EXPECT_EQ(program.messages.size(), 1u) << program.all();
}

}  // namespace test_SceneFile
