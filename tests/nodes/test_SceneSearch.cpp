// nodes/SceneSearch: the scene search in one place.
//
// figment::findClothEngines: every engine of a scene once, in scene order, wherever it lies
// (under a Switch that is off, or reached only through a field connection). It walks each node
// once: a search action made a path for every way to reach a node, and 65,520 paths through
// shared groups took 4.9 s (found by tests/fuzz/fuzz_scene).
//
// figment::fullTail (nodes/SceneSearch.h): the last nodes of a search's path, hidden children
// included, without Coin's static_cast<SoFullPath*> idiom. That cast was undefined behaviour
// (a search's paths are SoPaths), and the sanitizer build stopped on it in findClothEngines,
// the stencil rule and the viewer's staging.
#include <Inventor/SoPath.h>
#include <Inventor/nodes/SoCube.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoSwitch.h>
#include <gtest/gtest.h>

#include <string>

#include "nodes/SceneSearch.h"
#include "nodes/cloth/ClothEngine.h"
#include "support/SceneTestSupport.h"

namespace {

TEST(FindClothEngines, FindsEachEngineOnceInSceneOrder) {
  figment::test::initCoin();
  // A shares a group used 2^16 times; B lies under a Switch that is off; C feeds B's rest
  // points only.
  std::string text =
      "#Inventor V2.1 ascii\nSeparator {\n  DEF L0 Group { Coordinate3 { point = DEF A ClothEngine { } . positions } "
      "}\n";
  for (int i = 1; i <= 16; ++i)
    text += "  DEF L" + std::to_string(i) + " Group { USE L" + std::to_string(i - 1) + " USE L" +
            std::to_string(i - 1) + " }\n";
  text +=
      "  Switch { whichChild -1  Coordinate3 { point = DEF B ClothEngine { restPoints = DEF C ClothEngine { } "
      ". positions } . positions } }\n}\n";
  const figment::test::SceneRoot root = figment::test::readString(text);
  ASSERT_TRUE(root);
  const std::vector<ClothEngine*> engines = figment::findClothEngines(root.get());
  ASSERT_EQ(engines.size(), 3u);
  EXPECT_STREQ(engines[0]->getName().getString(), "A");
  EXPECT_STREQ(engines[1]->getName().getString(), "B");
  EXPECT_STREQ(engines[2]->getName().getString(), "C");
}

}  // namespace

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
