// The guard's calls for C and for Python through ctypes: a scene that passes is added to the
// caller's group; a refused one is one line in the caller's buffer, cut to its size, and
// leaves the group as it was.

#include <Inventor/nodes/SoCube.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <string>

#include "guard/GuardC.h"
#include "support/SceneTestSupport.h"

namespace {

class GuardCTest : public ::testing::Test {
 protected:
  void SetUp() override {
    figment::test::initCoin();
    group_ = new SoSeparator;
    group_->ref();
  }
  void TearDown() override { group_->unref(); }
  figment::test::TempDir dir_;
  SoSeparator* group_ = nullptr;
};

}  // namespace

TEST_F(GuardCTest, AddsAPassingSceneToTheGroup) {
  const std::string scene = dir_.file("good.iv", "#Inventor V2.1 ascii\nSeparator { Cube { } }\n");
  char error[256] = "untouched";
  EXPECT_EQ(figment_guard_read_scene(scene.c_str(), group_, error, sizeof error), 0);
  EXPECT_STREQ(error, "untouched");
  ASSERT_EQ(group_->getNumChildren(), 1);
  EXPECT_EQ(group_->getChild(0)->getRefCount(), 1) << "held by the group alone";
  EXPECT_EQ(figment_guard_check_shapes(group_, error, sizeof error), 0);
  EXPECT_EQ(figment_guard_read_scene(scene.c_str(), nullptr, error, sizeof error), 0) << "a null group only checks";
}

TEST_F(GuardCTest, RefusesInOneLineCutToTheBuffer) {
  const std::string scene =
      dir_.file("bad.iv", "#Inventor V2.1 ascii\nSeparator {\n  Cube { fields [ SFFloat wobble ] }\n}\n");
  char error[256] = "";
  EXPECT_EQ(figment_guard_read_scene(scene.c_str(), group_, error, sizeof error), 1);
  EXPECT_STREQ(error, "line 3: Cube: fields [ SFFloat wobble ] declares a field Cube does not have");
  EXPECT_EQ(group_->getNumChildren(), 0);
  char shortError[8] = "";
  EXPECT_EQ(figment_guard_read_scene(scene.c_str(), group_, shortError, sizeof shortError), 1);
  EXPECT_STREQ(shortError, "line 3:");
  EXPECT_EQ(figment_guard_read_scene(scene.c_str(), group_, nullptr, 0), 1) << "no buffer: the status alone";
  char notAGroup[256] = "";
  SoCube* cube = new SoCube;
  cube->ref();
  EXPECT_EQ(figment_guard_read_scene(scene.c_str(), cube, notAGroup, sizeof notAGroup), 1);
  EXPECT_STREQ(notAGroup, "the node to add the scene to is not a group");
  cube->unref();
}

TEST_F(GuardCTest, ChecksShapesInOneLine) {
  const std::string scene =
      dir_.file("faces.iv",
                "#Inventor V2.1 ascii\nSeparator {\n  Coordinate3 { point [ 0 0 0, 1 0 0, 0 1 0 ] }\n"
                "  IndexedFaceSet { coordIndex [ 0 1 5 -1 ] }\n}\n");
  char error[256] = "";
  ASSERT_EQ(figment_guard_read_scene(scene.c_str(), group_, error, sizeof error), 0) << error;
  EXPECT_EQ(figment_guard_check_shapes(group_, error, sizeof error), 1);
  EXPECT_STREQ(error, "IndexedFaceSet: coordIndex[2] = 5 is not a vertex: the coordinates have 3 points");
}
