// Outside rendering a DepthSortedGroup is a Group: its children are traversed in scene order
// whatever their depth, and state flows from one to the next.
#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/nodes/SoCube.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "nodes/render/DepthSortedGroup.h"
#include "support/SceneTestSupport.h"

using namespace figment::test;

namespace {

TEST(DepthSortedGroup, OtherActionsTraverseInSceneOrder) {
  initCoin();
  // Near, far, middle along z: a render would draw Far, Middle, Near.
  SceneRoot root = readString(
      "#Inventor V2.1 ascii\nDepthSortedGroup {\n"
      "  Separator { Translation { translation 0 0 2 } DEF Near Cube { } }\n"
      "  Separator { Translation { translation 0 0 -2 } DEF Far Cube { } }\n"
      "  Separator { DEF Middle Cube { } }\n}\n");
  ASSERT_TRUE(root);
  std::vector<std::string> order;
  SoCallbackAction action;
  action.addPreCallback(
      SoCube::getClassTypeId(),
      [](void* data, SoCallbackAction*, const SoNode* node) {
        static_cast<std::vector<std::string>*>(data)->emplace_back(node->getName().getString());
        return SoCallbackAction::CONTINUE;
      },
      &order);
  action.apply(root.get());
  EXPECT_EQ(order, (std::vector<std::string>{"Near", "Far", "Middle"}));
}

TEST(DepthSortedGroup, StateFlowsBetweenChildrenAsInAGroup) {
  initCoin();
  SceneRoot root = readString(
      "#Inventor V2.1 ascii\nSeparator { DepthSortedGroup { Translation { translation 10 0 0 } Cube { } } }\n");
  ASSERT_TRUE(root);
  SoGetBoundingBoxAction box{SbViewportRegion(10, 10)};
  box.apply(root.get());
  EXPECT_FLOAT_EQ(box.getBoundingBox().getCenter()[0], 10.0f);
}

}  // namespace
