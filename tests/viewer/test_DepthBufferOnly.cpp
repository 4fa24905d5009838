// The depth buffer alone (paper Fig. 5.2a): the hybrid nodes swapped for plain stand-ins with
// the same data and children, and back; the scene is as it was after the object goes.
#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <string>

#include "nodes/Init.h"
#include "nodes/render/ClothingLayer.h"
#include "nodes/render/DepthSortedGroup.h"
#include "nodes/render/StencilSeparator.h"
#include "viewer/DepthBufferOnly.h"

namespace {

int countOf(SoNode* root, SoType type, bool exactType) {
  SoSearchAction search;
  search.setType(type, !exactType);
  search.setInterest(SoSearchAction::ALL);
  search.setSearchingAll(TRUE);
  search.apply(root);
  return search.getPaths().getLength();
}

SoSeparator* readScene(const std::string& text) {
  SoInput in;
  in.setBuffer(text.data(), text.size());
  SoSeparator* root = SoDB::readAll(&in);
  if (root) root->ref();
  return root;
}

TEST(DepthBufferOnly, SwapsTheHybridNodesForPlainOnesAndBack) {
  figment::init();
  SoSeparator* root = readScene(
      "#Inventor V2.1 ascii\nSeparator {\n"
      "  Coordinate3 { point [ 0 0 0, 1 0 0, 0 1 0 ] }\n"
      "  DepthSortedGroup { Separator { ClothingLayer { coordIndex [ 0, 1, 2, -1 ] } } }\n"
      "  StencilSeparator { Cube { } }\n}\n");
  ASSERT_NE(root, nullptr);
  {
    figment::viewer::DepthBufferOnly plain(root);
    plain.use(true);
    EXPECT_EQ(countOf(root, ClothingLayer::getClassTypeId(), false), 0);
    EXPECT_EQ(countOf(root, DepthSortedGroup::getClassTypeId(), false), 0);
    EXPECT_EQ(countOf(root, StencilSeparator::getClassTypeId(), false), 0);
    SoSearchAction faces;
    faces.setType(SoIndexedFaceSet::getClassTypeId(), FALSE);  // the stand-in, not a layer
    faces.setSearchingAll(TRUE);
    faces.apply(root);
    ASSERT_NE(faces.getPath(), nullptr);
    const auto* standIn = static_cast<SoIndexedFaceSet*>(faces.getPath()->getTail());
    EXPECT_EQ(standIn->coordIndex.getNum(), 4);
    EXPECT_EQ(countOf(root, SoType::fromName("Cube"), true), 1);  // the separator's child kept
    plain.use(false);
    EXPECT_EQ(countOf(root, ClothingLayer::getClassTypeId(), false), 1);
    plain.use(true);
  }
  // Gone: the hybrid nodes are back.
  EXPECT_EQ(countOf(root, ClothingLayer::getClassTypeId(), false), 1);
  EXPECT_EQ(countOf(root, DepthSortedGroup::getClassTypeId(), false), 1);
  EXPECT_EQ(countOf(root, StencilSeparator::getClassTypeId(), false), 1);
  root->unref();
}

}  // namespace
