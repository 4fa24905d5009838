// ClothingLayer: an IndexedFaceSet in every respect, plus `masked` and its display mesh.

#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPickedPoint.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoGetPrimitiveCountAction.h>
#include <Inventor/actions/SoRayPickAction.h>
#include <Inventor/details/SoFaceDetail.h>
#include <gtest/gtest.h>

#include "nodes/render/ClothingLayer.h"
#include "support/ActionChecks.h"
#include "support/SceneTestSupport.h"

using namespace figment::test;

namespace {

// Two unit squares side by side at z = 0, drawn by `shape` ("IndexedFaceSet" or
// "ClothingLayer") with every IndexedFaceSet field set.
std::string squares(const std::string& shape, const std::string& extra = "") {
  return "#Inventor V2.1 ascii\nSeparator {\n"
         "  Coordinate3 { point [ 0 0 0, 1 0 0, 2 0 0, 0 1 0, 1 1 0, 2 1 0 ] }\n"
         "  Normal { vector [ 0 0 1 ] }\n"
         "  MaterialBinding { value PER_FACE_INDEXED }\n"
         "  NormalBinding { value PER_VERTEX_INDEXED }\n"
         "  Material { diffuseColor [ 1 0 0, 0 1 0 ] }\n"
         "  " +
         shape +
         " {\n"
         "    coordIndex [ 0 1 4 3 -1, 1 2 5 4 -1 ]\n"
         "    materialIndex [ 1, 0 ]\n"
         "    normalIndex [ 0 0 0 0 -1, 0 0 0 0 -1 ]\n"
         "    textureCoordIndex [ -1 ]\n" +
         extra + "  }\n}\n";
}

class ClothingLayerTest : public ::testing::Test {
 protected:
  void SetUp() override { initCoin(); }
};

}  // namespace

TEST_F(ClothingLayerTest, IsAnIndexedFaceSetWithAMaskedField) {
  ClothingLayer* layer = new ClothingLayer;
  layer->ref();
  EXPECT_TRUE(layer->isOfType(SoIndexedFaceSet::getClassTypeId()));
  EXPECT_FALSE(layer->masked.getValue());
  EXPECT_TRUE(layer->stencilRule.getValue()) << "default TRUE: the rule decides";
  EXPECT_EQ(SoType::fromName("ClothingLayer"), ClothingLayer::getClassTypeId());
  layer->unref();
}

// displaySubdivision: 0 (the simulation's faces, as the paper draws them) unless a scene
// asks; a level outside 0 to 3 is one line naming the layer, the field and the value.
TEST_F(ClothingLayerTest, DisplaySubdivisionIsZeroUnlessAskedAndRefusedOutOfRange) {
  ClothingLayer* layer = new ClothingLayer;
  layer->ref();
  layer->setName("Dress");
  EXPECT_EQ(layer->displaySubdivision.getValue(), 0);
  EXPECT_EQ(layer->fieldProblem(), "");
  layer->displaySubdivision = ClothingLayer::kMostDisplaySubdivision;
  EXPECT_EQ(layer->fieldProblem(), "");
  layer->displaySubdivision = 7;
  EXPECT_EQ(layer->fieldProblem(), "ClothingLayer 'Dress': displaySubdivision = 7 is not 0 to 3");
  layer->displaySubdivision = -1;
  EXPECT_NE(layer->fieldProblem(), "");
  layer->unref();
}

TEST_F(ClothingLayerTest, ReadsAndWritesEveryField) {
  SceneRoot root = readString(squares("ClothingLayer", "    masked TRUE\n"));
  ASSERT_TRUE(root);
  auto* layer = find<ClothingLayer>(root.get());
  ASSERT_NE(layer, nullptr);
  EXPECT_TRUE(layer->masked.getValue());
  EXPECT_EQ(layer->coordIndex.getNum(), 10);
  EXPECT_EQ(layer->materialIndex[0], 1);

  const std::string text = writeString(root.get());
  EXPECT_NE(text.find("fields [ "), std::string::npos) << "a program without FIGMENT can still read it";
  SceneRoot again = readString(text);
  ASSERT_TRUE(again);
  auto* copy = find<ClothingLayer>(again.get());
  ASSERT_NE(copy, nullptr);
  SoFieldList fields;
  layer->getFields(fields);
  for (int i = 0; i < fields.getLength(); ++i) {
    SbName name;
    layer->getFieldName(fields[i], name);
    EXPECT_TRUE(fields[i]->isSame(*copy->getField(name))) << name.getString();
  }
}

TEST_F(ClothingLayerTest, ActsLikeAnIndexedFaceSetInEveryAction) {
  SceneRoot faceSet = readString(squares("IndexedFaceSet"));
  SceneRoot layer = readString(squares("ClothingLayer"));
  ASSERT_TRUE(faceSet && layer);
  EXPECT_EQ(boundingBoxOf(layer.get()).getMin(), boundingBoxOf(faceSet.get()).getMin());
  EXPECT_EQ(boundingBoxOf(layer.get()).getMax(), boundingBoxOf(faceSet.get()).getMax());
  EXPECT_EQ(triangleCountOf(layer.get()), 4);

  SoRayPickAction pick(kActionViewport);
  const SoPickedPoint* picked = pickAlongMinusZ(pick, layer.get(), SbVec3f(1.5f, 0.5f, 1.0f));
  ASSERT_NE(picked, nullptr);
  EXPECT_TRUE(picked->getPath()->getTail()->isOfType(ClothingLayer::getClassTypeId()));
  const auto* face = static_cast<const SoFaceDetail*>(picked->getDetail());
  ASSERT_NE(face, nullptr);
  EXPECT_EQ(face->getFaceIndex(), 1);
  ASSERT_EQ(face->getNumPoints(), 4);  // the second square
  EXPECT_EQ(face->getPoint(0)->getMaterialIndex(), 0) << "materialIndex [ 1, 0 ]: the second face takes colour 0";
}
