// Whole-number fields Coin indexes its own arrays with: a TextureUnit's unit below 0
// corrupted the heap or crashed figment-view, one of 2147483647 ran it out of memory.

#include "viewer/NodeFieldRanges.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

#include <string>

using namespace figment::viewer;

namespace {

std::string problemIn(const std::string& body) {
  SoDB::init();
  const std::string text = "#Inventor V2.1 ascii\n" + body + "\n";
  SoInput in;
  in.setBuffer(text.data(), text.size());
  SoSeparator* root = SoDB::readAll(&in);
  if (!root) return "unreadable: " + body;
  root->ref();
  std::string problem = firstFieldOutOfRange(root);
  root->unref();
  return problem;
}

}  // namespace

TEST(NodeFieldRanges, TakesTheTextureUnitsOpenGLNames) {
  EXPECT_EQ(problemIn("TextureUnit { unit 0 } TextureUnit { unit 31 } Cube { }"), "");
  EXPECT_EQ(problemIn("Separator { DEF Second TextureUnit { unit -5 } }"),
            "TextureUnit 'Second': unit = -5 is not a texture unit: 0 to 31");
  EXPECT_EQ(problemIn("VRMLShape { geometry VRMLBox { } } TextureUnit { unit 32 }"),
            "TextureUnit: unit = 32 is not a texture unit: 0 to 31");
}
