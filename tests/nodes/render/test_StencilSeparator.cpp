// A StencilSeparator outside rendering is a Separator: its children's state stays inside it;
// its fields default to the rule deciding (stencilRule TRUE, writeStencil FALSE) and read
// back as written.
#include <Inventor/SbBox.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <gtest/gtest.h>

#include <string>

#include "nodes/render/StencilSeparator.h"
#include "support/SceneTestSupport.h"

using namespace figment::test;

namespace {

TEST(StencilSeparator, DefaultsToTheRuleDeciding) {
  initCoin();
  SceneRoot root = readString("#Inventor V2.1 ascii\nSeparator { StencilSeparator { } }\n");
  ASSERT_TRUE(root);
  const StencilSeparator* part = find<StencilSeparator>(root.get());
  EXPECT_TRUE(part->stencilRule.getValue());
  EXPECT_FALSE(part->writeStencil.getValue());
}

TEST(StencilSeparator, ItsFieldsReadBackAsWritten) {
  initCoin();
  SceneRoot root = readString(
      "#Inventor V2.1 ascii\nSeparator { DEF Arm StencilSeparator { writeStencil TRUE stencilRule FALSE } }\n");
  ASSERT_TRUE(root);
  SceneRoot again = readString(writeString(root.get()));
  ASSERT_TRUE(again);
  const StencilSeparator* part = find<StencilSeparator>(again.get(), "Arm");
  ASSERT_NE(part, nullptr);
  EXPECT_TRUE(part->writeStencil.getValue());
  EXPECT_FALSE(part->stencilRule.getValue());
}

TEST(StencilSeparator, KeepsItsChildrensStateInside) {
  initCoin();
  // The Translation inside the separator must not move the cube after it.
  SceneRoot root = readString(
      "#Inventor V2.1 ascii\nSeparator { StencilSeparator { Translation { translation 10 0 0 } } Cube { } }\n");
  ASSERT_TRUE(root);
  SoGetBoundingBoxAction box{SbViewportRegion(10, 10)};
  box.apply(root.get());
  const SbVec3f centre = box.getBoundingBox().getCenter();
  EXPECT_FLOAT_EQ(centre[0], 0.0f);
}

}  // namespace
