// DepthSortedGroup and StencilSeparator outside rendering: a Group and a Separator in
// every other action (bounding box, picking, primitive count, search, write and read).
#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPickedPoint.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoGetPrimitiveCountAction.h>
#include <Inventor/actions/SoRayPickAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <gtest/gtest.h>

#include "nodes/render/DepthSortedGroup.h"
#include "nodes/render/StencilSeparator.h"
#include "support/ActionChecks.h"
#include "support/SceneTestSupport.h"

using namespace figment::test;

namespace {

// Two pieces, a red square at z = 0 and a green one at z = -1, in `group`.
std::string pieces(const std::string& group, const std::string& fields = "") {
  return "#Inventor V2.1 ascii\nSeparator {\n  DEF Pieces " + group + " {\n" + fields +
         "    DEF Near Separator { BaseColor { rgb 1 0 0 }\n"
         "      Coordinate3 { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0 ] } IndexedFaceSet { coordIndex [ 0 1 2 3 -1 ] } }\n"
         "    DEF Far Separator { BaseColor { rgb 0 1 0 }\n"
         "      Coordinate3 { point [ 0 0 -1, 2 0 -1, 2 2 -1, 0 2 -1 ] } IndexedFaceSet { coordIndex [ 0 1 2 3 -1 ] } "
         "}\n"
         "  }\n}\n";
}

class HybridNodes : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override { initCoin(); }
};

}  // namespace

TEST_P(HybridNodes, ActsLikeItsBaseInEveryOtherAction) {
  const std::string type = GetParam();
  const std::string base = type == "DepthSortedGroup" ? "Group" : "Separator";
  SceneRoot plain = readString(pieces(base));
  SceneRoot ours = readString(pieces(type));
  ASSERT_TRUE(plain && ours);
  SoNode* node = find<SoNode>(ours.get(), "Pieces");
  ASSERT_NE(node, nullptr);
  EXPECT_STREQ(node->getTypeId().getName().getString(), type.c_str());

  EXPECT_EQ(boundingBoxOf(ours.get()).getMin(), boundingBoxOf(plain.get()).getMin());
  EXPECT_EQ(boundingBoxOf(ours.get()).getMax(), boundingBoxOf(plain.get()).getMax());
  EXPECT_EQ(triangleCountOf(ours.get()), 4);

  // Picking goes through in scene order and finds the nearest piece.
  SoRayPickAction pick(kActionViewport);
  const SoPickedPoint* picked = pickAlongMinusZ(pick, ours.get(), SbVec3f(0.5f, 0.5f, 5.0f));
  ASSERT_NE(picked, nullptr);
  EXPECT_TRUE(picked->getPath()->containsNode(find<SoNode>(ours.get(), "Near")));

  SoSearchAction search;
  search.setName("Far");
  search.apply(ours.get());
  ASSERT_NE(search.getPath(), nullptr);
  EXPECT_TRUE(search.getPath()->containsNode(node));
}

INSTANTIATE_TEST_SUITE_P(Types, HybridNodes, ::testing::Values("DepthSortedGroup", "StencilSeparator"));

TEST(StencilSeparatorTest, WritesAndReadsWriteStencil) {
  initCoin();
  SceneRoot root = readString(pieces("StencilSeparator", "    writeStencil TRUE\n"));
  ASSERT_TRUE(root);
  auto* separator = find<StencilSeparator>(root.get(), "Pieces");
  ASSERT_NE(separator, nullptr);
  EXPECT_TRUE(separator->writeStencil.getValue());
  const std::string text = writeString(root.get());
  EXPECT_NE(text.find("fields [ "), std::string::npos) << "a program without FIGMENT can still read it";
  SceneRoot again = readString(text);
  ASSERT_TRUE(again);
  auto* copy = find<StencilSeparator>(again.get(), "Pieces");
  ASSERT_NE(copy, nullptr);
  EXPECT_TRUE(copy->writeStencil.getValue());
  EXPECT_EQ(copy->getNumChildren(), 2);
  auto* fresh = new StencilSeparator;
  fresh->ref();
  EXPECT_FALSE(fresh->writeStencil.getValue()) << "default FALSE";
  EXPECT_TRUE(fresh->stencilRule.getValue()) << "default TRUE: the rule decides";
  fresh->unref();
}
