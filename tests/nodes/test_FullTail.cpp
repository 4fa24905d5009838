// figment::fullTail (nodes/SceneSearch.h): the last nodes of a search's path, hidden children
// included, without Coin's static_cast<SoFullPath*> idiom. That cast was undefined behaviour
// (a search's paths are SoPaths), and the sanitizer build stopped on it in findClothEngines,
// the stencil rule and the viewer's staging.
#include "nodes/SceneSearch.h"
#include "support/SceneTestSupport.h"

#include <Inventor/SoPath.h>
#include <Inventor/nodes/SoCube.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoSwitch.h>

#include <gtest/gtest.h>

namespace {

TEST(FullTail, GivesTheLastNodesOfASearchPathAndNullPastItsStart) {
  figment::test::initCoin();
  figment::test::SceneRoot root(new SoSeparator);
  root->ref();
  auto* off = new SoSwitch;  // whichChild -1: found only by searching everything
  auto* group = new SoGroup;
  auto* cube = new SoCube;
  root->addChild(off);
  off->addChild(group);
  group->addChild(cube);

  const SoPathList paths = figment::findAll(root.get(), SoCube::getClassTypeId());
  ASSERT_EQ(paths.getLength(), 1);
  EXPECT_EQ(figment::fullTail(paths[0]), cube);
  EXPECT_EQ(figment::fullTail(paths[0], 1), group);
  EXPECT_EQ(figment::fullTail(paths[0], 3), root.get());
  EXPECT_EQ(figment::fullTail(paths[0], 4), nullptr);
  EXPECT_EQ(figment::fullTail(paths[0], -1), nullptr);
}

}  // namespace
