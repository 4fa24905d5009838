// ClothingLayer: an IndexedFaceSet in every respect, plus `masked` and its display mesh.

#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPickedPoint.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoGetPrimitiveCountAction.h>
#include <Inventor/actions/SoRayPickAction.h>
#include <Inventor/details/SoFaceDetail.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "nodes/render/ClothingLayer.h"
#include "sim/core/DisplaySubdivision.h"
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

namespace {

// An open hexagonal tube of radius 1 about z, 2 long, in triangles: its corners lie at
// 0, 60, ..., 300 degrees, so its flat sides reach y = +-sin 60 and the smooth surface of
// a display mesh stands past that, between the corners at 60 and 120 degrees.
std::string hexagonalTube(int levels) {
  std::string points, faces;
  for (int ring = 0; ring < 2; ++ring)
    for (int k = 0; k < 6; ++k)
      points += std::to_string(std::cos(k * M_PI / 3)) + " " + std::to_string(std::sin(k * M_PI / 3)) + " " +
                std::to_string(2.0 * ring) + ", ";
  for (int k = 0; k < 6; ++k) {
    const int a = k, b = (k + 1) % 6, c = 6 + (k + 1) % 6, d = 6 + k;
    faces += std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + " -1, " + std::to_string(a) + " " +
             std::to_string(c) + " " + std::to_string(d) + " -1, ";
  }
  return "#Inventor V2.1 ascii\nSeparator {\n  Coordinate3 { point [ " + points + "] }\n" +
         "  ClothingLayer { coordIndex [ " + faces + "] displaySubdivision " + std::to_string(levels) + " }\n}\n";
}

// The box of the display mesh the layer draws, made apart from it.
SbBox3f displayMeshBox(const SoCoordinate3& coordinates, const ClothingLayer& layer) {
  std::vector<figment::Vec3> points;
  for (int i = 0; i < coordinates.point.getNum(); ++i)
    points.emplace_back(coordinates.point[i][0], coordinates.point[i][1], coordinates.point[i][2]);
  std::vector<figment::Triangle> triangles;
  for (int i = 0; i + 3 < layer.coordIndex.getNum(); i += 4)
    triangles.push_back({layer.coordIndex[i], layer.coordIndex[i + 1], layer.coordIndex[i + 2]});
  const figment::DisplaySubdivision display(triangles, points, layer.displaySubdivision.getValue());
  std::vector<figment::Vec3> fine, normals;
  display.apply(points, fine, normals);
  SbBox3f box;
  for (const figment::Triangle& t : display.triangles())
    for (int v : t) box.extendBy(SbVec3f(float(fine[v].x()), float(fine[v].y()), float(fine[v].z())));
  return box;
}

void expectSameBox(const SbBox3f& a, const SbBox3f& b) {
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(a.getMin()[axis], b.getMin()[axis], 1e-6f) << "axis " << axis;
    EXPECT_NEAR(a.getMax()[axis], b.getMax()[axis], 1e-6f) << "axis " << axis;
  }
}

}  // namespace

// The box covers what is drawn (issue 29): with a display mesh, that mesh, which stands
// past the faces; at level 0 the faces' box, as an IndexedFaceSet's. Picking and counts
// keep the faces (ActsLikeAnIndexedFaceSetInEveryAction).
TEST_F(ClothingLayerTest, BoundsWhatItDraws) {
  SceneRoot faces = readString(hexagonalTube(0));
  ASSERT_TRUE(faces);
  const SbBox3f flat = boundingBoxOf(faces.get());
  EXPECT_NEAR(flat.getMax()[1], std::sin(M_PI / 3), 1e-5);
  for (int levels : {1, 2}) {
    SceneRoot root = readString(hexagonalTube(levels));
    ASSERT_TRUE(root);
    auto* layer = find<ClothingLayer>(root.get());
    auto* coordinates = find<SoCoordinate3>(root.get());
    ASSERT_TRUE(layer && coordinates);
    const SbBox3f drawn = displayMeshBox(*coordinates, *layer);
    EXPECT_GT(drawn.getMax()[1], flat.getMax()[1] + 0.05f) << "the display mesh stands past the faces";
    SbBox3f expected = flat;
    expected.extendBy(drawn);
    expectSameBox(boundingBoxOf(root.get()), expected);
    // Kept with the coordinates: a moved corner moves the box.
    coordinates->point.set1Value(0, 3.0f, 0.0f, 0.0f);
    SbBox3f moved = displayMeshBox(*coordinates, *layer);
    moved.extendBy(SbVec3f(3.0f, 0.0f, 0.0f));
    expectSameBox(boundingBoxOf(root.get()), moved);
  }
  expectSameBox(boundingBoxOf(faces.get()), flat);
}
