// The look at a read scene graph before any action traverses it: shared nodes and copies
// are counted as a traversal visits them, and a graph too large or too deep to traverse is
// refused in one line naming where.

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/VRMLnodes/SoVRMLFontStyle.h>
#include <Inventor/VRMLnodes/SoVRMLText.h>
#include <Inventor/misc/SoChildList.h>
#include <Inventor/nodes/SoCube.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <string>

#include "guard/SceneExpansion.h"

using namespace figment::guard;

namespace {

// The graph read from `text` (an Inventor scene, header included), referenced once.
SoSeparator* read(const std::string& text) {
  SoDB::init();
  SoInput in;
  in.setBuffer(text.data(), text.size());
  SoSeparator* root = SoDB::readAll(&in);
  EXPECT_NE(root, nullptr) << text;
  if (root) root->ref();
  return root;
}

// `levels` groups, each using the one before `uses` times, around a Cube.
std::string sharedChain(int levels, int uses) {
  std::string text = "#Inventor V2.1 ascii\nDEF L0 Cube { }\n";
  for (int i = 1; i <= levels; ++i) {
    text += "DEF L" + std::to_string(i) + " Group {";
    for (int u = 0; u < uses; ++u) text += " USE L" + std::to_string(i - 1);
    text += " }\n";
  }
  return text;
}

struct Expanded {
  SceneExpansion expansion;
  std::string problem;
};

Expanded expand(const std::string& text) {
  SoSeparator* root = read(text);
  if (!root) return {};
  Expanded out{expandScene(root), sceneExpansionProblem(root)};
  root->unref();
  return out;
}

}  // namespace

TEST(SceneExpansion, CountsEachUseAndEachCopyAsATraversalVisitsThem) {
  // Root, L0, L1 (L0 twice), L2 (L1 twice): 1 + 1 + (1 + 2) + (1 + 2 * 3) = 12.
  EXPECT_EQ(expand(sharedChain(2, 2)).expansion.visits, 12u);
  EXPECT_EQ(expand(sharedChain(2, 2)).expansion.depth, 4);
  // An Array of 2 x 3 x 4 Cubes: the root, the Array, 24 Cubes.
  EXPECT_EQ(expand("#Inventor V2.1 ascii\nArray { numElements1 2 numElements2 3 numElements3 4 Cube { } }\n")
                .expansion.visits,
            26u);
  EXPECT_EQ(expand("#Inventor V2.1 ascii\nMultipleCopy { matrix [ 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1,"
                   " 1 0 0 0 0 1 0 0 0 0 1 0 1 0 0 1 ] Cube { } Sphere { } }\n")
                .expansion.visits,
            6u);
  EXPECT_EQ(expand(sharedChain(2, 2)).problem, "");
}

// 40 groups each using the one before twice draw 2^40 Cubes: figment-view never finished.
// Shipped scenes make at most 107 visits.
TEST(SceneExpansion, RefusesAGraphThatDrawsMoreThanTheBoundNamingWhere) {
  const Expanded doubled = expand(sharedChain(40, 2));
  EXPECT_EQ(doubled.expansion.visits, kMaxNodeVisits + 1);
  // Every L is also a child of the root: the sum passes 20,000 at L13 (L12 and those before
  // make 16,369).
  EXPECT_EQ(doubled.problem,
            "the scene would draw more than 20000 nodes, counting a USEd node once for each use and an "
            "Array's or MultipleCopy's children once for each copy (passed at Group 'L13')");
  const Expanded array = expand(
      "#Inventor V2.1 ascii\nDEF Grid Array { numElements1 30000 numElements2 30000 numElements3 30000 "
      "Cube { } }\n");
  EXPECT_NE(array.problem.find("more than 20000 nodes"), std::string::npos) << array.problem;
  EXPECT_NE(array.problem.find("(passed at Array 'Grid')"), std::string::npos) << array.problem;
  // Coin loops over the copies of an Array without children too (fuzz_scene: 45 million
  // copies of nothing took 19 s); each copy counts as a visit.
  const Expanded empty = expand(
      "#Inventor V2.1 ascii\nSeparator {\n  DEF Grid Array { numElements2 30000 "
      "numElements2 15000 numElements3 3000 }\n}\n");
  EXPECT_NE(empty.problem.find("(passed at Array 'Grid')"), std::string::npos) << empty.problem;
  EXPECT_EQ(expand("#Inventor V2.1 ascii\nArray { numElements1 2 numElements2 3 }\n").expansion.visits, 8u);
  // 13 levels draw 16,370 nodes, 14 levels 32,753.
  EXPECT_EQ(expand(sharedChain(12, 2)).expansion.visits, 16'370u);
  EXPECT_EQ(expand(sharedChain(12, 2)).problem, "");
  EXPECT_NE(expand(sharedChain(13, 2)).problem.find("(passed at Group 'L13')"), std::string::npos);
}

// `levels` Groups, each holding the one before, around a Cube; the root holds the last only
// (a graph a scene makes with Groups held in fields, each using the one before). Referenced once.
SoSeparator* chainGraph(int levels) {
  SoDB::init();
  auto* root = new SoSeparator;
  root->ref();
  SoNode* inner = new SoCube;
  for (int i = 0; i < levels; ++i) {
    auto* group = new SoGroup;
    group->addChild(inner);
    inner = group;
  }
  root->addChild(inner);
  return root;
}

TEST(SceneExpansion, RefusesAGraphDeeperThanTheBound) {
  SoSeparator* deep = chainGraph(kMaxGraphDepth + 10);
  EXPECT_EQ(expandScene(deep).depth, kMaxGraphDepth + 1);
  EXPECT_EQ(sceneExpansionProblem(deep),
            "the scene graph is more than 512 nodes deep, counting through each USE (passed at Group)");
  deep->unref();
  // The root, 510 groups and the Cube: 512 deep.
  SoSeparator* atBound = chainGraph(kMaxGraphDepth - 2);
  EXPECT_EQ(sceneExpansionProblem(atBound), "");
  atBound->unref();
  SoSeparator* past = chainGraph(kMaxGraphDepth - 1);
  EXPECT_NE(sceneExpansionProblem(past), "");
  past->unref();
}

// Coin destroys a group's children from its destructor, recursively: letting go of 100,000
// groups each holding the one before overflowed the stack (SIGSEGV) after the scene was refused.
TEST(SceneExpansion, LetsGoOfAGraphOneNodeAtATime) {
  SoSeparator* root = chainGraph(100'000);
  SoNode* cube = root;
  while (cube->getChildren()) cube = (*cube->getChildren())[0];
  cube->ref();
  unrefWithoutRecursion(root);
  EXPECT_EQ(cube->getRefCount(), 1);  // held by nothing else now
  cube->unref();
}

// Nodes held in fields are linked as children are: Coin destroys them recursively too, and
// letting go of 19,500 VRMLTexts each holding the one before as its fontStyle overflowed the
// stack (SIGSEGV) after the scene was refused.
TEST(SceneExpansion, CountsAndLetsGoOfNodesHeldInFields) {
  SoDB::init();
  auto* root = new SoSeparator;
  root->ref();
  SoNode* held = new SoVRMLFontStyle;
  held->ref();  // kept, to see it let go of
  SoNode* fontStyle = held;
  for (int i = 0; i < 100'000; ++i) {
    auto* text = new SoVRMLText;
    text->fontStyle = held;
    held = text;
  }
  root->addChild(held);
  EXPECT_EQ(expandScene(root).depth, kMaxGraphDepth + 1);
  EXPECT_NE(sceneExpansionProblem(root).find("more than 512 nodes deep"), std::string::npos);
  unrefWithoutRecursion(root);
  EXPECT_EQ(fontStyle->getRefCount(), 1);
  fontStyle->unref();
  // A VRMLText holding its fontStyle: two levels below the root, one visit each.
  EXPECT_EQ(expand("#Inventor V2.1 ascii\nVRMLText { fontStyle VRMLFontStyle { } }\n").expansion.visits, 3u);
}
