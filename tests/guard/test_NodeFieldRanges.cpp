// Whole-number fields Coin indexes its own arrays with: a TextureUnit's unit below 0
// corrupted the heap or crashed figment-view, one of 2147483647 ran it out of memory.

#include <gtest/gtest.h>

#include <string>

#include "guard/NodeFieldRanges.h"
#include "support/SceneTestSupport.h"

namespace test_NodeFieldRanges {

using namespace figment::guard;

namespace {

std::string problemIn(const std::string& body) {
  figment::test::initCoin();
  const figment::test::SceneRoot root = figment::test::readString("#Inventor V2.1 ascii\n" + body + "\n");
  return root ? firstFieldOutOfRange(root.get()) : "unreadable: " + body;
}

}  // namespace

TEST(NodeFieldRanges, TakesTheTextureUnitsOpenGLNames) {
  EXPECT_EQ(problemIn("TextureUnit { unit 0 } TextureUnit { unit 31 } Cube { }"), "");
  EXPECT_EQ(problemIn("Separator { DEF Second TextureUnit { unit -5 } }"),
            "TextureUnit 'Second': unit = -5 is not a texture unit: 0 to 31");
  EXPECT_EQ(problemIn("VRMLShape { geometry VRMLBox { } } TextureUnit { unit 32 }"),
            "TextureUnit: unit = 32 is not a texture unit: 0 to 31");
}

}  // namespace test_NodeFieldRanges
