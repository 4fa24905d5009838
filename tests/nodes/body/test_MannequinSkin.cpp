// MannequinSkin: a `mannequin` that is not a Mannequin is said, never drawn in silence
// (found by fuzzing figment-view, issue 15).

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/nodes/SoCube.h>
#include <gtest/gtest.h>

#include "nodes/body/MannequinSkin.h"
#include "support/SceneTestSupport.h"

using namespace figment::test;

namespace {

class MannequinSkinTest : public ::testing::Test {
 protected:
  void SetUp() override { initCoin(); }
};

}  // namespace

TEST_F(MannequinSkinTest, AMannequinOfAnotherTypeIsAReadErrorNamingTheType) {
  CapturedErrors errors;
  SceneRoot root = readString(
      "#Inventor V2.1 ascii\nSeparator {\n"
      "  DEF Arms MannequinSkin { mannequin Cube { } }\n"
      "}\n");
  EXPECT_FALSE(root) << "the file does not read";
  EXPECT_NE(errors.all().find("MannequinSkin 'Arms': mannequin is a Cube, not a Mannequin"), std::string::npos)
      << errors.all();
}

TEST_F(MannequinSkinTest, ANullMannequinReadsAndDrawsNothing) {
  CapturedErrors errors;
  SceneRoot root = readString("#Inventor V2.1 ascii\nSeparator { MannequinSkin { } }\n");
  ASSERT_TRUE(root) << errors.all();
  EXPECT_EQ(errors.all(), "");
}

TEST_F(MannequinSkinTest, AMannequinOfAnotherTypeSetLaterIsItsLastError) {
  SceneRoot root = readString("#Inventor V2.1 ascii\nSeparator { DEF Skin MannequinSkin { } }\n");
  ASSERT_TRUE(root);
  auto* skin = find<MannequinSkin>(root.get(), "Skin");
  ASSERT_TRUE(skin);
  CapturedErrors errors;
  skin->mannequin = new SoCube;
  SoGetBoundingBoxAction bbox(SbViewportRegion(100, 100));
  bbox.apply(root.get());
  EXPECT_EQ(skin->lastError(), "MannequinSkin 'Skin': mannequin is a Cube, not a Mannequin");
  EXPECT_TRUE(bbox.getBoundingBox().isEmpty()) << "nothing drawn";
}
